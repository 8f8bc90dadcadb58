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

/* 1 when element i has element j's inputs (bitwise). */
static int same_inputs(const double *theta0, const double *omega0, const double *L, const double *g, size_t i,
                       size_t j)
{
    return same_bits(theta0[i], theta0[j]) && same_bits(omega0[i], omega0[j]) && same_bits(L[i], L[j])
           && same_bits(g[i], g[j]);
}

/* pendulum_exact_many on contiguous arrays of n elements */
static size_t many_contiguous(size_t n, const double *theta0, const double *omega0, const double *L, const double *g,
                              const double *t, double *theta, double *omega)
{
    size_t refused = 0;
    size_t start = 0;
    while (start < n) {
        /* a run of elements with the same inputs shares one set-up */
        size_t end = start + 1;
        while (end < n && same_inputs(theta0, omega0, L, g, end, start)) {
            ++end;
        }
        if (end - start > 1) {
            PendulumExact ex;
            if (set_up(&ex, theta0[start], omega0[start], L[start], g[start]) == 0) {
                refused += evaluate(&ex, end - start, t + start, theta + start, omega + start);
            } else {
                refuse(end - start, theta + start, omega + start);
                refused += end - start;
            }
            start = end;
            continue;
        }
        /* a stretch of elements each with inputs of its own (a state per point): set up and
         * evaluated together, several at once (pendulum_exact_once_gl_many, the same bits) */
        while (end < n && !(end + 1 < n && same_inputs(theta0, omega0, L, g, end + 1, end))) {
            ++end;
        }
        refused += pendulum_exact_once_gl_many(end - start, theta0 + start, omega0 + start, g + start, L + start, 0.0,
                                               t + start, theta + start, omega + start);
        start = end;
    }
    return refused;
}

size_t pendulum_exact_many(size_t n, const double *theta0, const double *omega0, const double *L,
                           const double *g, const double *t, const size_t *stride, double *theta, double *omega)
{
    const double *const input[5] = {theta0, omega0, L, g, t};
    /* blocks of the inputs, contiguous: an array read where it is, a stride-0 input repeated
     * once into a block of its own */
    double repeated[5][PENDULUM_EXACT_BLOCK];
    for (int k = 0; k < 5; ++k) {
        for (size_t i = 0; stride[k] == 0 && i < PENDULUM_EXACT_BLOCK && i < n; ++i) {
            repeated[k][i] = input[k][0];
        }
    }
    size_t refused = 0;
    for (size_t first = 0; first < n; first += PENDULUM_EXACT_BLOCK) {
        const size_t count = n - first < PENDULUM_EXACT_BLOCK ? n - first : PENDULUM_EXACT_BLOCK;
        const double *block[5];
        for (int k = 0; k < 5; ++k) {
            block[k] = stride[k] ? input[k] + first : repeated[k];
        }
        refused += many_contiguous(count, block[0], block[1], block[2], block[3], block[4], theta + first,
                                   omega + first);
    }
    return refused;
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
