/* test_exact_batch.c: pendulum_exact_eval_many (points of a libration in lock-step) and
 * pendulum_exact_once_gl_many (new states each set up and evaluated once, in blocks) give bit
 * for bit what pendulum_exact_init_gl and pendulum_exact_eval give, point by point, for every kind of state and time:
 * librations with few and with many Landen levels (lock-step and the scalar fallback), wound-up
 * initial angles, rotations, the separatrix, rest; times at t0 exactly, negative, far (past
 * 2^50 and 2^60 quarter periods), NaN and infinite, in blocks that mix them, and counts that
 * are not a multiple of the lane count; for the new states, arrays that mix every kind of
 * state, refused inputs and special times. Prints one summary line; exit status 0 iff every
 * check passed. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "exact.h"

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

/* pendulum_exact_once_gl_many against pendulum_exact_init_gl, _eval and _resolvable, element
 * by element: arrays of 1 to 40 releases from rest (most: every amplitude, near the top, past
 * pi, tiny), moving starts, refused inputs, runs of one g and L, special times. */
static void check_once(void)
{
    int differences = 0, points = 0, refusals = 0, wrong_counts = 0;
    for (int round = 0; round < 4000; ++round) {
        const size_t n = 1 + (size_t)(uniform() * 40);
        double theta0[40], omega0[40], g[40], L[40], t[40], theta[40], omega[40];
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
        const size_t refused = pendulum_exact_once_gl_many(n, theta0, omega0, g, L, t0, t, theta, omega);
        size_t expected_refused = 0;
        for (size_t i = 0; i < n; ++i) {
            PendulumExact ex;
            double th = NAN, om = NAN;
            if (pendulum_exact_init_gl(&ex, theta0[i], omega0[i], g[i], L[i], t0) == 0) {
                pendulum_exact_eval(&ex, t[i], &th, &om);
                expected_refused += !pendulum_exact_resolvable(&ex, t[i]);
            } else {
                expected_refused += 1;
                refusals++;
            }
            points++;
            if (!same_bits(th, theta[i]) || !same_bits(om, omega[i])) {
                if (differences++ == 0) {
                    check(0, "once: theta0 = %.17g, omega0 = %.17g, g = %.17g, L = %.17g at t = %.17g: (%.17g, %.17g), "
                          "scalar (%.17g, %.17g)", theta0[i], omega0[i], g[i], L[i], t[i], theta[i], omega[i], th, om);
                }
            }
        }
        wrong_counts += refused != expected_refused;
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
    check(wrong_counts == 0, "once_gl_many: %d arrays with a wrong count of refused elements", wrong_counts);
    check(refusals > 1000, "once_gl_many: %d refused inputs drawn", refusals);
}

int main(void)
{
    check_once();
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
    return check_summary("test_exact_batch");
}
