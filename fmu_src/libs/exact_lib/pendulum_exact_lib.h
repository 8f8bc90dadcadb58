/* pendulum_exact_lib.h: the FMU's exact solution as a plain C library (no FMI), for callers
 * that need theta_exact at many points without an FMU round trip per point (the Python
 * function pendulum_fmu.exact). It sets the solution up as the FMU's initialization does,
 * pendulum_exact_init_gl from the doubles g and L with the initial state posed at t = 0 (the
 * FMU at start time 0), and evaluates with pendulum_exact_eval_many (several points in
 * lock-step, bit for bit pendulum_exact_eval), so its theta equals the FMU's theta_exact bit
 * for bit. */
#ifndef PENDULUM_EXACT_LIB_H
#define PENDULUM_EXACT_LIB_H

#include <stddef.h>

#if defined(_WIN32)
#define PENDULUM_EXACT_API __declspec(dllexport)
#else
#define PENDULUM_EXACT_API __attribute__((visibility("default")))
#endif

/* Version of this interface; a caller checks it before trusting the signature below. */
#define PENDULUM_EXACT_ABI 2
PENDULUM_EXACT_API int pendulum_exact_abi(void);

/* For each i < n: theta[i], omega[i] of the pendulum released at t = 0 from (theta0[i],
 * omega0[i]) with length L[i] and gravity g[i], at time t[i]. Each of the five inputs is an
 * array of n (its stride 1) or one value for every element (its stride 0): stride[0..4] for
 * theta0, omega0, L, g, t, so that a caller broadcasting a scalar passes it without an array.
 * The solution's constants are set up again only when an initial state or parameter differs
 * from element i - 1's, so a problem over many times costs a set-up per block of
 * PENDULUM_EXACT_BLOCK elements; elements that share their inputs with neither neighbour
 * are set up and evaluated together (pendulum_exact_once_gl_many, several at a time), the
 * same bits. Returns the number of elements whose inputs were refused (not finite, L or g
 * not > 0, g/L not finite and > 0) or whose time is not resolvable; their outputs are NaN.
 * Every pointer may alias nothing else; n == 0 does nothing. */
#define PENDULUM_EXACT_BLOCK 256
PENDULUM_EXACT_API size_t pendulum_exact_many(size_t n, const double *theta0, const double *omega0,
                                              const double *L, const double *g, const double *t,
                                              const size_t *stride, double *theta, double *omega);

/* The same for one initial state and parameters over n times: theta[i], omega[i] at t[i].
 * Returns 0, or n when the inputs are refused (all outputs NaN then); a non-finite t[i]
 * gives NaN at i and counts one, as does a t[i] too far from 0 to resolve the phase
 * (pendulum_exact_resolvable). */
PENDULUM_EXACT_API size_t pendulum_exact_times(double theta0, double omega0, double L, double g, size_t n,
                                               const double *t, double *theta, double *omega);

#endif
