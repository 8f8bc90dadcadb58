/* symplectic.c: 8th-order symmetric composition of Stormer-Verlet, 15 stages, with a
 * fixed step derived from the tolerance.
 *
 * Method: Psi_h = V(g15 h) o ... o V(g2 h) o V(g1 h), V the velocity-Verlet step
 * (kick h/2, drift h, kick h/2), g palindromic (g_{16-i} = g_i) with
 * g8 = 1 - 2 (g1 + ... + g7). Coefficients: M. Suzuki, K. Umeno, "Higher-order
 * decomposition theory of exponential operators and its applications to QMC and nonlinear
 * dynamics" (1993), and R. I. McLachlan, SIAM J. Sci. Comput. 16 (1995) 151-168; method
 * "p8 s15" in Hairer, Lubich & Wanner, Geometric Numerical Integration (2nd ed.), V.3.2.
 * Observed local order 9 (global order 8) checked with mpmath and in
 * tests/c/test_integrators.c. Each Verlet stage needs the force at its new position; the
 * force at the end of a step is the first kick of the next, so a step costs 15 sin
 * (and one cos for the interpolation, below).
 *
 * Step rule (constant for the whole run): on y'' = -w0^2 y the method is an exact
 * rotation by an angle phi = h w0 + C (h w0)^9 + ..., C = 4.75e-6 (computed from the
 * coefficients at 50 digits). Asking the phase error per unit of w0 t to be tol,
 * C (h w0)^8 = tol, gives the same "local error per unit time ~ tol" rule as rk4.c;
 * a safety factor 0.8 covers the larger error of big amplitudes (whose motion has
 * higher harmonics: at 80 deg the error is ~6x the harmonic estimate, and 0.8^8 = 0.17):
 *     h = 0.8 (tol / C)^(1/8) / w0,   capped at 1 / w0 (tol > ~2e-6).
 * The motion's own scales refine it (integrator.c): w0 becomes the rate r (sqrt(m) w0 in
 * rotation), tol is scaled by the closeness c to the separatrix and by SYMP_TOL_FACTOR, the
 * measured margin for the global error over ten periods (the interpolant's included):
 *     h = min(0.8 (1e-3 tol c / C)^(1/8), 1) / r.
 * Near the separatrix (c < 1e-2) every step is projected onto the initial energy
 * (integrator.c; the composition is then no longer symplectic there, but its energy is held
 * to rounding), and c stops tightening the step at 1e-7 (integrator_step_closeness).
 *
 * Output: Hermite interpolation of degree 7 for theta from theta, theta' = omega,
 * theta'' = -w0^2 sin(theta) and theta''' = -w0^2 cos(theta) omega at both ends of the
 * step; omega is its derivative. Its error, O(h^8) in theta and O(h^7) in omega, matches
 * the method's order (a quintic Hermite, O(h^5) in omega, is 300x less accurate than the
 * step points at tol 1e-9). theta''' costs one cos per step, counted in rhs_evals with the
 * sines (a step counts 16). The internal steps never land on the output times, so the
 * symplectic map is applied with the same h throughout and the energy error stays
 * bounded; the output at a given time is independent of the grid. */
#include <math.h>

#include "integrator.h"
#include "integrator_core.h"
#include "methods.h"

#define SYMP_STAGES 15
#define SYMP_PHASE_C 4.75e-6
#define SYMP_SAFETY 0.8
#define SYMP_HMAX_W0 1.0
#define SYMP_TOL_FACTOR 0.001   /* the global error over ten periods, measured (test_solver_tolerance.c) */

/* g1..g7 to 26 digits as published; g8 = 1 - 2 (g1 + ... + g7). */
static const double G[SYMP_STAGES] = {
    0.74167036435061295344822780, -0.40910082580003159399730010,
    0.19075471029623837995387626, -0.57386247111608226665638773,
    0.29906418130365592384446354, 0.33462491824529818378495798,
    0.31529309239676659663205666, -0.79688793935291635401978884,
    0.31529309239676659663205666, 0.33462491824529818378495798,
    0.29906418130365592384446354, -0.57386247111608226665638773,
    0.19075471029623837995387626, -0.40910082580003159399730010,
    0.74167036435061295344822780};

/* third derivative d/dt (-w0^2 sin theta) = -w0^2 cos(theta) omega; counted like a sin */
static double jerk(Integrator *it, double theta, double omega)
{
    it->stats.rhs_evals++;
    return -it->w0sq * cos(theta) * omega;
}

void integrator_symplectic_start(Integrator *it)
{
    /* rate and closeness: integrator.c (the motion's time scale, the separatrix's sensitivity) */
    it->h = fmin(SYMP_SAFETY * pow(it->rtol * integrator_step_closeness(it) * SYMP_TOL_FACTOR / SYMP_PHASE_C, 0.125),
                 SYMP_HMAX_W0) / it->rate;
    it->dense[0][1] = jerk(it, it->y[0], it->y[1]);
}

int integrator_symplectic_step(Integrator *it)
{
    const double h = it->h;
    double x = it->y[0], v = it->y[1];
    double a = it->f[1];   /* force at x, from the end of the previous step */

    if (!(h >= integrator_hmin(it)))
        return -1;   /* below the smallest step (integrator_hmin): measured in the motion's time, not
                        against the clock t (the compensated sum t + t_lo resolves the step) */
    /* compensated sums: dense[1] (unused by the output) carries the rounding of x and v */
    double *carry = it->dense[1];
    for (int i = 0; i < SYMP_STAGES; i++) {
        const double hi = G[i] * h;
        v = integrator_add_compensated(v, 0.5 * hi * a, &carry[1]);   /* kick */
        x = integrator_add_compensated(x, hi * v, &carry[0]);         /* drift */
        a = integrator_accel(it, x);
        v = integrator_add_compensated(v, 0.5 * hi * a, &carry[1]);   /* kick */
    }
    if (!isfinite(x) || !isfinite(v))
        return -1;
    double y1[2] = {x, v}, f1[2] = {v, a};
    if (it->project_energy) {
        /* near the separatrix: back onto the initial energy (integrator.c), f with it; the
         * rounding carried so far belongs to the point before the move */
        double trig[2];
        if (integrator_project(it, it->y, y1, f1, trig) == 1) {
            carry[0] = carry[1] = 0.0;
        }
    }
    it->dense[0][0] = it->dense[0][1];   /* third derivative at the start / end of the step */
    it->dense[0][1] = jerk(it, x, v);
    integrator_accept(it, h, y1, f1);
    return 0;
}

void integrator_symplectic_interp(const Integrator *it, double s, double y[2])
{
    /* p(s) = p0 + v0 s + a0 s^2/2 + j0 s^3/6 + c4 s^4 + c5 s^5 + c6 s^6 + c7 s^7 on
     * s = (t - t_prev)/h, with v, a, j the 1st, 2nd, 3rd derivatives times h, h^2, h^3,
     * c4..c7 from p(1) = p1, p'(1) = v1, p''(1) = a1, p'''(1) = j1. With the residuals
     * R0 = p1 - (p0 + v0 + a0/2 + j0/6), R1 = v1 - (v0 + a0 + j0/2), R2 = a1 - (a0 + j0),
     * R3 = j1 - j0, the inverse of that 4x4 system (exact rationals) gives
     *   c4 =  35 R0 - 15 R1 + 5/2 R2 - 1/6 R3,   c5 = -84 R0 + 39 R1 - 7 R2 + 1/2 R3,
     *   c6 =  70 R0 - 34 R1 + 13/2 R2 - 1/2 R3,  c7 = -20 R0 + 10 R1 - 2 R2 + 1/6 R3. */
    const double h = it->h_last;
    const double p0 = it->y_prev[0], p1 = it->y[0];
    const double v0 = h * it->y_prev[1], v1 = h * it->y[1];
    const double a0 = h * h * it->f_prev[1], a1 = h * h * it->f[1];
    const double j0 = h * h * h * it->dense[0][0], j1 = h * h * h * it->dense[0][1];
    const double R0 = (p1 - p0) - (v0 + 0.5 * a0 + j0 / 6.0);
    const double R1 = v1 - (v0 + a0 + 0.5 * j0);
    const double R2 = a1 - (a0 + j0);
    const double R3 = j1 - j0;
    const double c4 = 35.0 * R0 - 15.0 * R1 + 2.5 * R2 - R3 / 6.0;
    const double c5 = -84.0 * R0 + 39.0 * R1 - 7.0 * R2 + 0.5 * R3;
    const double c6 = 70.0 * R0 - 34.0 * R1 + 6.5 * R2 - 0.5 * R3;
    const double c7 = -20.0 * R0 + 10.0 * R1 - 2.0 * R2 + R3 / 6.0;
    y[0] = p0 + s * (v0 + s * (0.5 * a0 + s * (j0 / 6.0 +
                                                 s * (c4 + s * (c5 + s * (c6 + s * c7))))));
    y[1] = (v0 + s * (a0 + s * (0.5 * j0 +
                                s * (4.0 * c4 + s * (5.0 * c5 + s * (6.0 * c6 +
                                                                     s * 7.0 * c7)))))) / h;
}
