/* integrator_methods.h: private interface between integrator.c (init, dispatch) and the
 * per-method files. Not part of the FMU's API.
 *
 * Each method provides
 *   start(it):        called once by integrator_init after the common fields are set
 *                     (it->f holds y' at t0, already counted); chooses it->h.
 *   step(it):         takes one accepted step from it->t, moving the old point to
 *                     t_prev/y_prev/f_prev, and refreshing it->f and it->dense.
 *                     Returns 0, or -1 on step-size underflow / non-finite values.
 *   interp(it, t, y): the solution at t_prev < t < t (it->h_last > 0). */
#ifndef PENDULUM_INTEGRATOR_METHODS_H
#define PENDULUM_INTEGRATOR_METHODS_H

#include <math.h>

#include "integrator.h"

/* The right-hand side, one sin per call, counted in rhs_evals. */
static inline void integ_rhs(Integrator *it, const double y[2], double f[2])
{
    f[0] = y[1];
    f[1] = -it->w0sq * sin(y[0]);
    it->stats.rhs_evals++;
}

/* The acceleration alone (Nystrom and symplectic methods), counted the same way. */
static inline double integ_accel(Integrator *it, double theta)
{
    it->stats.rhs_evals++;
    return -it->w0sq * sin(theta);
}

/* Weighted RMS norm of a local error estimate e (Hairer, Norsett & Wanner, Solving ODEs I,
 * II.4 (4.11)): sc_i = atol + rtol max(|y0_i|, |y1_i|), err = sqrt(mean (e_i / sc_i)^2). */
static inline double integ_err_norm(const Integrator *it, const double e[2],
                                    const double y0[2], const double y1[2])
{
    double s = 0.0;
    for (int i = 0; i < 2; i++) {
        double sc = it->atol + it->rtol * fmax(fabs(y0[i]), fabs(y1[i]));
        double r = e[i] / sc;
        s += r * r;
    }
    return sqrt(0.5 * s);
}

/* integrator.c: shared helpers. */

/* Initial step for an adaptive method of order `order` (HNW I, II.4, algorithm after
 * (4.14)); uses it->f at (t, y) and costs one right-hand side. */
double integ_initial_step(Integrator *it, int order);

/* Step-size controller shared by the adaptive methods: the PI controller of HNW I, IV.2
 * (alpha = 1/q - 0.75 beta, beta = 0.08, safety 0.9, factor in [0.2, 10]),
 * q = order of the error estimate + 1. Given the error norm err of a step
 * of size h, returns the next step to try; *accept tells whether the step is accepted.
 * Updates err_prev / last_rejected / stats.rejected. */
double integ_control(Integrator *it, double h, double err, int q, int *accept);

/* Accepts a step: (t, y, f) moves to (t_prev, y_prev, f_prev), the new point becomes
 * (t + h, ynew, fnew). */
void integ_accept(Integrator *it, double h, const double ynew[2], const double fnew[2]);

/* Quintic Hermite interpolation on the last step from theta, theta' = omega and
 * theta'' = f(theta) at both ends; omega is the derivative of the same polynomial. */
void integ_hermite5(const Integrator *it, double t, double y[2]);

/* Energy projection for the adaptive methods: moves the new point ynew of an accepted step
 * along grad H back onto H = it->energy0 (Newton; at most a few iterations) and returns
 * f at the projected point in fnew (fnew must hold f(ynew) on entry). Skipped, returning
 * 0 and leaving ynew/fnew alone, where the correction would exceed the local error
 * tolerance (near the saddle (pi, 0) grad H vanishes), or if it->project_energy is 0.
 * Returns 1 if projected. */
int integ_project(Integrator *it, const double y0[2], double ynew[2], double fnew[2]);

/* The smallest step the adaptive methods may take at time t before reporting underflow. */
double integ_hmin(double t);

/* Per-method entry points. */
void integ_dopri5_start(Integrator *it);
int integ_dopri5_step(Integrator *it);
void integ_dopri5_interp(const Integrator *it, double t, double y[2]);

void integ_rk4_start(Integrator *it);
int integ_rk4_step(Integrator *it);
void integ_rk4_interp(const Integrator *it, double t, double y[2]);

void integ_rkn_start(Integrator *it);
int integ_rkn_step(Integrator *it);
void integ_rkn_interp(const Integrator *it, double t, double y[2]);

void integ_symplectic_start(Integrator *it);
int integ_symplectic_step(Integrator *it);
void integ_symplectic_interp(const Integrator *it, double t, double y[2]);

#endif
