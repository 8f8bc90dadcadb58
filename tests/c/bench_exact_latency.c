/* bench_exact_latency.c: what one new state alone waits on. Every output's bits rest on the
 * set-up's Landen chain, k'_{n+1} = sqrt(k'_n) / ((1 + k'_n) / 2), each level's root and
 * quotient correctly rounded from the level before: no two levels can run side by side, and
 * the evaluation cannot start before the chain's end gives K. Prints
 *  - the core's clock, from a chain of one-cycle integer additions (x86-64 only);
 *  - the latency of one level of that chain (a root, then the quotient by (1 + k')/2), timed
 *    as a dependent loop, in ns and cycles;
 *  - for each amplitude of bench_exact (release from rest, g = L = 1): the chain's levels N
 *    (pendulum_exact_init_gl), N times one level's latency (a floor under the set-up alone),
 *    and one new state set up and evaluated once, timed two ways: independent states (as
 *    bench_exact times it) and each state's angle waiting on the previous state's output
 *    (theta0 + (theta - theta): the same value, one state's whole latency).
 * Processor time (clock()), the best of 7 rounds.
 *
 * Built with the tests (bash scripts/build-fmu.sh): build/tests/c/bench_exact_latency
 * (docs/speed-exact.md, "Where the time of one new state goes"). */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "exact.h"

#define STATES 100000
#define ROUNDS 7
#define PI 3.141592653589793

static double seconds(void)
{
    return (double)clock() / (double)CLOCKS_PER_SEC;
}

/* GHz of the core: ten dependent one-cycle additions a turn (0 where not measured) */
static double clock_ghz(void)
{
#if defined(__GNUC__) && defined(__x86_64__)
    const long turns = 50000000;
    double best = 0.0;
    for (int round = 0; round < ROUNDS; ++round) {
        unsigned long x = 1;
        const double start = seconds();
        for (long i = 0; i < turns; ++i) {
            __asm__ volatile("add %0, %0\n\tadd %0, %0\n\tadd %0, %0\n\tadd %0, %0\n\tadd %0, %0\n\t"
                             "add %0, %0\n\tadd %0, %0\n\tadd %0, %0\n\tadd %0, %0\n\tadd %0, %0"
                             : "+r"(x));
        }
        const double elapsed = seconds() - start;
        if (elapsed > 0.0 && 10.0 * (double)turns / elapsed / 1e9 > best) {
            best = 10.0 * (double)turns / elapsed / 1e9;
        }
    }
    return best;
#else
    return 0.0;
#endif
}

/* ns of one Landen level, k' <- sqrt(k') / ((1 + k')/2), as a dependent chain; *sink keeps it */
static double level_ns(double *sink)
{
    const long levels = 10000000;
    double best = INFINITY;
    for (int round = 0; round < ROUNDS; ++round) {
        volatile double first = 0x1p-40;
        double kc = first;
        const double start = seconds();
        for (long i = 0; i < levels; ++i) {
            kc = sqrt(kc) / (0.5 * (1.0 + kc));
            if ((i & 7) == 7) {
                kc *= 0x1p-40;   /* a small k' again every 8 levels, before the chain reaches 1 */
            }
        }
        best = fmin(best, (seconds() - start) / (double)levels * 1e9);
        *sink += kc;
    }
    return best;
}

/* ns per new state (init + one eval), independent (chained = 0) or each angle waiting on the
 * previous output (chained = 1) */
static double state_ns(double angle, const double *times, int chained, double *sink)
{
    double best = INFINITY;
    for (int round = 0; round < ROUNDS; ++round) {
        double theta = 0.0, omega = 0.0, sum = 0.0;
        const double start = seconds();
        for (int j = 0; j < STATES; ++j) {
            double theta0 = angle * (1.0 + 1e-9 * j);
            if (chained) {
                theta0 += theta - theta;   /* the same value, known only once theta is */
            }
            PendulumExact ex;
            if (pendulum_exact_init_gl(&ex, theta0, 0.0, 1.0, 1.0, 0.0) == 0) {
                pendulum_exact_eval(&ex, times[j], &theta, &omega);
                sum += omega;
            }
        }
        best = fmin(best, (seconds() - start) / STATES * 1e9);
        *sink += sum + theta;
    }
    return best;
}

int main(void)
{
    static double times[STATES];
    unsigned long long x = 88172645463325252ULL;
    for (int j = 0; j < STATES; ++j) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        times[j] = 50.0 * 2.0 * PI * (double)(x >> 11) * 0x1p-53;   /* about 50 periods */
    }
    double sink = 0.0;
    const double ghz = clock_ghz(), level = level_ns(&sink);
    printf("core clock %.2f GHz (one-cycle additions); one Landen level (root, then quotient) %.2f ns = %.0f "
           "cycles\n",
           ghz, level, level * ghz);
    const double degrees[] = {10.0, 90.0, 170.0, 179.9999};
    for (int i = 0; i < 4; ++i) {
        const double angle = degrees[i] * PI / 180.0;
        PendulumExact ex;
        if (pendulum_exact_init_gl(&ex, angle, 0.0, 1.0, 1.0, 0.0) != 0) {
            printf("%.7g deg: refused\n", degrees[i]);
            return 1;
        }
        const int levels = ex.ell.levels;
        printf("%.7g deg: %d levels, the chain alone %.1f ns | one new state %.1f ns, each waiting on the last "
               "%.1f ns\n",
               degrees[i], levels, levels * level, state_ns(angle, times, 0, &sink), state_ns(angle, times, 1, &sink));
    }
    printf("checksum %.17g\n", sink);
    return 0;
}
