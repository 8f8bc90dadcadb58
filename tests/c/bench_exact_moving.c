/* bench_exact_moving.c: new moving librations and rotations set up and evaluated once, in a batch
 * (pendulum_exact_once_gl_many, 64 states a call, as exact() hands them over) against one at a
 * time (pendulum_exact_init_gl + pendulum_exact_eval), ns per state; a release from rest as
 * the batch's reference. g = L = 1; 100,000 states per case, theta0 (1 + 1e-9 j) around the
 * case's angle, times uniform over 50 periods of w0 = 1. Processor time (clock()), the two
 * kinds alternated in 7 rounds; prints the best and the median round.
 *
 * Built with the tests (bash scripts/build-fmu.sh): build/tests/c/bench_exact_moving
 * (docs/speed-exact.md: old and new builds alternated, the load average stated). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "exact.h"

#define STATES 100000
#define ROUNDS 7
#define CALL 64
#define PI 3.141592653589793

static double theta0[STATES], omega0[STATES], ones[STATES], times[STATES], theta[STATES], omega[STATES];

static double seconds(void)
{
    return (double)clock() / (double)CLOCKS_PER_SEC;
}

static int ascending(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* ns per state of the batch (kind 0) or of one state at a time (kind 1); *sum keeps the work */
static double time_kind(int kind, double *sum)
{
    const double start = seconds();
    if (kind == 0) {
        for (int first = 0; first < STATES; first += CALL) {
            const int count = STATES - first < CALL ? STATES - first : CALL;
            pendulum_exact_once_gl_many((size_t)count, theta0 + first, omega0 + first, ones + first, ones + first, 0.0,
                                        times + first, theta + first, omega + first);
        }
        for (int j = 0; j < STATES; j += 97) {
            *sum += theta[j] + omega[j];
        }
    } else {
        for (int j = 0; j < STATES; ++j) {
            PendulumExact ex;
            double th, om;
            if (pendulum_exact_init_gl(&ex, theta0[j], omega0[j], 1.0, 1.0, 0.0) == 0) {
                pendulum_exact_eval(&ex, times[j], &th, &om);
                *sum += th + om;
            }
        }
    }
    return (seconds() - start) / STATES * 1e9;
}

int main(void)
{
    /* deg, omega0: librations, a release from rest, rotations (omega0 above the separatrix
     * speed 2 cos(theta0/2): 2, 1.41, 1.99, 0.17) */
    const double cases[][2] = {{90.0, 0.5}, {30.0, 1.2}, {10.0, 1.9}, {90.0, 0.0},
                               {0.0, 2.5}, {90.0, 3.0}, {10.0, 20.0}, {170.0, 0.3}};
    unsigned long long x = 88172645463325252ULL;
    for (int j = 0; j < STATES; ++j) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        times[j] = (double)(x >> 11) * 0x1p-53 * 50.0 * 2.0 * PI;
        ones[j] = 1.0;
    }
    double sum = 0.0;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        for (int j = 0; j < STATES; ++j) {
            theta0[j] = cases[c][0] * (PI / 180.0) * (1.0 + 1e-9 * (double)(j & 1023));
            omega0[j] = cases[c][1];
        }
        double ns[2][ROUNDS];
        for (int round = 0; round < ROUNDS; ++round) {
            ns[0][round] = time_kind(0, &sum);
            ns[1][round] = time_kind(1, &sum);
        }
        qsort(ns[0], ROUNDS, sizeof ns[0][0], ascending);
        qsort(ns[1], ROUNDS, sizeof ns[1][0], ascending);
        printf("theta0 %g deg, omega0 %g: batch best %.1f median %.1f ns | one at a time best %.1f median %.1f ns"
               " | ratio %.2f\n", cases[c][0], cases[c][1], ns[0][0], ns[0][ROUNDS / 2], ns[1][0], ns[1][ROUNDS / 2],
               ns[1][0] / ns[0][0]);
    }
    printf("checksum %.17g\n", sum);
    return 0;
}
