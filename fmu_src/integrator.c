/* integrator.c: initialisation, dispatch to the methods, and helpers shared by them
 * (initial step, step-size control, energy projection, Hermite interpolation). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "integrator.h"
#include "integrator_methods.h"

/* The adaptive methods never go below this tolerance (about 45 ulp of 1): tighter
 * requests only make the step-size controller chase rounding noise. */
#define INTEG_MIN_TOL 1e-14

/* Largest adaptive step in units of 1/w0. Only binds near the equilibria, where the
 * error estimate vanishes and the step would otherwise grow without limit. */
#define INTEG_HMAX_W0 1.0

int integrator_init(Integrator *it, SolverKind kind, double w0sq, double tol,
                    double t0, double theta0, double omega0)
{
    if (it == NULL || !isfinite(w0sq) || !(w0sq > 0.0) || !isfinite(tol) || !(tol > 0.0) ||
        !isfinite(t0) || !isfinite(theta0) || !isfinite(omega0))
        return -1;
    if (kind != SOLVER_DOPRI5 && kind != SOLVER_RK4 && kind != SOLVER_RKN &&
        kind != SOLVER_SYMPLECTIC)
        return -1;

    memset(it, 0, sizeof *it);
    it->kind = kind;
    it->w0sq = w0sq;
    /* Local error test rtol = atol = tol (states have nominal value 1). The fixed-step
     * methods turn tol into their step (rk4.c, symplectic.c). The adaptive methods also
     * project onto the initial energy: without it, the energy error of the local steps
     * drifts and turns into a secular phase error (DOPRI5 at tol 1e-8 was 4e-6 off after
     * 10 periods at 75..90 deg, as scipy's RK45 is), and near the separatrix it can carry
     * a libration over the top; with it, 3e-8 (see tests/c/test_integrators.c). */
    it->rtol = tol;
    if (kind == SOLVER_DOPRI5 || kind == SOLVER_RKN)
        it->rtol = fmax(it->rtol, INTEG_MIN_TOL);
    it->atol = it->rtol;
    it->t = t0;
    it->y[0] = theta0;
    it->y[1] = omega0;
    it->hmax = INTEG_HMAX_W0 / sqrt(w0sq);
    it->err_prev = 1e-4;
    it->project_energy = (kind == SOLVER_DOPRI5 || kind == SOLVER_RKN);
    it->t_prev = t0;
    it->y_prev[0] = theta0;
    it->y_prev[1] = omega0;
    it->h_last = 0.0;
    if (it->project_energy) {
        double s = sin(0.5 * theta0);
        it->energy0 = 0.5 * omega0 * omega0 + 2.0 * w0sq * s * s;
        it->stats.rhs_evals++;
    }
    integ_rhs(it, it->y, it->f);
    it->f_prev[0] = it->f[0];
    it->f_prev[1] = it->f[1];

    switch (kind) {
    case SOLVER_DOPRI5: integ_dopri5_start(it); break;
    case SOLVER_RK4: integ_rk4_start(it); break;
    case SOLVER_RKN: integ_rkn_start(it); break;
    case SOLVER_SYMPLECTIC: integ_symplectic_start(it); break;
    }
    return (isfinite(it->h) && it->h > 0.0) ? 0 : -1;
}

static int method_step(Integrator *it)
{
    switch (it->kind) {
    case SOLVER_DOPRI5: return integ_dopri5_step(it);
    case SOLVER_RK4: return integ_rk4_step(it);
    case SOLVER_RKN: return integ_rkn_step(it);
    case SOLVER_SYMPLECTIC: return integ_symplectic_step(it);
    }
    return -1;
}

static void method_interp(const Integrator *it, double t, double y[2])
{
    switch (it->kind) {
    case SOLVER_DOPRI5: integ_dopri5_interp(it, t, y); return;
    case SOLVER_RK4: integ_rk4_interp(it, t, y); return;
    case SOLVER_RKN: integ_rkn_interp(it, t, y); return;
    case SOLVER_SYMPLECTIC: integ_symplectic_interp(it, t, y); return;
    }
}

int integrator_advance(Integrator *it, double t_out, double y_out[2])
{
    if (it == NULL || y_out == NULL || !isfinite(t_out))
        return -1;
    /* Internal steps are never shortened to land on t_out: the step sequence is the same
     * for every output grid. A bounded number of steps per call: no call can hang. */
    long budget = INTEGRATOR_MAX_STEPS_PER_ADVANCE;
    while (it->t < t_out) {
        if (budget-- == 0)
            return -2;
        if (method_step(it) != 0)
            return -1;
    }
    if (t_out == it->t) {
        y_out[0] = it->y[0];
        y_out[1] = it->y[1];
    } else if (it->h_last > 0.0 && t_out >= it->t_prev) {
        method_interp(it, t_out, y_out);
    } else {
        return -1;   /* before the last step: the contract forbids going back */
    }
    return (isfinite(y_out[0]) && isfinite(y_out[1])) ? 0 : -1;
}

/* ---- shared helpers ------------------------------------------------------------------ */

double integ_hmin(double t)
{
    return fmax(16.0 * DBL_EPSILON * fabs(t), 1e-300);
}

double integ_initial_step(Integrator *it, int order)
{
    /* HNW I, II.4: d0 = ||y0||, d1 = ||f0||, h0 = 0.01 d0/d1; one explicit Euler step
     * gives d2 = ||f1 - f0|| / h0; h1 = (0.01 / max(d1, d2))^(1/(order+1));
     * h = min(100 h0, h1). Norms weighted by sc_i = atol + rtol |y0_i|. */
    const double tscale = 1.0 / sqrt(it->w0sq);
    double d0 = 0.0, d1 = 0.0, d2 = 0.0;
    for (int i = 0; i < 2; i++) {
        double sc = it->atol + it->rtol * fabs(it->y[i]);
        d0 += (it->y[i] / sc) * (it->y[i] / sc);
        d1 += (it->f[i] / sc) * (it->f[i] / sc);
    }
    d0 = sqrt(0.5 * d0);
    d1 = sqrt(0.5 * d1);
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 * tscale : 0.01 * d0 / d1;
    h0 = fmin(h0, it->hmax);

    double y1[2], f1[2];
    y1[0] = it->y[0] + h0 * it->f[0];
    y1[1] = it->y[1] + h0 * it->f[1];
    integ_rhs(it, y1, f1);
    for (int i = 0; i < 2; i++) {
        double sc = it->atol + it->rtol * fabs(it->y[i]);
        double r = (f1[i] - it->f[i]) / sc;
        d2 += r * r;
    }
    d2 = sqrt(0.5 * d2) / h0;

    double dmax = fmax(d1, d2);
    double h1 = (dmax <= 1e-15) ? fmax(1e-6 * tscale, h0 * 1e-3)
                                : pow(0.01 / dmax, 1.0 / (order + 1));
    return fmin(fmin(100.0 * h0, h1), it->hmax);
}

double integ_control(Integrator *it, double h, double err, int q, int *accept)
{
    /* PI step-size control (Gustafsson; HNW I, IV.2 (2.43c), in the form of Hairer's
     * DOPRI5 code): h_new = h * err^-alpha * err_prev^beta / safe, alpha = 1/q - 0.75 beta,
     * factor limited to [0.2, 10]. beta = 0.08 rather than DOPRI5's default 0.04: with 0.04
     * the pendulum's libration rejected two steps per period and a rotation 13 % of its
     * steps (the controller overshoots where the step must shrink); 0.08 rejects none in
     * either case, for about the same cost at equal error. */
    const double beta = 0.08, safe = 0.9;
    const double fac_min = 0.2, fac_max = 10.0;
    const double alpha = 1.0 / q - 0.75 * beta;
    double fac11 = pow(err, alpha);
    if (err <= 1.0) {
        double fac = fac11 / pow(it->err_prev, beta) / safe;   /* = h / h_new */
        fac = fmax(1.0 / fac_max, fmin(1.0 / fac_min, fac));
        double hnew = h / fac;
        if (it->last_rejected)
            hnew = fmin(hnew, h);     /* no increase right after a rejection */
        it->err_prev = fmax(err, 1e-4);
        it->last_rejected = 0;
        *accept = 1;
        return fmin(hnew, it->hmax);
    }
    /* rejected: pure I control, never shrink by more than fac_min */
    it->last_rejected = 1;
    it->stats.rejected++;
    *accept = 0;
    return h / fmin(1.0 / fac_min, fac11 / safe);
}

void integ_accept(Integrator *it, double h, const double ynew[2], const double fnew[2])
{
    it->t_prev = it->t;
    it->y_prev[0] = it->y[0];
    it->y_prev[1] = it->y[1];
    it->f_prev[0] = it->f[0];
    it->f_prev[1] = it->f[1];
    it->t = it->t_prev + h;
    it->h_last = it->t - it->t_prev;
    it->y[0] = ynew[0];
    it->y[1] = ynew[1];
    it->f[0] = fnew[0];
    it->f[1] = fnew[1];
    it->stats.steps++;
}

void integ_hermite5(const Integrator *it, double t, double y[2])
{
    /* p(s), s = (t - t_prev)/h, matches theta, h theta', h^2 theta'' at s = 0 and 1:
     * p = p0 + s (v0 + s (a0/2 + s (c3 + s (c4 + s c5)))) with D = p1 - p0 and
     * c3 = 10D - 6v0 - 4v1 - (3a0 - a1)/2, c4 = -15D + 8v0 + 7v1 + (3a0 - 2a1)/2,
     * c5 = 6D - 3v0 - 3v1 - (a0 - a1)/2. */
    const double h = it->h_last;
    const double s = (t - it->t_prev) / h;
    const double D = it->y[0] - it->y_prev[0];
    const double v0 = h * it->y_prev[1], v1 = h * it->y[1];
    const double a0 = h * h * it->f_prev[1], a1 = h * h * it->f[1];
    const double c3 = 10.0 * D - 6.0 * v0 - 4.0 * v1 - 0.5 * (3.0 * a0 - a1);
    const double c4 = -15.0 * D + 8.0 * v0 + 7.0 * v1 + 0.5 * (3.0 * a0 - 2.0 * a1);
    const double c5 = 6.0 * D - 3.0 * v0 - 3.0 * v1 - 0.5 * (a0 - a1);
    y[0] = it->y_prev[0] + s * (v0 + s * (0.5 * a0 + s * (c3 + s * (c4 + s * c5))));
    y[1] = (v0 + s * (a0 + s * (3.0 * c3 + s * (4.0 * c4 + s * 5.0 * c5)))) / h;
}

int integ_project(Integrator *it, const double y0[2], double ynew[2], double fnew[2])
{
    /* Orthogonal projection onto the energy level (Hairer, Lubich & Wanner, Geometric
     * Numerical Integration, IV.4.1): y <- y + lambda grad H(y), grad H = (w0sq sin theta,
     * omega), lambda = (H0 - H(y)) / |grad H|^2 (Newton on the scalar lambda, converging
     * quadratically: one iteration at tight tolerances, two or three at loose ones). With
     * s = sin(theta/2), c = cos(theta/2): H = omega^2/2 + 2 w0sq s^2, sin theta = 2 s c.
     * Each (s, c) evaluation is counted in rhs_evals: it costs what a stage costs. */
    const double w0sq = it->w0sq;
    const double h_tol = 4.0 * DBL_EPSILON * (it->energy0 + w0sq);   /* |H - H0| goal */
    const double sc_th = it->atol + it->rtol * fmax(fabs(y0[0]), fabs(ynew[0]));
    const double sc_om = it->atol + it->rtol * fmax(fabs(y0[1]), fabs(ynew[1]));
    if (!it->project_energy)
        return 0;
    double th = ynew[0], om = ynew[1];
    double s = sin(0.5 * th), c = cos(0.5 * th);
    int moved = 0;
    it->stats.rhs_evals++;
    for (int iter = 0; iter < 4; iter++) {
        double r = it->energy0 - (0.5 * om * om + 2.0 * w0sq * s * s);
        if (fabs(r) <= h_tol)
            break;
        double g0 = 2.0 * w0sq * s * c, g1 = om;
        double gg = g0 * g0 + g1 * g1;
        if (!(gg > 0.0))
            return 0;
        double lam = r / gg;
        th += lam * g0;
        om += lam * g1;
        if (!(fabs(th - ynew[0]) <= sc_th && fabs(om - ynew[1]) <= sc_om))
            return 0;   /* ill-conditioned: larger than the tolerated local error */
        s = sin(0.5 * th);
        c = cos(0.5 * th);
        it->stats.rhs_evals++;
        moved = 1;
    }
    if (!moved)
        return 0;
    ynew[0] = th;
    ynew[1] = om;
    fnew[0] = om;
    fnew[1] = -w0sq * 2.0 * s * c;
    return 1;
}
