/* rk4.c: the classical 4th-order Runge-Kutta method (Kutta 1901; HNW I, Table II.1.2)
 * with a fixed step derived from the tolerance.
 *
 * Step rule (constant for the whole run): on the linearised pendulum y'' = -w0^2 y the
 * RK4 amplification factor is R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 with z = i h w0,
 * whose leading local error is |R(z) - e^z| ~ (h w0)^5 / 120 per step. Asking this to
 * be tol per unit of w0 t (local error per unit time ~ tol, so the global error grows
 * like tol * w0 t) gives
 *     h = (120 tol)^(1/4) / w0,   capped at 0.5 / w0.
 * The motion's own scales refine it (integrator.c): w0 becomes the rate r (sqrt(m) w0 in
 * rotation), tol is scaled by the closeness c to the separatrix and by RK4_TOL_FACTOR, the
 * measured margin for the global error over ten periods (tests/c/test_solver_tolerance.c):
 *     h = min((30 tol c)^(1/4), 0.5) / r.
 * At tol = 1e-8 and small amplitudes this is h w0 = 0.023 (about 270 steps a period).
 * Near the separatrix (c < 1e-2) every step is projected onto the initial energy
 * (integrator.c), and c stops tightening the step at 1e-7 (integrator_step_closeness): below, the
 * projection holds the energy, and smaller steps only added rounding.
 *
 * Output: the internal steps never land on the output times; values in between come
 * from quintic Hermite interpolation of theta using theta, theta' = omega and
 * theta'' = -w0^2 sin(theta) at both ends of the step (all known: the slope at the end
 * is the next step's first stage), omega being the derivative of that polynomial. Its
 * error, O(h^6) in theta and O(h^5) in omega, is below RK4's O(h^4) global error, and
 * the step sequence, hence the output at any given time, is independent of the grid. */
#include <math.h>

#include "integrator.h"
#include "integrator_core.h"
#include "methods.h"

/* tol per unit of rate t, scaled for the global error over ten periods */
#define RK4_TOL_FACTOR 0.25

void integrator_rk4_start(Integrator *it)
{
    /* rate and closeness: integrator.c (the motion's time scale, the separatrix's sensitivity) */
    it->h = fmin(pow(120.0 * it->rtol * integrator_step_closeness(it) * RK4_TOL_FACTOR, 0.25), 0.5) / it->rate;
}

int integrator_rk4_step(Integrator *it)
{
    const double h = it->h;
    const double *y = it->y;
    const double *k1 = it->f;   /* f at (t, y), computed as the end slope of the last step */
    double k2[2], k3[2], k4[2], ys[2], ynew[2], fnew[2];

    if (!(h >= integrator_hmin(it)))
        return -1;   /* below the smallest step (integrator_hmin): measured in the motion's time, not
                        against the clock t (the compensated sum t + t_lo resolves the step) */
    for (int i = 0; i < 2; i++)
        ys[i] = y[i] + 0.5 * h * k1[i];
    integrator_rhs(it, ys, k2);
    for (int i = 0; i < 2; i++)
        ys[i] = y[i] + 0.5 * h * k2[i];
    integrator_rhs(it, ys, k3);
    for (int i = 0; i < 2; i++)
        ys[i] = y[i] + h * k3[i];
    integrator_rhs(it, ys, k4);
    /* compensated: dense[0] (unused by the quintic Hermite output) carries the rounding */
    for (int i = 0; i < 2; i++)
        ynew[i] = integrator_add_compensated(y[i], h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]),
                                        &it->dense[0][i]);
    if (!isfinite(ynew[0]) || !isfinite(ynew[1]))
        return -1;
    if (it->project_energy) {
        /* near the separatrix: back onto the initial energy (integrator.c); f comes with it,
         * and the rounding carried so far belongs to the point before the move */
        double trig[2];
        if (integrator_project(it, y, ynew, fnew, trig) == 1) {
            it->dense[0][0] = it->dense[0][1] = 0.0;
        }
    } else {
        integrator_rhs(it, ynew, fnew);   /* next step's k1 and the interpolation's end slope */
    }
    integrator_accept(it, h, ynew, fnew);
    return 0;
}

void integrator_rk4_interp(const Integrator *it, double s, double y[2])
{
    integrator_hermite5(it, s, y);
}
