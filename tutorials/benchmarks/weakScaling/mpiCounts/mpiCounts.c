/*---------------------------------------------------------------------------*\
  polymerCloud: tutorials/benchmarks/weakScaling/mpiCounts/mpiCounts.c

Description
    An MPI profiling (PMPI) library, preloaded into each rank: counts the
    messages a rank sends and their bytes, point to point (with the
    distinct ranks it sends to) and in collectives (one per call, the bytes
    it contributes), and at MPI_Finalize writes them with the rank's peak
    resident memory to mpiCounts.<rank> in the working directory:
        rank sends sendBytes partners collectives collectiveBytes maxRSSkB
    and on a second line the messages sent to each rank, 0 to size - 1.
    With MPICOUNTS_TRACE=<rank> in the environment, that rank also writes
    the call stack of each message it sends to mpiTrace.<rank>, between
    lines "send" and "end" (glibc's backtrace_symbols_fd), to find which
    code sends them.
    Build: mpicc -O2 -shared -fPIC -o libmpiCounts.so mpiCounts.c
    Use:   mpirun -x LD_PRELOAD=$PWD/libmpiCounts.so ...
\*---------------------------------------------------------------------------*/

#include <mpi.h>
#include <stdio.h>
#include <sys/resource.h>
#include <execinfo.h>
#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#define MAX_RANKS 4096

static long long sends = 0, sendBytes = 0, collectives = 0, collectiveBytes = 0;
static long long partner[MAX_RANKS];

static long long bytesOf(int count, MPI_Datatype type)
{
    int size = 0;
    PMPI_Type_size(type, &size);
    return (long long)count*size;
}

/* The call stack of a send, for MPICOUNTS_TRACE's rank (-1: not traced;
   -2: not asked yet) */
static int traceFd = -2;

static void trace(void)
{
    void* frames[48];
    int n;

    if (traceFd == -2)
    {
        const char* traced = getenv("MPICOUNTS_TRACE");
        int rank = -1;
        char name[64];
        traceFd = -1;
        PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
        if (traced && atoi(traced) == rank)
        {
            snprintf(name, sizeof(name), "mpiTrace.%d", rank);
            traceFd = open(name, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        }
    }
    if (traceFd >= 0)
    {
        n = backtrace(frames, 48);
        dprintf(traceFd, "send\n");
        backtrace_symbols_fd(frames, n, traceFd);
        dprintf(traceFd, "end\n");
    }
}

static void sent(int count, MPI_Datatype type, int dest)
{
    ++sends;
    sendBytes += bytesOf(count, type);
    trace();
    if (dest >= 0 && dest < MAX_RANKS)
    {
        ++partner[dest];
    }
}

static void collective(int count, MPI_Datatype type)
{
    ++collectives;
    collectiveBytes += bytesOf(count, type);
}

int MPI_Send(const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{ sent(c, t, d); return PMPI_Send(b, c, t, d, g, m); }

int MPI_Ssend(const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{ sent(c, t, d); return PMPI_Ssend(b, c, t, d, g, m); }

int MPI_Bsend(const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{ sent(c, t, d); return PMPI_Bsend(b, c, t, d, g, m); }

int MPI_Isend
(const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m, MPI_Request* r)
{ sent(c, t, d); return PMPI_Isend(b, c, t, d, g, m, r); }

int MPI_Issend
(const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m, MPI_Request* r)
{ sent(c, t, d); return PMPI_Issend(b, c, t, d, g, m, r); }

int MPI_Allreduce
(const void* s, void* r, int c, MPI_Datatype t, MPI_Op o, MPI_Comm m)
{ collective(c, t); return PMPI_Allreduce(s, r, c, t, o, m); }

int MPI_Reduce
(const void* s, void* r, int c, MPI_Datatype t, MPI_Op o, int root, MPI_Comm m)
{ collective(c, t); return PMPI_Reduce(s, r, c, t, o, root, m); }

int MPI_Bcast(void* b, int c, MPI_Datatype t, int root, MPI_Comm m)
{ collective(c, t); return PMPI_Bcast(b, c, t, root, m); }

int MPI_Gather
(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt,
 int root, MPI_Comm m)
{ collective(sc, st); return PMPI_Gather(s, sc, st, r, rc, rt, root, m); }

int MPI_Gatherv
(const void* s, int sc, MPI_Datatype st, void* r, const int* rc,
 const int* d, MPI_Datatype rt, int root, MPI_Comm m)
{ collective(sc, st); return PMPI_Gatherv(s, sc, st, r, rc, d, rt, root, m); }

int MPI_Allgather
(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt,
 MPI_Comm m)
{ collective(sc, st); return PMPI_Allgather(s, sc, st, r, rc, rt, m); }

int MPI_Allgatherv
(const void* s, int sc, MPI_Datatype st, void* r, const int* rc,
 const int* d, MPI_Datatype rt, MPI_Comm m)
{ collective(sc, st); return PMPI_Allgatherv(s, sc, st, r, rc, d, rt, m); }

int MPI_Alltoall
(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt,
 MPI_Comm m)
{
    int n = 1;
    PMPI_Comm_size(m, &n);
    collective(sc*n, st);
    return PMPI_Alltoall(s, sc, st, r, rc, rt, m);
}

int MPI_Alltoallv
(const void* s, const int* sc, const int* sd, MPI_Datatype st, void* r,
 const int* rc, const int* rd, MPI_Datatype rt, MPI_Comm m)
{
    int n = 1, i, total = 0;
    PMPI_Comm_size(m, &n);
    for (i = 0; i < n; ++i)
    {
        total += sc[i];
    }
    collective(total, st);
    return PMPI_Alltoallv(s, sc, sd, st, r, rc, rd, rt, m);
}

int MPI_Scatter
(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt,
 int root, MPI_Comm m)
{ collective(rc, rt); return PMPI_Scatter(s, sc, st, r, rc, rt, root, m); }

int MPI_Scatterv
(const void* s, const int* sc, const int* d, MPI_Datatype st, void* r,
 int rc, MPI_Datatype rt, int root, MPI_Comm m)
{ collective(rc, rt); return PMPI_Scatterv(s, sc, d, st, r, rc, rt, root, m); }

int MPI_Finalize(void)
{
    int rank = 0, size = 1, i, nPartners = 0;
    char name[64];
    struct rusage usage;
    FILE* out;

    PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
    PMPI_Comm_size(MPI_COMM_WORLD, &size);
    for (i = 0; i < MAX_RANKS; ++i)
    {
        nPartners += (partner[i] > 0);
    }
    getrusage(RUSAGE_SELF, &usage);
    snprintf(name, sizeof(name), "mpiCounts.%d", rank);
    out = fopen(name, "w");
    if (out)
    {
        fprintf
        (
            out, "%d %lld %lld %d %lld %lld %ld\n", rank, sends, sendBytes,
            nPartners, collectives, collectiveBytes, usage.ru_maxrss
        );
        for (i = 0; i < size && i < MAX_RANKS; ++i)
        {
            fprintf(out, "%s%lld", i ? " " : "", partner[i]);
        }
        fprintf(out, "\n");
        fclose(out);
    }
    return PMPI_Finalize();
}
