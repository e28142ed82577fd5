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
    to mpiTrace.<rank> each distinct call stack of the messages it sent,
    between a line "send <number of messages>" and a line "end" (glibc's
    backtrace_symbols_fd; a stack without frames: the messages beyond the
    table's room), to find which code sends them.
    Build: mpicc -O2 -shared -fPIC -o libmpiCounts.so mpiCounts.c
    Use:   mpirun -x LD_PRELOAD=$PWD/libmpiCounts.so ...
\*---------------------------------------------------------------------------*/

#include <mpi.h>
#include <stdio.h>
#include <sys/resource.h>
#include <execinfo.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
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

/* The distinct call stacks of the sends of MPICOUNTS_TRACE's rank, each
   with its number of sends, written at MPI_Finalize */
#define MAX_FRAMES 32
#define MAX_STACKS 8192
struct stack { int nFrames; long long count; void* frames[MAX_FRAMES]; };
static struct stack* stacks = NULL;
static int traced = -1;  /* -1: not asked yet; 0: no; 1: yes */
static long long untraced = 0;

static void trace(void)
{
    void* frames[MAX_FRAMES];
    int n, i;
    unsigned long long h = 1469598103934665603ULL;

    if (traced < 0)
    {
        const char* rank = getenv("MPICOUNTS_TRACE");
        int me = -1;
        PMPI_Comm_rank(MPI_COMM_WORLD, &me);
        traced = rank && atoi(rank) == me;
        if (traced)
        {
            stacks = calloc(MAX_STACKS, sizeof(struct stack));
            traced = stacks != NULL;
        }
    }
    if (!traced)
    {
        return;
    }
    n = backtrace(frames, MAX_FRAMES);
    for (i = 0; i < n; ++i)
    {
        h = (h ^ (unsigned long long)frames[i])*1099511628211ULL;
    }
    /* open addressing: the first slot that holds this stack or none */
    for (i = 0; i < MAX_STACKS; ++i)
    {
        struct stack* st = &stacks[(h + i) % MAX_STACKS];
        if (st->nFrames == 0)
        {
            st->nFrames = n;
            memcpy(st->frames, frames, n*sizeof(void*));
        }
        if (st->nFrames == n && !memcmp(st->frames, frames, n*sizeof(void*)))
        {
            ++st->count;
            return;
        }
    }
    ++untraced;
}

static void writeTrace(int rank)
{
    char name[64];
    int i, fd;

    if (traced != 1)
    {
        return;
    }
    snprintf(name, sizeof(name), "mpiTrace.%d", rank);
    fd = open(name, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0)
    {
        return;
    }
    for (i = 0; i < MAX_STACKS; ++i)
    {
        if (stacks[i].count)
        {
            dprintf(fd, "send %lld\n", stacks[i].count);
            backtrace_symbols_fd(stacks[i].frames, stacks[i].nFrames, fd);
            dprintf(fd, "end\n");
        }
    }
    if (untraced)
    {
        dprintf(fd, "send %lld\nend\n", untraced);
    }
    close(fd);
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
    writeTrace(rank);
    return PMPI_Finalize();
}
