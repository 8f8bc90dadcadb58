/* bench_exact.c: time the exact solution per point, side by side in one run.
 *
 * Usage: bench_exact [N [amplitude_deg ...]]   (defaults: N = 200000; 10 90 170 179.9999)
 *
 * For each amplitude (theta0 = amplitude, omega0 = 0, w0 = 1) N times are drawn uniformly in
 * [0, 50 periods) before timing, so every evaluation is at a new time. Timed, per point:
 *   eval   pendulum_exact_eval (theta and omega) in a loop;
 *   batch  pendulum_exact_eval_many over the same times (lock-step, bit for bit the same);
 *   gsl    GSL's gsl_sf_elljac_e(u, m) at u = w0 t + K (release from rest), then
 *          theta = 2 atan2(k sn, dn), omega = 2 k w0 cn (only when built with GSL);
 *   init   a new state and one evaluation: pendulum_exact_init for N different release
 *          angles around the amplitude (theta0 (1 + 1e-9 j)), each evaluated once at one of
 *          the times;
 *   gsl_init  the same new states with GSL: k = sin(theta0/2), K by gsl_sf_ellint_Kcomp_e,
 *          then gsl_sf_elljac_e(w0 t + K, k^2) and the two outputs as for gsl (only with GSL);
 *   once   the same new states and times through pendulum_exact_once_gl_many (g = L = 1), 64
 *          a call: set up and evaluated in blocks, as pendulum_fmu.exact does them.
 * Times are processor time of the process (clock()), so that waiting for a core on a shared
 * machine does not count. The kinds are timed in interleaved rounds (ROUNDS rounds, each timing every kind and
 * amplitude once), so that a change of machine load hits all of them alike; each figure is
 * reported as the best and the median over the rounds. One line per amplitude,
 * machine-readable (key=value, space separated, ns per point):
 *   bench_exact amplitude_deg=90 n=200000 rounds=7 ns_per_eval=... eval_median=...
 *     batch_best=... batch_median=... gsl_best=... gsl_median=... init_best=... init_median=...
 *     gsl_init_best=... gsl_init_median=... gsl_over_eval=... eval_over_batch=...
 *     gsl_init_over_init=... once_best=... init_over_once=... instructions: see docs/speed-exact.md
 * (gsl_* are "nan" without GSL). ns_per_eval is the best eval time (the field older parsers
 * read). The checksum keeps the compiler from dropping the work.
 *
 * bench_exact --count KIND N amplitude_deg runs one kind once over N points and prints
 * nothing else but its checksum: for counting instructions per point with valgrind, as the
 * difference of two runs (docs/speed-exact.md):
 *   valgrind --tool=callgrind --callgrind-out-file=/dev/null bench_exact --count init 20000 90 */
#include "exact.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef PENDULUM_BENCH_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_elljac.h>
#include <gsl/gsl_sf_ellint.h>
#endif

#define ROUNDS 7
#define KINDS 6
enum { KIND_EVAL, KIND_BATCH, KIND_GSL, KIND_INIT, KIND_GSL_INIT, KIND_ONCE };
static const char *const KIND_NAMES[KINDS] = {"eval", "batch", "gsl", "init", "gsl_init", "once"};

/* the once kind hands pendulum_exact_once_gl_many this many new states a call */
#define ONCE_CALL 64

/* Processor time of this process (C clock(): CPU time on POSIX), not wall time: the machine
 * may be shared, and time spent waiting for a core is not the code's. */
static double now_seconds(void)
{
    return (double)clock() / (double)CLOCKS_PER_SEC;
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

static int compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef struct {
    double amplitude_deg;
    double theta0;
    PendulumExact ex;
    long n;
    const double *times;
    double *theta, *omega;
    double checksum;
} Case;

/* One timing of one kind over the case's N points; ns per point, or NaN if unavailable. */
static double time_kind(int kind, Case *c)
{
    const long n = c->n;
    double sum = 0.0;
    const double start = now_seconds();
    switch (kind) {
    case KIND_EVAL:
        for (long i = 0; i < n; ++i) {
            double theta, omega;
            pendulum_exact_eval(&c->ex, c->times[i], &theta, &omega);
            sum += theta + omega;
        }
        break;
    case KIND_BATCH:
        pendulum_exact_eval_many(&c->ex, (size_t)n, c->times, c->theta, c->omega);
        for (long i = 0; i < n; ++i) {
            sum += c->theta[i] + c->omega[i];
        }
        break;
    case KIND_GSL: {
#ifdef PENDULUM_BENCH_GSL
        const double half = 0.5 * c->theta0, k = sin(half), m = k * k, w0 = 1.0;
        gsl_sf_result K;
        gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &K);
        for (long i = 0; i < n; ++i) {
            double sn, cn, dn;
            gsl_sf_elljac_e(w0 * c->times[i] + K.val, m, &sn, &cn, &dn);
            sum += 2.0 * atan2(k * sn, dn) + 2.0 * k * w0 * cn;
        }
        break;
#else
        return NAN;
#endif
    }
    case KIND_GSL_INIT: {
#ifdef PENDULUM_BENCH_GSL
        const double w0 = 1.0;
        for (long i = 0; i < n; ++i) {
            const double theta0 = c->theta0 * (1.0 + 1e-9 * (double)(i & 1023));
            const double k = sin(0.5 * theta0), m = k * k;
            gsl_sf_result K;
            double sn, cn, dn;
            gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &K);
            gsl_sf_elljac_e(w0 * c->times[i] + K.val, m, &sn, &cn, &dn);
            sum += 2.0 * atan2(k * sn, dn) + 2.0 * k * w0 * cn;
        }
        break;
#else
        return NAN;
#endif
    }
    case KIND_ONCE: {
        double theta0[ONCE_CALL], zeros[ONCE_CALL], ones[ONCE_CALL];
        for (long first = 0; first < n; first += ONCE_CALL) {
            const long count = n - first < ONCE_CALL ? n - first : ONCE_CALL;
            for (long j = 0; j < count; ++j) {
                theta0[j] = c->theta0 * (1.0 + 1e-9 * (double)((first + j) & 1023));
                zeros[j] = 0.0;
                ones[j] = 1.0;
            }
            if (pendulum_exact_once_gl_many((size_t)count, theta0, zeros, ones, ones, 0.0, c->times + first, c->theta,
                                            c->omega) != 0) {
                return NAN;
            }
            for (long j = 0; j < count; ++j) {
                sum += c->theta[j] + c->omega[j];
            }
        }
        break;
    }
    default: /* KIND_INIT */
        for (long i = 0; i < n; ++i) {
            PendulumExact fresh;
            double theta, omega;
            const double theta0 = c->theta0 * (1.0 + 1e-9 * (double)(i & 1023));
            if (pendulum_exact_init(&fresh, theta0, 0.0, 1.0, 0.0) != 0) {
                return NAN;
            }
            pendulum_exact_eval(&fresh, c->times[i], &theta, &omega);
            sum += theta + omega;
        }
        break;
    }
    const double elapsed = now_seconds() - start;
    c->checksum += sum;
    return 1e9 * elapsed / (double)n;
}

/* --count KIND N amplitude_deg */
static int count_one(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "bench_exact: usage: bench_exact --count eval|batch|gsl|init|gsl_init|once N amplitude_deg\n");
        return 2;
    }
    int kind = -1;
    for (int k = 0; k < KINDS; ++k) {
        kind = strcmp(argv[2], KIND_NAMES[k]) == 0 ? k : kind;
    }
    Case c;
    c.amplitude_deg = strtod(argv[4], NULL);
    c.theta0 = c.amplitude_deg * (3.14159265358979323846 / 180.0);
    c.n = strtol(argv[3], NULL, 10);
    c.checksum = 0.0;
    if (kind < 0 || c.n <= 0 || pendulum_exact_init(&c.ex, c.theta0, 0.0, 1.0, 0.0) != 0) {
        fprintf(stderr, "bench_exact: bad --count arguments\n");
        return 2;
    }
    double *times = malloc((size_t)c.n * sizeof *times);
    c.theta = malloc((size_t)c.n * sizeof *c.theta);
    c.omega = malloc((size_t)c.n * sizeof *c.omega);
    if (times == NULL || c.theta == NULL || c.omega == NULL) {
        fprintf(stderr, "bench_exact: out of memory\n");
        return 2;
    }
    unsigned long long rng = 0x9E3779B97F4A7C15ULL;
    const double horizon = 50.0 * pendulum_exact_period(&c.ex);
    for (long i = 0; i < c.n; ++i) {
        times[i] = horizon * next_uniform(&rng);
    }
    c.times = times;
    (void)time_kind(kind, &c);
    printf("bench_exact --count %s n=%ld amplitude_deg=%.10g checksum=%.17g\n", KIND_NAMES[kind], c.n,
           c.amplitude_deg, c.checksum);
    free(times);
    free(c.theta);
    free(c.omega);
    return 0;
}

int main(int argc, char **argv)
{
#ifdef PENDULUM_BENCH_GSL
    /* GSL's default handler aborts on a domain error: gsl_sf_ellint_Kcomp_e refuses k^2 == 1,
     * which sin(theta0/2)^2 rounds to within about 3e-8 rad of the top (a few of the release
     * angles around 179.9999 deg); it then returns NaN, which the checksum carries */
    gsl_set_error_handler_off();
#endif
    if (argc > 1 && strcmp(argv[1], "--count") == 0) {
        return count_one(argc, argv);
    }
    const long n = argc > 1 ? strtol(argv[1], NULL, 10) : 200000L;
    static const double default_amplitudes[] = {10.0, 90.0, 170.0, 179.9999};
    const int n_amp = argc > 2 ? argc - 2 : (int)(sizeof default_amplitudes / sizeof default_amplitudes[0]);
    if (n <= 0 || n_amp > 64) {
        fprintf(stderr, "bench_exact: N must be positive and at most 64 amplitudes given\n");
        return 2;
    }
    Case cases[64];
    double timings[64][KINDS][ROUNDS];
    unsigned long long rng = 0x9E3779B97F4A7C15ULL;
    for (int a = 0; a < n_amp; ++a) {
        const double amplitude_deg = argc > 2 ? strtod(argv[2 + a], NULL) : default_amplitudes[a];
        Case *c = &cases[a];
        c->amplitude_deg = amplitude_deg;
        c->theta0 = amplitude_deg * (3.14159265358979323846 / 180.0);
        c->n = n;
        c->checksum = 0.0;
        double *times = malloc((size_t)n * sizeof *times);
        c->theta = malloc((size_t)n * sizeof *c->theta);
        c->omega = malloc((size_t)n * sizeof *c->omega);
        if (times == NULL || c->theta == NULL || c->omega == NULL) {
            fprintf(stderr, "bench_exact: out of memory\n");
            return 2;
        }
        if (pendulum_exact_init(&c->ex, c->theta0, 0.0, 1.0, 0.0) != 0) {
            fprintf(stderr, "bench_exact: init failed for %g deg\n", amplitude_deg);
            return 1;
        }
        const double horizon = 50.0 * pendulum_exact_period(&c->ex);
        for (long i = 0; i < n; ++i) {
            times[i] = horizon * next_uniform(&rng);
        }
        c->times = times;
    }
    for (int round = 0; round < ROUNDS; ++round) {
        for (int a = 0; a < n_amp; ++a) {
            for (int kind = 0; kind < KINDS; ++kind) {
                timings[a][kind][round] = time_kind(kind, &cases[a]);
            }
        }
    }
    for (int a = 0; a < n_amp; ++a) {
        double best[KINDS], median[KINDS];
        for (int kind = 0; kind < KINDS; ++kind) {
            qsort(timings[a][kind], ROUNDS, sizeof(double), compare_doubles);
            best[kind] = timings[a][kind][0];
            median[kind] = timings[a][kind][ROUNDS / 2];
        }
        printf("bench_exact amplitude_deg=%.10g n=%ld rounds=%d ns_per_eval=%.3f", cases[a].amplitude_deg, n, ROUNDS,
               best[KIND_EVAL]);
        for (int kind = 0; kind < KINDS; ++kind) {
            printf(" %s_best=%.3f %s_median=%.3f", KIND_NAMES[kind], best[kind], KIND_NAMES[kind], median[kind]);
        }
        printf(" gsl_over_eval=%.3f gsl_over_eval_median=%.3f eval_over_batch=%.3f eval_over_batch_median=%.3f"
               " gsl_init_over_init=%.3f gsl_init_over_init_median=%.3f init_over_once=%.3f init_over_once_median=%.3f"
               " checksum=%.17g\n",
               best[KIND_GSL] / best[KIND_EVAL], median[KIND_GSL] / median[KIND_EVAL],
               best[KIND_EVAL] / best[KIND_BATCH], median[KIND_EVAL] / median[KIND_BATCH],
               best[KIND_GSL_INIT] / best[KIND_INIT], median[KIND_GSL_INIT] / median[KIND_INIT],
               best[KIND_INIT] / best[KIND_ONCE], median[KIND_INIT] / median[KIND_ONCE], cases[a].checksum);
        free((void *)cases[a].times);
        free(cases[a].theta);
        free(cases[a].omega);
    }
    return 0;
}
