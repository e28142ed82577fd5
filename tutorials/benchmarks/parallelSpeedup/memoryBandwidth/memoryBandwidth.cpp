// memoryBandwidth: the triad a = b + s*c over arrays of a given total size,
// repeated for a given time; prints the mean bandwidth in GB/s (bytes read
// and written per second). The mean, not STREAM's best pass: two copies
// started together must stream over the same seconds, and the best pass of
// each would be one the other did not overlap.
//
// Usage: memoryBandwidth <megabytes of the three arrays> <seconds>
//
// The parallel-speed-up benchmark runs it once alone and twice at once, at
// the working-set sizes of a processor's cache and of main memory: what
// two processors streaming together get against one (the ceiling of a
// memory-bound solver's speed-up on the machine).

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char* argv[])
{
    if (argc != 3)
    {
        std::fprintf(stderr, "Usage: %s <megabytes> <seconds>\n", argv[0]);
        return 1;
    }
    const double megabytes = std::atof(argv[1]);
    const double duration = std::atof(argv[2]);
    const std::size_t n = megabytes*1e6/(3*sizeof(double));
    if (n < 1000 || duration <= 0)
    {
        std::fprintf(stderr, "%s: at least 0.024 MB, some seconds\n", argv[0]);
        return 1;
    }

    std::vector<double> a(n, 1), b(n, 2), c(n, 3);

    const auto start = std::chrono::steady_clock::now();
    std::chrono::duration<double> seconds(0);
    double passes = 0;
    while (seconds.count() < duration)
    {
        const double scale = 1.5 + 1e-9*passes;
        for (std::size_t i = 0; i < n; ++i)
        {
            a[i] = b[i] + scale*c[i];
        }
        ++passes;
        seconds = std::chrono::steady_clock::now() - start;
    }
    const double rate = 3*sizeof(double)*double(n)*passes/seconds.count();

    // The result is used, so the loops are not optimised away
    std::printf("%.2f GB/s (check %g)\n", rate/1e9, a[n/2]);
    return 0;
}
