/* pendulum_exact_lib.c: see pendulum_exact_lib.h. */
#include "pendulum_exact_lib.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "exact.h"

int pendulum_exact_abi(void) { return PENDULUM_EXACT_ABI; }

/* The same solution as the FMU's initialization (model.c): set up from g and L as given, w0 in
 * double-double (pendulum_exact_init_gl), refused unless g / L is finite and > 0. */
static int set_up(PendulumExact *ex, double theta0, double omega0, double L, double g)
{
    double w0sq = g / L;
    if (!(L > 0.0) || !(g > 0.0) || !isfinite(L) || !isfinite(g) || !(w0sq > 0.0) || !isfinite(w0sq)) {
        return -1;
    }
    return pendulum_exact_init_gl(ex, theta0, omega0, g, L, 0.0);
}

/* Equal as bit patterns: -0.0 and 0.0 differ (they may set up different solutions). */
static int same_bits(double a, double b)
{
    uint64_t x, y;
    memcpy(&x, &a, sizeof x);
    memcpy(&y, &b, sizeof y);
    return x == y;
}

size_t pendulum_exact_many(size_t n, const double *theta0, const double *omega0, const double *L,
                           const double *g, const double *t, double *theta, double *omega)
{
    PendulumExact ex;
    size_t refused = 0;
    int ready = 0; /* 1: ex holds the solution of element i - 1's inputs; -1: they were refused */
    for (size_t i = 0; i < n; ++i) {
        int same = i > 0 && same_bits(theta0[i], theta0[i - 1]) && same_bits(omega0[i], omega0[i - 1]) &&
                   same_bits(L[i], L[i - 1]) && same_bits(g[i], g[i - 1]);
        if (!same) {
            ready = set_up(&ex, theta0[i], omega0[i], L[i], g[i]) == 0 ? 1 : -1;
        }
        if (ready == 1 && isfinite(t[i])) {
            pendulum_exact_eval(&ex, t[i], &theta[i], &omega[i]);
        } else {
            theta[i] = omega[i] = NAN;
            ++refused;
        }
    }
    return refused;
}

size_t pendulum_exact_times(double theta0, double omega0, double L, double g, size_t n, const double *t,
                            double *theta, double *omega)
{
    PendulumExact ex;
    int ready = set_up(&ex, theta0, omega0, L, g) == 0;
    size_t refused = 0;
    for (size_t i = 0; i < n; ++i) {
        if (ready && isfinite(t[i])) {
            pendulum_exact_eval(&ex, t[i], &theta[i], &omega[i]);
        } else {
            theta[i] = omega[i] = NAN;
            ++refused;
        }
    }
    return refused;
}
