/* solvers/methods.h: the per-method entry points, referenced by the solver table in
 * integrator.c (SOLVERS) only, where their contract is written. Not part of the FMU's API. The
 * methods themselves build on integrator_core.h, never on integrator.c.
 *
 * Each method provides start(it), step(it) and interp(it, s, y) (integrator.c, above SOLVERS). */
#ifndef PENDULUM_INTEGRATOR_METHODS_H
#define PENDULUM_INTEGRATOR_METHODS_H

#include "integrator.h"

/* Per-method entry points. */
void integrator_dopri5_start(Integrator *it);
int integrator_dopri5_step(Integrator *it);
void integrator_dopri5_interp(const Integrator *it, double s, double y[2]);

void integrator_rk4_start(Integrator *it);
int integrator_rk4_step(Integrator *it);
void integrator_rk4_interp(const Integrator *it, double s, double y[2]);

void integrator_rkn_start(Integrator *it);
int integrator_rkn_step(Integrator *it);
void integrator_rkn_interp(const Integrator *it, double s, double y[2]);

void integrator_symplectic_start(Integrator *it);
int integrator_symplectic_step(Integrator *it);
void integrator_symplectic_interp(const Integrator *it, double s, double y[2]);

#endif
