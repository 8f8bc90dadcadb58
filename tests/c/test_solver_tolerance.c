/* test_solver_tolerance.c: every solver honours its tolerance in every regime:
 * max |theta - theta_exact| <= 100 tol over 10 periods or revolutions, for tol
 * 1e-4 .. 1e-10, at rest and moving, small and large amplitudes, fast rotation, and states
 * down to 1e-6 (in m1, the complementary parameter) from the separatrix on both sides.
 * The reference is the exact port (fmu_src/math/exact.c, itself checked against mpmath at 50
 * digits by tests/exact/test_exact_mpmath.py and tests/exact/test_exact_edges.py), ~1e-14 here.
 *
 * Run with an argument to print the table of error / tol per solver and state. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "exact.h"
#include "integrator.h"

#define LIMIT 100.0     /* allowed max |theta - theta_exact| in units of tol */
#define PERIODS 10.0
#define SAMPLES_PER_PERIOD 40

typedef struct {
    const char *name;
    double theta0, omega0, w0sq;
} State;

/* theta0 at rest with complementary parameter m1 = cos^2(theta0/2) */
static double rest_angle(double m1)
{
    return 2.0 * acos(sqrt(m1));
}

/* max |theta - theta_exact| over PERIODS periods (revolutions) of the exact motion */
static double max_error(SolverKind kind, double tol, const State *s, long *steps)
{
    PendulumExact ex;
    Integrator it;
    const double w0 = sqrt(s->w0sq);
    if (pendulum_exact_init(&ex, s->theta0, s->omega0, w0, 0.0) != 0 ||
        integrator_init(&it, kind, s->w0sq, tol, 0.0, s->theta0, s->omega0) != 0) {
        return INFINITY;
    }
    const double period = pendulum_exact_period(&ex);
    const int n = (int)(PERIODS * SAMPLES_PER_PERIOD);
    double worst = 0.0;
    for (int i = 1; i <= n; ++i) {
        const double t = PERIODS * period * i / n;
        double y[2], theta, omega;
        if (integrator_advance(&it, t, y) != 0) {
            return INFINITY;
        }
        pendulum_exact_eval(&ex, t, &theta, &omega);
        worst = fmax(worst, fabs(y[0] - theta));
    }
    *steps = it.stats.steps;
    return worst;
}

/* xorshift64: the same pseudo-random states in every run */
static double uniform(unsigned long long *rng)
{
    *rng ^= *rng << 13, *rng ^= *rng >> 7, *rng ^= *rng << 17;
    return (double)(*rng >> 11) * 0x1p-53;
}

/* A random state: theta0 in [-4 pi, 4 pi], g/L in 1e-3..1e3, omega0 such that the motion is
 * a libration or a rotation with |m1| / max(1, m) = 10^-u, u uniform in [0, 6] (so at least
 * 1e-6 from the separatrix), or a fast rotation up to 100 times the separatrix speed. */
static State random_state(unsigned long long *rng)
{
    State s = {"random", 0.0, 0.0, 1.0};
    s.theta0 = (2.0 * uniform(rng) - 1.0) * 4.0 * PI;
    s.w0sq = pow(10.0, 6.0 * uniform(rng) - 3.0);
    const double w0 = sqrt(s.w0sq), c = fabs(cos(0.5 * s.theta0));
    const double closeness = pow(10.0, -6.0 * uniform(rng));
    const double kind = uniform(rng), sign = uniform(rng) < 0.5 ? -1.0 : 1.0;
    double q2;                                   /* q^2 = (omega0 / (2 w0))^2 */
    if (kind < 0.4) {
        q2 = c * c - closeness;                  /* libration: m1 = closeness */
        if (q2 < 0.0) {
            q2 = 0.0;                            /* (then m1 = c^2, further from the top) */
        }
    } else if (kind < 0.8) {
        const double s2 = 1.0 - c * c;           /* rotation: -m1 / m = closeness */
        q2 = (c * c + closeness * s2) / (1.0 - closeness);
    } else {
        q2 = pow(10.0, 4.0 * uniform(rng));      /* fast rotation, up to 100 x 2 w0 */
    }
    s.omega0 = sign * 2.0 * w0 * sqrt(q2);
    return s;
}

int main(int argc, char **argv)
{
    const int verbose = argc > 1 && argv[1] != NULL;
    const double w0sq_slow = 0.00668 / 45.165;
    State states[] = {
        {"rest 0.3 rad", 0.3, 0.0, 1.0},
        {"rest 90 deg", 0.5 * PI, 0.0, 9.81},
        {"rest 170 deg", 170.0 * PI / 180.0, 0.0, 1.0},
        {"rest m1 = 1e-2", rest_angle(1e-2), 0.0, 1.0},
        {"rest m1 = 1e-4", rest_angle(1e-4), 0.0, 1.0},
        {"rest m1 = 1e-6", rest_angle(1e-6), 0.0, 1.0},
        {"rest 3.0639, slow", 3.0638846369717534, 0.0, w0sq_slow},
        {"moving 0.3, -1.2", 0.3, -1.2, 4.0},
        {"rotation m1 = -1e-6", 0.0, 2.0 * sqrt(1.0 + 1e-6), 1.0},
        {"rotation m1 = -1e-4", 0.0, 2.0 * sqrt(1.0 + 1e-4), 1.0},
        {"rotation 2.5", 0.5, 2.5, 1.0},
        {"rotation 30", 0.3, 30.0, 1.0},
        {"rotation 300", 0.3, 300.0, 1.0},
        {"rotation -1000, g/L = 9.81", -1.0, -1000.0, 9.81},
    };
    unsigned long long rng = 0x9E3779B97F4A7C15ull;
    State all[sizeof states / sizeof states[0] + 40];
    size_t n_states = 0;
    for (size_t i = 0; i < sizeof states / sizeof states[0]; ++i) {
        all[n_states++] = states[i];
    }
    while (n_states < sizeof all / sizeof all[0]) {
        all[n_states++] = random_state(&rng);
    }
    const SolverKind kinds[] = {SOLVER_DOPRI5, SOLVER_RK4, SOLVER_RKN, SOLVER_SYMPLECTIC};
    const double tols[] = {1e-4, 1e-6, 1e-8, 1e-10};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) {
        double worst_ratio = 0.0;
        for (size_t i = 0; i < n_states; ++i) {
            for (size_t j = 0; j < sizeof tols / sizeof tols[0]; ++j) {
                long steps = 0;
                const double err = max_error(kinds[k], tols[j], &all[i], &steps);
                const double ratio = err / tols[j];
                worst_ratio = fmax(worst_ratio, ratio);
                check(ratio <= LIMIT, "%s, %s (%.17g, %.17g, g/L %.17g), tol %g: max |theta - theta_exact| = %.3g = "
                      "%.3g tol", integrator_solver_name(kinds[k]), all[i].name, all[i].theta0, all[i].omega0, all[i].w0sq, tols[j], err,
                      ratio);
                if (verbose) {
                    printf("%-10s %-26s tol %-6g error/tol %9.3g  steps %ld\n", integrator_solver_name(kinds[k]), all[i].name,
                           tols[j], ratio, steps);
                }
            }
        }
        printf("%s: worst max|theta - theta_exact| / tol over 10 periods = %.3g\n", integrator_solver_name(kinds[k]), worst_ratio);
    }
    return check_summary("test_solver_tolerance");
}
