/* solvers/methods.h: the per-method entry points, called by integrator.c (init,
 * dispatch) only. Not part of the FMU's API. The methods themselves build on
 * integrator_core.h, never on integrator.c.
 *
 * Each method provides
 *   start(it):        called once by integrator_init after the common fields are set
 *                     (it->f holds y' at t0, already counted); chooses it->h.
 *   step(it):         takes one accepted step from it->t, moving the old point to
 *                     t_prev/y_prev/f_prev, and refreshing it->f and it->dense.
 *                     Returns 0, or -1 on step-size underflow / non-finite values.
 *   interp(it, s, y): the solution at t_prev + s h_last, 0 <= s <= 1 (it->h_last > 0). */
#ifndef PENDULUM_INTEGRATOR_METHODS_H
#define PENDULUM_INTEGRATOR_METHODS_H

#include "integrator.h"

/* Per-method entry points. */
void integ_dopri5_start(Integrator *it);
int integ_dopri5_step(Integrator *it);
void integ_dopri5_interp(const Integrator *it, double s, double y[2]);

void integ_rk4_start(Integrator *it);
int integ_rk4_step(Integrator *it);
void integ_rk4_interp(const Integrator *it, double s, double y[2]);

void integ_rkn_start(Integrator *it);
int integ_rkn_step(Integrator *it);
void integ_rkn_interp(const Integrator *it, double s, double y[2]);

void integ_symplectic_start(Integrator *it);
int integ_symplectic_step(Integrator *it);
void integ_symplectic_interp(const Integrator *it, double s, double y[2]);

#endif
