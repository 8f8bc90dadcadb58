/* integrator_core.h: what the methods share (integrator_core.c, and the inline helpers
 * below). Not part of the FMU's API. Layering: integrator.c (init, dispatch) calls the
 * methods through methods.h; the methods call only this file's helpers; the
 * helpers call neither.
 */
#ifndef PENDULUM_INTEGRATOR_CORE_H
#define PENDULUM_INTEGRATOR_CORE_H

#include <math.h>

#include "integrator.h"

/* The right-hand side, one sin per call, counted in rhs_evals. */
static inline void integrator_rhs(Integrator *it, const double y[2], double f[2])
{
    f[0] = y[1];
    const double s = sin(y[0]);
    f[1] = -(it->w0sq * s + it->w0sq_lo * s);
    it->stats.rhs_evals++;
}

/* The acceleration alone (Nystrom and symplectic methods), counted the same way. */
static inline double integrator_accel(Integrator *it, double theta)
{
    it->stats.rhs_evals++;
    const double s = sin(theta);
    return -(it->w0sq * s + it->w0sq_lo * s);
}

/* x + d with the rounding error carried in *carry (compensated summation, Kahan 1965, with
 * Knuth's TwoSum so that |d| > |x| is fine): the fixed-step methods accumulate no rounding
 * drift over millions of steps (near the separatrix, summed plainly, an energy drift of a
 * few ulps per step is the error at tol 1e-10). */
static inline double integrator_add_compensated(double x, double d, double *carry)
{
    const double b = d + *carry;
    const double sum = x + b;
    const double bb = sum - x;
    *carry = (x - (sum - bb)) + (b - bb);
    return sum;
}

/* The larger and the smaller of two numbers that are not NaN, inline: gcc calls libm's fmax
 * and fmin (they must handle NaN), a call on the step's chain of dependent operations. */
static inline double integrator_max(double a, double b)
{
    return a > b ? a : b;
}

static inline double integrator_min(double a, double b)
{
    return a < b ? a : b;
}

/* Weighted RMS norm of a local error estimate e (Hairer, Norsett & Wanner, Solving ODEs I,
 * II.4 (4.11)): sc_i = atol_i + rtol max(|y0_i|, |y1_i|), err = sqrt(mean (e_i / sc_i)^2). */
static inline double integrator_err_norm(const Integrator *it, const double e[2],
                                    const double y0[2], const double y1[2])
{
    double s = 0.0;
    for (int i = 0; i < 2; i++) {
        double sc = it->atol[i] + it->rtol * integrator_max(fabs(y0[i]), fabs(y1[i]));   /* NaN: err is NaN too */
        double r = e[i] / sc;
        s += r * r;
    }
    return sqrt(0.5 * s);
}

/* The closeness the fixed-step rules use: below INTEGRATOR_FIXED_MIN_CLOSENESS they tighten no
 * further, since there they project onto the energy (integrator.c), and the projection, not the
 * step, holds the energy that the period amplifies. */
#define INTEGRATOR_FIXED_MIN_CLOSENESS 1e-7
static inline double integrator_step_closeness(const Integrator *it)
{
    return it->project_energy ? fmax(it->closeness, INTEGRATOR_FIXED_MIN_CLOSENESS) : it->closeness;
}

/* integrator_core.c: shared helpers. */

/* G = omega0^2/2 - 2 w0sq cos^2(theta0/2) in double-double: the high part returned, the low
 * part in *lo (to ~1e-31 of the terms). */
double integrator_energy0(double w0sq, double w0sq_lo, double theta0, double omega0, double *lo);

/* Initial step for an adaptive method of order `order` (HNW I, II.4, algorithm after
 * (4.14)); uses it->f at (t, y) and costs one right-hand side. */
double integrator_initial_step(Integrator *it, int order);

/* Step-size controller shared by the adaptive methods: the PI controller of HNW I, IV.2
 * (beta = 0.4/q, alpha = 0.7/q, factor in [0.2, 10]), q = order of the error estimate
 * + 1, safety factor `safe`. Given the error norm err of a step of size h, returns the
 * next step to try; *accept tells whether the step is accepted.
 * Updates err_prev / last_rejected / stats.rejected. */
double integrator_control(Integrator *it, double h, double err, int q, double safe, int *accept);

/* Accepts a step: (t, y, f) moves to (t_prev, y_prev, f_prev), the new point becomes
 * (t + h, ynew, fnew), the time summed with compensation (t_lo). */
void integrator_accept(Integrator *it, double h, const double ynew[2], const double fnew[2]);

/* Quintic Hermite interpolation on the last step from theta, theta' = omega and
 * theta'' = f(theta) at both ends; omega is the derivative of the same polynomial. */
void integrator_hermite5(const Integrator *it, double s, double y[2]);

/* The end point of an accepted step of the projecting methods: evaluates sin and cos of
 * theta at ynew (one pair, counted in rhs_evals) and, if it->project_energy, moves ynew
 * along the gradient of G in the dimensionless coordinates (theta, omega / w0) back onto the
 * initial energy G = energy0 + energy0_lo (Newton; at most a few iterations). The projection is skipped, leaving ynew alone, where the correction would
 * exceed the local error tolerance (near the saddle (pi, 0) grad G vanishes). On return
 * fnew = f(ynew) and trig = (sin, cos) of ynew[0], at the point returned.
 * Returns 1 if projected, 0 if not. */
int integrator_project(Integrator *it, const double y0[2], double ynew[2], double fnew[2],
                  double trig[2]);

/* Dense output from the differential equation itself: INTEGRATOR_TAYLOR_TERMS Taylor
 * coefficients at each end of a step (all of them follow from theta, omega, sin theta and
 * cos theta by recurrences, no further evaluation of sin) fix a two-point Hermite
 * polynomial of degree 2 INTEGRATOR_TAYLOR_TERMS - 1 = 15 for theta; omega is its derivative.
 * Its error is of the order of h^16 theta^(16)/16! / 4^8: below the local error of a
 * 12th-order step of the same size. */
#define INTEGRATOR_TAYLOR_TERMS 8

/* a[n] = theta^(n)(t) / n!, n < INTEGRATOR_TAYLOR_TERMS, given theta, omega and
 * trig = (sin theta, cos theta) at t. In a time unit h (the step's variable s = (t - t0)/h):
 * pass w0sq h^2 and omega h, get a[n] h^n. */
void integrator_taylor(double w0sq, double theta, double omega, const double trig[2],
                  double a[INTEGRATOR_TAYLOR_TERMS]);

/* Stores the Hermite polynomial matching the scaled Taylor coefficients `left` at the start
 * and `right` at the end of a step in dense[0 .. INTEGRATOR_TAYLOR_TERMS - 1]. */
void integrator_hermite_setup(const double left[INTEGRATOR_TAYLOR_TERMS],
                         const double right[INTEGRATOR_TAYLOR_TERMS], double dense[][2]);

/* Evaluates that polynomial (theta) and its derivative (omega) at the fraction s of the
 * last step. */
void integrator_hermite_eval(const Integrator *it, double s, double y[2]);

/* The smallest step any method may take before reporting underflow: 16 eps / rate, in the
 * motion's own time unit, whatever the start time (the time itself is the compensated sum
 * t + t_lo, which resolves steps far below ulp(t)). */
double integrator_hmin(const Integrator *it);

/* 1 if the compensated time t + t_lo lies before x (|t_lo| <= ulp(t) / 2, the rounding error
 * of the sum: the low part decides only where t == x). */
static inline int integrator_time_before(double t, double t_lo, double x)
{
    return t < x || (t == x && t_lo < 0.0);
}

#endif
