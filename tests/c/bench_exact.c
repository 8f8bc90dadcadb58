/* bench_exact.c: time pendulum_exact_eval (theta and omega) at N fresh times.
 *
 * Usage: bench_exact [N [amplitude_deg ...]]   (defaults: N = 1000000; 10 90 170 179.9999)
 * For each amplitude (theta0 = amplitude, omega0 = 0, w0 = 1) the N times are drawn uniformly
 * in [0, 50 periods) before timing, so every evaluation is at a new time. One line per
 * amplitude, machine-readable (key=value, space separated):
 *   bench_exact amplitude_deg=90 n=1000000 ns_per_eval=35.12 checksum=...
 * The checksum (sum of theta + omega) keeps the compiler from dropping the work. */
#include "exact.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now_seconds(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* xorshift64* (Vigna 2016): uniform doubles in [0, 1). */
static double next_uniform(unsigned long long *state)
{
    unsigned long long x = *state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    *state = x;
    return (double)((x * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-53;
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? strtol(argv[1], NULL, 10) : 1000000L;
    static const double default_amplitudes[] = {10.0, 90.0, 170.0, 179.9999};
    int n_amp = argc > 2 ? argc - 2 : (int)(sizeof default_amplitudes / sizeof default_amplitudes[0]);
    if (n <= 0) {
        fprintf(stderr, "bench_exact: N must be positive\n");
        return 2;
    }
    double *times = malloc((size_t)n * sizeof *times);
    if (times == NULL) {
        fprintf(stderr, "bench_exact: out of memory\n");
        return 2;
    }
    unsigned long long rng = 0x9E3779B97F4A7C15ULL;
    for (int a = 0; a < n_amp; ++a) {
        double amplitude_deg = argc > 2 ? strtod(argv[2 + a], NULL) : default_amplitudes[a];
        PendulumExact ex;
        if (pendulum_exact_init(&ex, amplitude_deg * (3.14159265358979323846 / 180.0), 0.0, 1.0, 0.0) != 0) {
            fprintf(stderr, "bench_exact: init failed for %g deg\n", amplitude_deg);
            free(times);
            return 1;
        }
        double horizon = 50.0 * pendulum_exact_period(&ex);
        for (long i = 0; i < n; ++i) {
            times[i] = horizon * next_uniform(&rng);
        }
        double checksum = 0.0, best = INFINITY;
        for (int repeat = 0; repeat < 3; ++repeat) {
            double start = now_seconds();
            for (long i = 0; i < n; ++i) {
                double theta, omega;
                pendulum_exact_eval(&ex, times[i], &theta, &omega);
                checksum += theta + omega;
            }
            double elapsed = now_seconds() - start;
            best = elapsed < best ? elapsed : best;
        }
        printf("bench_exact amplitude_deg=%.10g n=%ld ns_per_eval=%.3f checksum=%.17g\n",
               amplitude_deg, n, 1e9 * best / (double)n, checksum);
    }
    free(times);
    return 0;
}
