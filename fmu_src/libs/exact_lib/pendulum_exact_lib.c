/* pendulum_exact_lib.c: see pendulum_exact_lib.h. */
#include "pendulum_exact_lib.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "exact.h"

int pendulum_exact_abi(void) { return PENDULUM_EXACT_ABI; }

/* The same set-up as the FMU's initialization: sqrt(g / L) of the two doubles as given. */
static int set_up(PendulumExact *ex, double theta0, double omega0, double L, double g)
{
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

/* Evaluates ex at the n times t (batch: pendulum_exact_eval_many, bit for bit the scalar
 * evaluation) and returns how many of them are not resolvable (their outputs are NaN). */
static size_t evaluate(const PendulumExact *ex, size_t n, const double *t, double *theta, double *omega)
{
    if (n == 1) {   /* a state per point: the scalar evaluation itself (eval_many's bits) */
        pendulum_exact_eval(ex, t[0], theta, omega);
        return !pendulum_exact_resolvable(ex, t[0]);
    }
    pendulum_exact_eval_many(ex, n, t, theta, omega);
    size_t refused = 0;
    for (size_t i = 0; i < n; ++i) {
        refused += !pendulum_exact_resolvable(ex, t[i]);
    }
    return refused;
}

static void refuse(size_t n, double *theta, double *omega)
{
    for (size_t i = 0; i < n; ++i) {
        theta[i] = omega[i] = NAN;
    }
}

/* Elements whose inputs differ from both neighbours' (a state per point) are set up and
 * evaluated this many at a time by pendulum_exact_once_gl_many (releases from rest several at
 * once, the same bits). */
#define SINGLES 32

typedef struct {
    size_t count;
    size_t at[SINGLES];
    double theta0[SINGLES], omega0[SINGLES], L[SINGLES], g[SINGLES], t[SINGLES];
} Singles;

/* Sets up and evaluates the pending single elements; returns how many were refused. */
static size_t flush_singles(Singles *s, double *theta, double *omega)
{
    double theta_at[SINGLES], omega_at[SINGLES];
    const size_t refused = pendulum_exact_once_gl_many(s->count, s->theta0, s->omega0, s->g, s->L, 0.0, s->t,
                                                       theta_at, omega_at);
    for (size_t j = 0; j < s->count; ++j) {
        theta[s->at[j]] = theta_at[j];
        omega[s->at[j]] = omega_at[j];
    }
    s->count = 0;
    return refused;
}

size_t pendulum_exact_many(size_t n, const double *theta0, const double *omega0, const double *L,
                           const double *g, const double *t, double *theta, double *omega)
{
    size_t refused = 0;
    size_t start = 0;
    Singles singles;
    singles.count = 0;
    while (start < n) {
        /* a run of elements with the same inputs (bitwise) shares one set-up */
        size_t end = start + 1;
        while (end < n && same_bits(theta0[end], theta0[start]) && same_bits(omega0[end], omega0[start])
               && same_bits(L[end], L[start]) && same_bits(g[end], g[start])) {
            ++end;
        }
        if (end - start == 1) {
            const size_t j = singles.count++;
            singles.at[j] = start;
            singles.theta0[j] = theta0[start];
            singles.omega0[j] = omega0[start];
            singles.L[j] = L[start];
            singles.g[j] = g[start];
            singles.t[j] = t[start];
            if (singles.count == SINGLES) {
                refused += flush_singles(&singles, theta, omega);
            }
            start = end;
            continue;
        }
        PendulumExact ex;
        if (set_up(&ex, theta0[start], omega0[start], L[start], g[start]) == 0) {
            refused += evaluate(&ex, end - start, t + start, theta + start, omega + start);
        } else {
            refuse(end - start, theta + start, omega + start);
            refused += end - start;
        }
        start = end;
    }
    return refused + flush_singles(&singles, theta, omega);
}

size_t pendulum_exact_times(double theta0, double omega0, double L, double g, size_t n, const double *t,
                            double *theta, double *omega)
{
    PendulumExact ex;
    if (set_up(&ex, theta0, omega0, L, g) != 0) {
        refuse(n, theta, omega);
        return n;
    }
    return evaluate(&ex, n, t, theta, omega);
}
