/* test_exact_batch.c: pendulum_exact_eval_many (points of a libration in lock-step) and
 * pendulum_exact_once_gl_many (new states each set up and evaluated once, in blocks) give bit
 * for bit what pendulum_exact_init_gl and pendulum_exact_eval give, point by point, for every kind of state and time:
 * librations with few and with many Landen levels (lock-step and the scalar fallback), wound-up
 * initial angles, rotations, the separatrix, rest; times at t0 exactly, negative, far (past
 * 2^50 and 2^60 quarter periods), NaN and infinite, in blocks that mix them, and counts that
 * are not a multiple of the lane count; for the new states, arrays that mix every kind of
 * state, refused inputs and special times, and arrays of moving starts (librations of every
 * amplitude and speed, next to the separatrix window's edge, k and m1 tiny, any g and L; one in
 * seven wound up by whole turns).
 * Arrays of rotations: barely over the top (either side of the fine window's edge), fast
 * spins, both directions, theta0 of both signs, near and past pi, any g and L, far times.
 * A copy of the fma build (four lanes; test_exact_batch_wide: of the AVX-512 build, eight) counts
 * the lanes its vectors did: releases from rest, moving librations and rotations must run
 * there, not only agree. Prints one summary line; exit status 0 iff
 * every check passed. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "exact_fma.h"

#ifdef EXACT_TEST_WIDE
#define TEST_NAME "test_exact_batch_wide"
#else
#define TEST_NAME "test_exact_batch"
#endif

/* The fma build once more (exact_fma.c, as the core compiles it; test_exact_batch_wide: the
 * AVX-512 build, avx512_copy.c), its entry points renamed
 * *_tallied and the lanes its vector blocks did counted (ONCE_AVX_TALLY of once_avx.h): the
 * moving librations must not only agree with the scalar set-up but run in the vectors. */
#ifdef PENDULUM_EXACT_FMA_BUILD
#define EXACT_TALLIED 1
/* the tallied copy runs on this processor: the fma build's where it has an fma, the AVX-512
 * build's (test_exact_batch_wide) where it has AVX-512F too */
#ifdef EXACT_TEST_WIDE
#define TALLIED_COPY_RUNS() (__builtin_cpu_supports("fma") && __builtin_cpu_supports("avx512f"))
#else
#define TALLIED_COPY_RUNS() __builtin_cpu_supports("fma")
#endif
static long tally_rest, tally_moving, tally_rotation;
#define TALLY(kind) tally_##kind
#define ONCE_AVX_TALLY(kind, done) (tally_##kind += __builtin_popcount((unsigned)(done)))
#define EXACT_COPY(name) name##_tallied
#pragma GCC push_options
#ifdef EXACT_TEST_WIDE
#include "avx512_copy.c"
#else
#include "exact_fma.c"
#endif
#pragma GCC pop_options
/* the test's own calls go to the core */
#undef pendulum_exact_init
#undef pendulum_exact_init_gl
#undef pendulum_exact_resolvable
#undef pendulum_exact_eval
#undef pendulum_exact_eval_many
#undef pendulum_exact_once_gl_many
#undef pendulum_exact_period
int pendulum_exact_init(PendulumExact *ex, double theta0, double omega0, double w0, double t0);
int pendulum_exact_init_gl(PendulumExact *ex, double theta0, double omega0, double g, double L, double t0);
int pendulum_exact_resolvable(const PendulumExact *ex, double t);
void pendulum_exact_eval(const PendulumExact *ex, double t, double *theta, double *omega);
void pendulum_exact_eval_many(const PendulumExact *ex, size_t n, const double *t, double *theta, double *omega);
size_t pendulum_exact_once_gl_many(size_t n, const double *theta0, const double *omega0, const double *g,
                                   const double *L, double t0, const double *t, double *theta, double *omega);
double pendulum_exact_period(const PendulumExact *ex);
#else
#define TALLY(kind) 0L   /* no tallied copy: nothing counted */
#include "exact.h"
#endif

#include "check.h"

#define PI 3.14159265358979323846
#define MAX_POINTS 203

static int same_bits(double a, double b)
{
    uint64_t x, y;
    memcpy(&x, &a, sizeof x);
    memcpy(&y, &b, sizeof y);
    return x == y;
}

static unsigned long long rng_state = 0x243F6A8885A308D3ULL;

static double uniform(void)
{
    unsigned long long x = rng_state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    rng_state = x;
    return (double)((x * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-53;
}

/* Compares the batch with the scalar loop over n times; returns the number of differences. */
static int compare(const PendulumExact *ex, size_t n, const double *t, const char *what)
{
    double theta[MAX_POINTS], omega[MAX_POINTS];
    pendulum_exact_eval_many(ex, n, t, theta, omega);
    int differences = 0;
    for (size_t i = 0; i < n; ++i) {
        double th, om;
        pendulum_exact_eval(ex, t[i], &th, &om);
        if (!same_bits(th, theta[i]) || !same_bits(om, omega[i])) {
            if (differences == 0) {
                check(0, "%s: point %zu at t=%.17g: batch (%.17g, %.17g), scalar (%.17g, %.17g)", what, i, t[i],
                      theta[i], omega[i], th, om);
            }
            ++differences;
        }
    }
    return differences;
}

/* Times over `periods` periods from t0, with special times mixed in when `mixed`. */
static size_t make_times(const PendulumExact *ex, double periods, int mixed, double *t)
{
    const double period = isfinite(pendulum_exact_period(ex)) ? pendulum_exact_period(ex) : 10.0;
    size_t n = MAX_POINTS;
    for (size_t i = 0; i < n; ++i) {
        t[i] = ex->t0 + (2.0 * uniform() - 1.0) * periods * period;
    }
    if (mixed) {
        t[5] = ex->t0;                       /* the initial state as given */
        t[17] = NAN;
        t[30] = INFINITY;
        t[41] = -INFINITY;
        t[58] = ex->t0 + 0x1p52 * period;    /* past 2^50 quarter periods: the wide phase */
        t[77] = ex->t0 + 0x1p62 * period;    /* past 2^60: not resolvable */
        t[101] = ex->t0 - 0x1p49 * period;   /* just below the wide phase */
        t[150] = 1e300;
    }
    return n;
}

static void check_state(double theta0, double omega0, double w0, double t0, const char *label)
{
    PendulumExact ex;
    check(pendulum_exact_init(&ex, theta0, omega0, w0, t0) == 0, "%s: init", label);
    double t[MAX_POINTS];
    for (int mixed = 0; mixed <= 1; ++mixed) {
        const double horizons[] = {1.0, 50.0, 1e6};
        for (size_t h = 0; h < sizeof horizons / sizeof horizons[0]; ++h) {
            const size_t n = make_times(&ex, horizons[h], mixed, t);
            /* every count from 0 to 33 (two blocks of 16 lanes and every remainder), then all */
            for (size_t count = 0; count < 34; ++count) {
                check(compare(&ex, count, t, label) == 0, "%s: %zu points (horizon %g, mixed %d)", label, count,
                      horizons[h], mixed);
            }
            check(compare(&ex, n, t, label) == 0, "%s: %zu points (horizon %g periods, mixed %d)", label, n,
                  horizons[h], mixed);
        }
    }
}

/* One array of new states for pendulum_exact_once_gl_many */
typedef struct {
    size_t n;
    const double *theta0, *omega0, *g, *L;
    double t0;
    const double *t;
} Once;

/* The arrays of once_gl_many's checks: mostly 1 to 40 elements, one in five up to MAX_ARRAY,
 * past the 64 elements it sorts at a time */
#define MAX_ARRAY 150

static size_t draw_count(void)
{
    return 1 + (size_t)(uniform() * (uniform() < 0.8 ? 40.0 : (double)MAX_ARRAY));
}

typedef size_t OnceFunction(size_t n, const double *theta0, const double *omega0, const double *g, const double *L,
                            double t0, const double *t, double *theta, double *omega);

/* `once` over the array a against pendulum_exact_init_gl, _eval and _resolvable, element by
 * element: returns the number of elements whose outputs differ (the first is printed), counts
 * a wrong number of refused elements in *wrong_counts and the refused inputs in *refusals */
static int compare_once(OnceFunction *once, const Once *a, int *wrong_counts, int *refusals)
{
    double theta[MAX_ARRAY], omega[MAX_ARRAY];
    const size_t refused = once(a->n, a->theta0, a->omega0, a->g, a->L, a->t0, a->t, theta, omega);
    size_t expected_refused = 0;
    int differences = 0;
    for (size_t i = 0; i < a->n; ++i) {
        PendulumExact ex;
        double th = NAN, om = NAN;
        if (pendulum_exact_init_gl(&ex, a->theta0[i], a->omega0[i], a->g[i], a->L[i], a->t0) == 0) {
            pendulum_exact_eval(&ex, a->t[i], &th, &om);
            expected_refused += !pendulum_exact_resolvable(&ex, a->t[i]);
        } else {
            expected_refused += 1;
            *refusals += 1;
        }
        if (!same_bits(th, theta[i]) || !same_bits(om, omega[i])) {
            if (differences++ == 0) {
                check(0, "once: theta0 = %a, omega0 = %a, g = %a, L = %a, t0 = %a at t = %.17g: (%.17g, %.17g), "
                      "scalar (%.17g, %.17g)", a->theta0[i], a->omega0[i], a->g[i], a->L[i], a->t0, a->t[i], theta[i],
                      omega[i], th, om);
            }
        }
    }
    *wrong_counts += refused != expected_refused;
    return differences;
}

/* compare_once of the core's pendulum_exact_once_gl_many and, where the processor has an fma,
 * of the tallied copy (whose vector lanes are counted) */
static int compare_both(const Once *a, int *wrong_counts, int *refusals)
{
    int differences = compare_once(pendulum_exact_once_gl_many, a, wrong_counts, refusals);
#ifdef EXACT_TALLIED
    if (TALLIED_COPY_RUNS()) {
        differences += compare_once(pendulum_exact_once_gl_many_tallied, a, wrong_counts, refusals);
    }
#endif
    return differences;
}

/* The checks of a run of arrays of one kind of moving start: no output differs, the counts of
 * refused elements are right, most states are of the kind, and (fma build) the vectors did
 * at least the `must` states that qualify and at most the `of_kind` of that kind */
static void check_kind(const char *kind, int differences, int wrong_counts, int points, long must, long of_kind,
                       long tally)
{
    check(differences == 0, "once_gl_many, %s: %d outputs differ from the set-up and evaluation (%d states)", kind,
          differences, points);
    check(wrong_counts == 0, "once_gl_many, %s: %d arrays with a wrong count of refused elements", kind, wrong_counts);
    check(must > points / 2, "once_gl_many, %s: %ld of %d states for the vectors", kind, must, points);
#ifdef EXACT_TALLIED
    if (TALLIED_COPY_RUNS()) {
        check(tally >= must && tally <= of_kind,
              "once_gl_many, %s: the vectors did %ld, at least %ld and at most %ld expected", kind, tally, must,
              of_kind);
        printf("once_gl_many, %s: %ld of %d states in vectors (%ld required, %ld of the kind)\n", kind, tally,
               points, must, of_kind);
        return;
    }
#endif
    (void)tally;
    (void)of_kind;
    printf("once_gl_many, %s: no fma build here, or this processor cannot run the tallied copy: its vectors "
           "not counted\n", kind);
}

/* pendulum_exact_once_gl_many against pendulum_exact_init_gl, _eval and _resolvable, element
 * by element: arrays (draw_count) of releases from rest (most: every amplitude, near the top, past
 * pi, tiny), moving starts, refused inputs, runs of one g and L, special times. */
static void check_once(void)
{
    int differences = 0, points = 0, refusals = 0, wrong_counts = 0;
    for (int round = 0; round < 4000; ++round) {
        const size_t n = draw_count();
        double theta0[MAX_ARRAY], omega0[MAX_ARRAY], g[MAX_ARRAY], L[MAX_ARRAY], t[MAX_ARRAY];
        const double t0 = uniform() < 0.6 ? 0.0 : 3.0 * (2.0 * uniform() - 1.0);
        for (size_t i = 0; i < n; ++i) {
            g[i] = 0.5 + 20.0 * uniform();
            L[i] = 0.05 + 5.0 * uniform();
            if (i > 0 && uniform() < 0.6) {
                g[i] = g[i - 1];
                L[i] = L[i - 1];
            }
            const double kind = uniform(), w0 = sqrt(g[i] / L[i]);
            theta0[i] = (2.0 * uniform() - 1.0) * PI;
            omega0[i] = 0.0;
            if (kind < 0.1) {
                theta0[i] = (uniform() < 0.5 ? -PI : PI) * (1.0 - pow(10.0, -1.0 - 15.0 * uniform()));
            } else if (kind < 0.15) {
                theta0[i] = (uniform() < 0.5 ? -1.0 : 1.0) * (PI + 0.058 * uniform());
            } else if (kind < 0.2) {
                theta0[i] *= pow(10.0, -300.0 * uniform());
            } else if (kind < 0.3) {
                omega0[i] = (2.0 * uniform() - 1.0) * 3.0 * w0;
            } else if (kind < 0.33) {
                theta0[i] += 2.0 * PI * floor(100.0 * uniform());
            } else if (kind < 0.36) {
                const double bad[] = {NAN, INFINITY, -1.0, 0.0};
                g[i] = bad[(int)(uniform() * 4)];
            }
            const double period = 2.0 * PI / w0;
            t[i] = t0 + (2.0 * uniform() - 1.0) * (uniform() < 0.5 ? 50.0 : 1e6) * period;
            if (uniform() < 0.05) {
                const double special[] = {t0, NAN, INFINITY, t0 + 0x1p52 * period, t0 + 0x1p63 * period};
                t[i] = special[(int)(uniform() * 5)];
            }
        }
        const Once arrays = {n, theta0, omega0, g, L, t0, t};
        differences += compare_both(&arrays, &wrong_counts, &refusals);
        points += (int)n;
    }
    /* releases from the edges of the set-up's cases: theta0 / 2 on the table's points i/64 and
     * half-way between them (ties of the nearest point), next to the quadrant's bound pi/4,
     * signed zeros, tiny, pi and just past it */
    double edge[200];
    int edges = 0;
    for (int i = 0; i <= 50; ++i) {
        edge[edges++] = i / 32.0;
        edge[edges++] = -(i + 0.5) / 32.0;
        edge[edges++] = nextafter((i + 0.5) / 32.0, 0.0);
    }
    const double quarter = 0.5 * PI;   /* theta0 / 2 = pi/4 (the double) */
    const double special[] = {quarter, nextafter(quarter, 0.0), nextafter(quarter, 4.0), -quarter, 0.0, -0.0,
                              0x1p-1000, -0x1p-30, PI, -PI, nextafter(PI, 4.0), 3.2, -3.15};
    for (size_t i = 0; i < sizeof special / sizeof special[0]; ++i) {
        edge[edges++] = special[i];
    }
    for (int i = 0; i < edges; ++i) {
        double zero = 0.0, g = 9.81, L = 0.5 + i, t = (i % 2 ? 1e8 : 0.37) * i + 0.1, theta, omega, th, om;
        const size_t refused = pendulum_exact_once_gl_many(1, &edge[i], &zero, &g, &L, 0.0, &t, &theta, &omega);
        PendulumExact ex;
        check(pendulum_exact_init_gl(&ex, edge[i], 0.0, g, L, 0.0) == 0 && refused == 0, "edge %a refused", edge[i]);
        pendulum_exact_eval(&ex, t, &th, &om);
        points++;
        if (!same_bits(th, theta) || !same_bits(om, omega)) {
            if (differences++ == 0) {
                check(0, "once: release from %a at t = %g: (%.17g, %.17g), scalar (%.17g, %.17g)", edge[i], t, theta,
                      omega, th, om);
            }
        }
    }
    check(differences == 0, "once_gl_many: %d of %d outputs differ from the set-up and evaluation", differences, points);
#ifdef EXACT_TALLIED
    /* about 60 % of the random states are releases from rest with |theta0| <= 3.2 */
    check(!TALLIED_COPY_RUNS() || tally_rest > points / 2,
          "once_gl_many: the vectors did %ld releases from rest of %d states", tally_rest, points);
    printf("once_gl_many: %ld of %d states released from rest in vectors\n", tally_rest, points);
#endif
    check(wrong_counts == 0, "once_gl_many: %d arrays with a wrong count of refused elements", wrong_counts);
    check(refusals > 1000, "once_gl_many: %d refused inputs drawn", refusals);
}


/* theta0, or in one draw of seven theta0 wound up by whole turns (up to 10^3 or 10^12 of them,
 * either way), which the vectors take after one subtraction of turns */
static double wound_up(double theta0)
{
    if (uniform() >= 1.0 / 7.0) {
        return theta0;
    }
    const double turns = floor(uniform() * (uniform() < 0.5 ? 1e3 : 1e12));
    return theta0 + (uniform() < 0.5 ? -2.0 : 2.0) * PI * turns;
}

/* g[i] and L[i] log-uniform over 10^+-decades, *far (one of them) beyond 2^+-450 in one draw
 * of 33, and in one of two the previous element's g and L again (a run of one rate) */
static void draw_g_L(double *g, double *L, size_t i, double decades, double *far)
{
    g[i] = pow(10.0, 2.0 * decades * uniform() - decades);
    L[i] = pow(10.0, 2.0 * decades * uniform() - decades);
    if (uniform() < 0.03) {
        *far = ldexp(*far, uniform() < 0.5 ? 450 : -450);
    }
    if (i > 0 && uniform() < 0.5) {
        g[i] = g[i - 1];
        L[i] = L[i - 1];
    }
}

/* A moving start of kind `kind` for w0 = sqrt(g/L): librations of every amplitude and speed
 * (small, large, q next to c, next to locate_separatrix's fine window 2^-30 on either side,
 * k tiny, m1 tiny, theta0 just past pi, omega0 of a few ulps), a few rotations,
 * separatrices and refused speeds (huge, infinite, NaN) among them; both signs of theta0 and
 * omega0 */
static void draw_moving(int kind, double w0, double *theta0, double *omega0)
{
    const double sign_th = uniform() < 0.5 ? -1.0 : 1.0, sign_om = uniform() < 0.5 ? -1.0 : 1.0;
    double th = (2.0 * uniform() - 1.0) * PI;
    switch (kind) {
    case 0: th = 0.2 * th; break;                                              /* small */
    case 4: th = uniform() < 0.1 ? sign_th * 0.0 : th * pow(10.0, -5.0 - 295.0 * uniform()); break;   /* k tiny */
    case 5: th = sign_th * PI * (1.0 - pow(10.0, -4.0 - 11.0 * uniform())); break;   /* m1 tiny */
    case 6: th = sign_th * (PI + 0.058 * uniform()); break;                     /* just past pi */
    case 9: th = sign_th * (2.5 + 0.64 * uniform()); break;                     /* near the top */
    default: break;
    }
    const double edge = 2.0 * w0 * fabs(cos(0.5 * th));   /* the separatrix speed */
    double speed = uniform() * edge;
    switch (kind) {
    case 0: speed = 0.2 * uniform() * edge; break;
    case 2: speed = edge * (1.0 - pow(10.0, -1.0 - 7.0 * uniform())); break;   /* q next to c */
    case 3: speed = edge / (1.0 + 0x1p-30 * (0.25 + 3.75 * uniform())); break;   /* the fine window's edge */
    case 4: speed = uniform() < 0.2 ? 0.0 : w0 * pow(10.0, -5.0 - 295.0 * uniform()); break;
    case 7: speed = (const double[]){0x1p-1074, 0x1p-1073, 1e-300, 1e-20, 1.7e308, INFINITY, NAN}[(int)(uniform() * 7)];
        break;
    case 8: speed = uniform() < 0.2 ? edge : edge * (1.0 + pow(10.0, -8.0 * uniform())); break;   /* rotation */
    default: break;
    }
    *theta0 = wound_up(th);
    *omega0 = sign_om * (speed == 0.0 ? 0x1p-1074 : speed);
}

/* A moving libration that the vectors must take: |theta0| < 2^44 (one subtraction of turns
 * brings it within 3.2), m1 clear of the fine
 * window (|c/q - 1| above 2^-28 in double, which is within 1e-15 of the set-up's), omega0
 * not of a few ulps, a time on the evaluation's common path */
static int vector_libration(const PendulumExact *ex, double theta0, double omega0, double w0, double t)
{
    const double c = fabs(cos(0.5 * theta0)), q = 0.5 * fabs(omega0) / w0;
    return ex->regime == PENDULUM_LIBRATION && fabs(theta0) < 0x1p44 && fabs(omega0) > 1e-290 && fabs(c / q - 1.0) > 0x1p-28
           && t != ex->t0 && fabs(ex->rho_hi * (t - ex->t0)) < 0x1p49;
}

/* pendulum_exact_once_gl_many over arrays of moving starts, mostly librations of every kind
 * (draw_moving), any g and L (runs of one, and beyond 2^+-400 where w0_of_gl scales), t0 = 0
 * or not, special times: the core's and the tallied copy's bits equal the scalar set-up's,
 * and the copy's vectors did every moving libration they must take. */
static void check_once_moving(void)
{
    int differences = 0, points = 0, refusals = 0, wrong_counts = 0;
    long must = 0, librations = 0;
#ifdef EXACT_TALLIED
    tally_moving = 0;
#endif
    for (int round = 0; round < 3000; ++round) {
        const size_t n = draw_count();
        double theta0[MAX_ARRAY], omega0[MAX_ARRAY], g[MAX_ARRAY], L[MAX_ARRAY], t[MAX_ARRAY];
        const double t0 = uniform() < 0.5 ? 0.0 : 5.0 * (2.0 * uniform() - 1.0);
        for (size_t i = 0; i < n; ++i) {
            draw_g_L(g, L, i, 3.0, &g[i]);
            const double w0 = sqrt(g[i] / L[i]), period = 2.0 * PI / w0;
            draw_moving((int)(uniform() * 10), w0, &theta0[i], &omega0[i]);
            t[i] = t0 + (2.0 * uniform() - 1.0) * (uniform() < 0.5 ? 3.0 : 1e6) * period;
            if (uniform() < 0.03) {
                const double special[] = {t0, NAN, INFINITY, t0 + 0x1p52 * period};
                t[i] = special[(int)(uniform() * 4)];
            }
            PendulumExact ex;
            if (pendulum_exact_init_gl(&ex, theta0[i], omega0[i], g[i], L[i], t0) == 0) {
                must += vector_libration(&ex, theta0[i], omega0[i], w0, t[i]);
                librations += ex.regime == PENDULUM_LIBRATION;
            }
        }
        const Once arrays = {n, theta0, omega0, g, L, t0, t};
        differences += compare_both(&arrays, &wrong_counts, &refusals);
        points += (int)n;
    }
    check_kind("moving librations", differences, wrong_counts, points, must, librations, TALLY(moving));
}

/* A rotation for w0: barely over the top (within 2^-26 of the separatrix speed, either side
 * of the fine window's edge 2^-30), just over it, fast spins (omega0 up to 1e8 w0), or any
 * speed above; theta0 of both signs, anywhere, near pi or just past it (up to 3.2), and
 * omega0 of both signs */
static void draw_rotation(double w0, double *theta0, double *omega0)
{
    const double sign_th = uniform() < 0.5 ? -1.0 : 1.0, sign_om = uniform() < 0.5 ? -1.0 : 1.0;
    const double where = uniform();
    double th = (2.0 * uniform() - 1.0) * PI;
    if (where < 0.15) {
        th = sign_th * PI * (1.0 - pow(10.0, -1.0 - 15.0 * uniform()));   /* near the top */
    } else if (where < 0.3) {
        th = sign_th * (PI + (3.2 - PI) * uniform());                        /* past pi */
    } else if (where < 0.4) {
        th = sign_th * uniform() * pow(10.0, -10.0 * uniform());             /* near the bottom */
    }
    const double edge = 2.0 * w0 * fabs(cos(0.5 * th)), kind = uniform();   /* the separatrix speed */
    double speed = edge * (1.0 + 3.0 * uniform());
    if (kind < 0.25) {
        speed = edge * (1.0 + 0x1p-30 * (0.25 + 63.75 * uniform()));   /* the fine window's edge */
    } else if (kind < 0.4) {
        speed = edge * (1.0 + pow(10.0, -8.0 * uniform()));
    } else if (kind < 0.6) {
        speed = w0 * pow(10.0, 8.0 * uniform());                       /* fast spins */
    }
    *theta0 = wound_up(th);
    *omega0 = sign_om * speed;
}

/* A rotation that the vectors must take: |theta0| < 2^44, clear of the fine window (|c/q - 1|
 * above 2^-28 in double, within 1e-15 of the set-up's), a time on the evaluation's common
 * path */
static int vector_rotation(const PendulumExact *ex, double theta0, double omega0, double w0, double t)
{
    const double c = fabs(cos(0.5 * theta0)), q = 0.5 * fabs(omega0) / w0;
    return ex->regime == PENDULUM_ROTATION && fabs(theta0) < 0x1p44 && fabs(c / q - 1.0) > 0x1p-28 && t != ex->t0
           && fabs(ex->rho_hi * (t - ex->t0)) < 0x1p49;
}

/* pendulum_exact_once_gl_many over arrays of rotations (draw_rotation) with a few moving
 * librations and releases from rest among them, any g and L (over twelve orders, and beyond
 * 2^+-400), t0 = 0 or not, times from a fraction of a turn to 1e12 turns and special times:
 * the bits of the scalar set-up, and the tallied copy's vectors did every rotation they must
 * take and no more rotations than there are */
static void check_once_rotation(void)
{
    int differences = 0, points = 0, refusals = 0, wrong_counts = 0;
    long must = 0, rotations = 0;
#ifdef EXACT_TALLIED
    tally_rotation = 0;
#endif
    for (int round = 0; round < 3000; ++round) {
        const size_t n = draw_count();
        double theta0[MAX_ARRAY], omega0[MAX_ARRAY], g[MAX_ARRAY], L[MAX_ARRAY], t[MAX_ARRAY];
        const double t0 = uniform() < 0.5 ? 0.0 : 1e3 * (2.0 * uniform() - 1.0);
        for (size_t i = 0; i < n; ++i) {
            draw_g_L(g, L, i, 6.0, &L[i]);
            const double w0 = sqrt(g[i] / L[i]);
            const double other = uniform();
            if (other < 0.1) {
                draw_moving((int)(uniform() * 10), w0, &theta0[i], &omega0[i]);
            } else {
                draw_rotation(w0, &theta0[i], &omega0[i]);
                omega0[i] = other < 0.12 ? 0.0 : omega0[i];
            }
            PendulumExact ex;
            const int set_up = pendulum_exact_init_gl(&ex, theta0[i], omega0[i], g[i], L[i], t0) == 0;
            const double period = set_up && isfinite(pendulum_exact_period(&ex)) ? pendulum_exact_period(&ex) : 1.0 / w0;
            const double turns[] = {0.3, 50.0, 1e6, 1e12};
            t[i] = t0 + (2.0 * uniform() - 1.0) * turns[(int)(uniform() * 4)] * period;
            if (uniform() < 0.04) {
                const double special[] = {t0, NAN, INFINITY, t0 + 0x1p52 * period, t0 - 0x1p63 * period};
                t[i] = special[(int)(uniform() * 5)];
            }
            if (set_up) {
                must += vector_rotation(&ex, theta0[i], omega0[i], w0, t[i]);
                rotations += ex.regime == PENDULUM_ROTATION;
            }
        }
        const Once arrays = {n, theta0, omega0, g, L, t0, t};
        differences += compare_both(&arrays, &wrong_counts, &refusals);
        points += (int)n;
    }
    check_kind("rotations", differences, wrong_counts, points, must, rotations, TALLY(rotation));
}

int main(void)
{
    check_once();
    check_once_moving();
    check_once_rotation();
    /* librations from rest, few levels (the lock-step path) and near the top (many levels) */
    const double amplitudes_deg[] = {1e-6, 0.5, 10.0, 45.0, 90.0, 135.0, 170.0, 179.0, 179.9999, 180.0 - 1e-9,
                                     180.0 - 1e-12, 180.0};
    int lock_step = 0, fallback = 0;
    for (size_t i = 0; i < sizeof amplitudes_deg / sizeof amplitudes_deg[0]; ++i) {
        char label[64];
        const double theta0 = amplitudes_deg[i] * (PI / 180.0);
        PendulumExact ex;
        check(pendulum_exact_init(&ex, theta0, 0.0, 1.0, 0.0) == 0, "init %g deg", amplitudes_deg[i]);
        lock_step += ex.ell.levels <= ELLIPTIC_LEVELS_WITHOUT_RESCALE;
        fallback += ex.ell.levels > ELLIPTIC_LEVELS_WITHOUT_RESCALE;
        snprintf(label, sizeof label, "libration %g deg", amplitudes_deg[i]);
        check_state(theta0, 0.0, 1.0, 0.0, label);
        snprintf(label, sizeof label, "libration -%g deg, t0 = 2.5", amplitudes_deg[i]);
        check_state(-theta0, 0.0, 3.13, 2.5, label);
    }
    check(lock_step >= 6 && fallback >= 1, "both paths covered: %d states lock-step, %d scalar", lock_step, fallback);
    /* moving starts, wound-up angles, rotations, separatrix, rest */
    check_state(0.3, 1.2, 1.0, 0.0, "libration with omega0");
    check_state(-2.0, -0.7, 2.0, -1.0, "libration with omega0 < 0");
    check_state(0.3 + 6.0 * PI, 0.4, 1.0, 0.0, "libration three turns up");
    check_state(-1e6, 0.1, 1.0, 0.0, "libration 1e6 rad down");
    check_state(1e17, 0.0, 1.0, 0.0, "libration at theta0 = 1e17");
    check_state(0.5, 2.5, 1.0, 0.0, "rotation");
    check_state(0.5, -30.0, 1.0, 0.0, "fast rotation backwards");
    check_state(0.0, 2.0, 1.0, 0.0, "separatrix");
    check_state(PI, 0.0, 1.0, 0.0, "at rest on the top");
    check_state(0.0, 0.0, 1.0, 0.0, "at rest at the bottom");
    return check_summary(TEST_NAME);
}
