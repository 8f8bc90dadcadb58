/* bench_exact_moving.c: new moving librations and rotations set up and evaluated once, in a batch
 * (pendulum_exact_once_gl_many, 64 states a call, as exact() hands them over) against one at a
 * time (pendulum_exact_init_gl + pendulum_exact_eval), ns per state; a release from rest as
 * the batch's reference. g = L = 1; 100,000 states per case, theta0 (1 + 1e-9 j) around the
 * case's angle, times uniform over 50 periods of w0 = 1. With GSL (as bench_exact), a third
 * kind times the same states through GSL: m = sin^2(theta0/2) + (omega0/2)^2, the initial
 * phase by gsl_sf_ellint_F, then gsl_sf_elljac_e and the outputs, a libration by
 * sin(theta/2) = k sn(t + u0 | m), a rotation by theta/2 = am(sqrt(m) t + v0 | 1/m) with the
 * direction of omega0 (the angle modulo a turn); the largest difference from our outputs is
 * printed beside it. Processor time (clock()), the kinds alternated in 7 rounds; prints the
 * best and the median round.
 *
 * Built with the tests (bash scripts/build-fmu.sh): build/tests/c/bench_exact_moving
 * (docs/speed-exact.md: old and new builds alternated, the load average stated). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "exact.h"

#ifdef PENDULUM_BENCH_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_elljac.h>
#include <gsl/gsl_sf_ellint.h>
#define KINDS 3
#else
#define KINDS 2
#endif

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

#ifdef PENDULUM_BENCH_GSL
/* One state through GSL (w0 = 1): theta (modulo a turn for a rotation) and omega at t */
static void gsl_state(double th0, double om0, double t, double *th, double *om)
{
    const double s = sin(0.5 * th0), q = 0.5 * om0, m = s * s + q * q;
    double sn, cn, dn;
    if (m < 1.0) {
        /* sn(u0) = s/k, cn(u0) = q/k (omega = 2 k cn): u0 = F(atan2(s, q) | m) */
        const double k = sqrt(m);
        gsl_sf_elljac_e(t + gsl_sf_ellint_F(atan2(s, q), k, GSL_PREC_DOUBLE), m, &sn, &cn, &dn);
        *th = 2.0 * atan2(k * sn, dn);
        *om = 2.0 * k * cn;
    } else {
        /* theta/2 = dir am(sqrt(m) t + F(dir theta0/2 | 1/m) | 1/m), omega = 2 dir sqrt(m) dn */
        const double root = sqrt(m), dir = om0 > 0.0 ? 1.0 : -1.0;
        gsl_sf_elljac_e(root * t + gsl_sf_ellint_F(dir * 0.5 * th0, 1.0 / root, GSL_PREC_DOUBLE), 1.0 / m, &sn, &cn,
                        &dn);
        *th = 2.0 * dir * atan2(sn, cn);
        *om = 2.0 * dir * root * dn;
    }
}

/* The largest difference of GSL's outputs from ours over every 97th state (theta modulo 2 pi) */
static double gsl_difference(void)
{
    double most = 0.0;
    for (int j = 0; j < STATES; j += 97) {
        double th, om, ours_th, ours_om;
        gsl_state(theta0[j], omega0[j], times[j], &th, &om);
        PendulumExact ex;
        if (pendulum_exact_init_gl(&ex, theta0[j], omega0[j], 1.0, 1.0, 0.0) != 0) {
            continue;
        }
        pendulum_exact_eval(&ex, times[j], &ours_th, &ours_om);
        const double turn = 2.0 * PI, d_th = remainder(th - ours_th, turn);
        most = fmax(most, fmax(fabs(d_th), fabs(om - ours_om)));
    }
    return most;
}
#endif

/* ns per state of the batch (kind 0), of one state at a time (kind 1) or of GSL (kind 2);
 * *sum keeps the work */
static double time_kind(int kind, double *sum)
{
    const double start = seconds();
#ifdef PENDULUM_BENCH_GSL
    if (kind == 2) {
        for (int j = 0; j < STATES; ++j) {
            double th, om;
            gsl_state(theta0[j], omega0[j], times[j], &th, &om);
            *sum += th + om;
        }
        return (seconds() - start) / STATES * 1e9;
    }
#endif
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
#ifdef PENDULUM_BENCH_GSL
    gsl_set_error_handler_off();   /* a refused argument gives NaN, not an abort */
#endif
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
        double ns[KINDS][ROUNDS];
        for (int round = 0; round < ROUNDS; ++round) {
            for (int kind = 0; kind < KINDS; ++kind) {
                ns[kind][round] = time_kind(kind, &sum);
            }
        }
        for (int kind = 0; kind < KINDS; ++kind) {
            qsort(ns[kind], ROUNDS, sizeof ns[kind][0], ascending);
        }
        printf("theta0 %g deg, omega0 %g: batch best %.1f median %.1f ns | one at a time best %.1f median %.1f ns"
               " | ratio %.2f", cases[c][0], cases[c][1], ns[0][0], ns[0][ROUNDS / 2], ns[1][0], ns[1][ROUNDS / 2],
               ns[1][0] / ns[0][0]);
#ifdef PENDULUM_BENCH_GSL
        printf(" | GSL best %.1f median %.1f ns, over the batch %.2f, largest difference %.1e", ns[2][0],
               ns[2][ROUNDS / 2], ns[2][0] / ns[0][0], gsl_difference());
#endif
        printf("\n");
    }
    printf("checksum %.17g\n", sum);
    return 0;
}
