/* integrator.c: the solver table (what each method is), initialisation, the dispatch to the
 * methods (methods.h) through that table, the shared step-end rule and the check of a solver
 * state read from an FMU state. The helpers the methods share live below both, in
 * integrator_core.c. */
#include <math.h>
#include <string.h>

#include "integrator.h"
#include "integrator_core.h"
#include "methods.h"

/* Below this, g - w0sq L may be subnormal and inexact: no low part then. */
#define DBL_MIN_NORMAL_GUARD 0x1p-900

/* The adaptive methods never go below this tolerance (about 45 ulp of 1): tighter
 * requests only make the step-size controller chase rounding noise. */
#define INTEGRATOR_MIN_TOL 1e-14

/* Largest adaptive step in units of 1/w0 (DOPRI5; rkn.c sets its own). Only binds near the
 * equilibria, where the error estimate vanishes and the step would otherwise grow without
 * limit. */
#define INTEGRATOR_HMAX_W0 1.0

/* Closeness below which the fixed-step methods project onto the energy as well. */
#define INTEGRATOR_PROJECT_CLOSENESS 1e-2

/* DOPRI5's local tolerance relative to the user's, scaled by the closeness too. */
#define INTEGRATOR_DOPRI5_TOL_FACTOR 0.1

/* What a solver is: one row of SOLVERS below. */
typedef struct {
    const char *name;    /* its item in the enumeration Solver of both model descriptions, and its name
                            in log messages */
    void (*start)(Integrator *it);
    int (*step)(Integrator *it);
    void (*interp)(const Integrator *it, double s, double y[2]);
    int fixed_step;      /* 1: start sets it->h from the tolerance and every step takes it (a state's h
                            must be that one); 0: adaptive, steps in (0, hmax], the local tolerance at
                            least INTEGRATOR_MIN_TOL */
    int always_projects; /* 1: every accepted point is projected onto the initial energy; 0: only near
                            the separatrix, closeness < INTEGRATOR_PROJECT_CLOSENESS */
    double tol_closeness_factor; /* > 0: the local tolerance is tol * closeness * this factor (closer
                                    to the separatrix, tighter); 0: tol itself */
    double reach;        /* smallest tol |1 - m| / max(1, m) at which it holds 100 tol over ten
                            periods (integrator.h, measured in tests/c/test_certificate.c) */
} SolverMethod;

/* The solvers, indexed by SolverKind (the value of the item in the model descriptions).
 *
 * Adding a solver: a SOLVER_* value in integrator.h and a row here (then its item in both model
 * descriptions and the rest of CONTRIBUTING.md's "Adding a solver"). Its three functions live
 * in its own file (declared in methods.h) and keep this contract:
 *   start(it):        called once by integrator_init after the common fields are set (it->f
 *                     holds y' at t0, already counted in the statistics; it->rtol, atol, hmax
 *                     and project_energy follow from this row); sets it->h > 0, finite.
 *   step(it):         takes one accepted step from it->t (integrator_accept moves the old point
 *                     to t_prev, y_prev, f_prev), refreshing it->f and it->dense, counting every
 *                     evaluation of sin or cos in it->stats; allocates nothing. Returns 0, or -1
 *                     on step-size underflow (integrator_hmin) or values that are not finite.
 *   interp(it, s, y): the solution (theta, omega) at t_prev + s h_last, 0 <= s <= 1 (only called
 *                     with h_last > 0), from it->dense or the end points alone: the internal steps
 *                     never depend on the output times.
 * The rest of the row says what the shared code does for it (the fields above). */
static const SolverMethod SOLVERS[] = {
    [SOLVER_DOPRI5] = {.name = "dopri5", .start = integrator_dopri5_start, .step = integrator_dopri5_step,
                       .interp = integrator_dopri5_interp, .fixed_step = 0, .always_projects = 1,
                       .tol_closeness_factor = INTEGRATOR_DOPRI5_TOL_FACTOR, .reach = INTEGRATOR_REACH},
    [SOLVER_RK4] = {.name = "rk4", .start = integrator_rk4_start, .step = integrator_rk4_step,
                    .interp = integrator_rk4_interp, .fixed_step = 1, .always_projects = 0,
                    .tol_closeness_factor = 0.0, .reach = INTEGRATOR_REACH_RK4},
    [SOLVER_RKN] = {.name = "rkn", .start = integrator_rkn_start, .step = integrator_rkn_step,
                    .interp = integrator_rkn_interp, .fixed_step = 0, .always_projects = 1,
                    .tol_closeness_factor = 0.0, .reach = INTEGRATOR_REACH},
    [SOLVER_SYMPLECTIC] = {.name = "symplectic", .start = integrator_symplectic_start,
                           .step = integrator_symplectic_step, .interp = integrator_symplectic_interp,
                           .fixed_step = 1, .always_projects = 0, .tol_closeness_factor = 0.0,
                           .reach = INTEGRATOR_REACH},
};

/* The row of a kind, or NULL for a value that names no solver. */
static const SolverMethod *method_of(int kind)
{
    if (kind < 0 || kind >= (int)(sizeof SOLVERS / sizeof SOLVERS[0]) || SOLVERS[kind].name == NULL)
        return NULL;
    return &SOLVERS[kind];
}

const char *integrator_solver_name(int kind)
{
    const SolverMethod *method = method_of(kind);
    return method == NULL ? NULL : method->name;
}

static int init_common(Integrator *it, SolverKind kind, double w0sq, double w0sq_lo, double tol,
                       double t0, double theta0, double omega0)
{
    if (it == NULL || !isfinite(w0sq) || !(w0sq > 0.0) || !isfinite(tol) || !(tol > 0.0) ||
        !isfinite(t0) || !isfinite(theta0) || !isfinite(omega0))
        return -1;
    const SolverMethod *method = method_of(kind);
    if (method == NULL)
        return -1;

    memset(it, 0, sizeof *it);
    it->kind = kind;
    it->w0sq = w0sq;
    it->w0sq_lo = w0sq_lo;
    /* Local error test rtol = atol = tol (states have nominal value 1). The fixed-step
     * methods turn tol into their step (rk4.c, symplectic.c). The adaptive methods also
     * project onto the initial energy: without it, the energy error of the local steps
     * drifts and turns into a secular phase error (measured without the projection: DOPRI5
     * at tol 1e-8 ends 4e-6 off after 10 periods at 75..90 deg, as scipy's RK45 does), and
     * near the separatrix it can carry a libration over the top; with it, 3e-8 (see
     * tests/c/test_integrators.c). */
    /* The motion's scales (documentation/math.html): m = s^2 + q^2, m1 = (|c| - |q|)(|c| + |q|) with
     * s, c = sin, cos(theta0/2), q = omega0 / (2 w0). The time scale is 1/rate, and near the
     * separatrix an energy error dH shifts the period by ~dH / (w0^2 closeness) (dK/dm ~
     * 1/(2 m1)), so the global error over a period grows like 1/closeness: the step rules of
     * the fixed-step methods and DOPRI5's local tolerance take both into account (measured
     * with rules that ignore them: symplectic at tol 1e-8 ends 1.7e-3 off over three
     * revolutions at omega0 = 30 w0, and 0.056 off at tol 1e-6 next to the separatrix;
     * tests/c/test_solver_tolerance.c). The closeness has a floor, INTEGRATOR_REACH / tol:
     * below tol closeness = INTEGRATOR_REACH the accuracy the bound needs falls below rounding
     * and no double-precision solver can hold it (integrator.h), so no step rule tightens
     * further there; without the floor the steps would shrink to nothing on the separatrix. */
    {
        const double w0 = sqrt(w0sq), s = sin(0.5 * theta0), c = fabs(cos(0.5 * theta0));
        const double q = fabs(omega0) / (2.0 * w0);
        const double m = s * s + q * q, m1 = (c - q) * (c + q);
        it->rate = isfinite(m) ? w0 * fmax(1.0, sqrt(m)) : INFINITY;
        it->closeness = fmin(1.0, fmax(INTEGRATOR_REACH / tol, fabs(m1) / fmax(1.0, m)));
        if (!(it->rate > 0.0) || !isfinite(it->rate))
            return -1;
    }
    it->rtol = tol;
    if (method->tol_closeness_factor > 0.0)
        it->rtol = tol * it->closeness * method->tol_closeness_factor;
    if (!method->fixed_step)
        it->rtol = fmax(it->rtol, INTEGRATOR_MIN_TOL);
    it->atol[0] = it->rtol;
    it->atol[1] = it->rtol * sqrt(w0sq);
    it->t = t0;
    it->y[0] = theta0;
    it->y[1] = omega0;
    it->hmax = INTEGRATOR_HMAX_W0 / it->rate;
    it->err_prev = 1e-4;
    /* the fixed-step methods project too near the separatrix: there the energy error of their
     * steps, not their phase error, is what the period amplifies (without the projection, rk4
     * and symplectic end 1e3 to 1e4 times their bound at 1 - m = 2e-12; docs/certificate.md) */
    it->project_energy = (method->always_projects || it->closeness < INTEGRATOR_PROJECT_CLOSENESS);
    it->t_prev = t0;
    it->y_prev[0] = theta0;
    it->y_prev[1] = omega0;
    it->h_last = 0.0;
    if (it->project_energy) {
        /* the energy measured from the separatrix, G = H - 2 w0sq (integrator.h): near the
         * top both of its terms are small, so it keeps its relative accuracy where
         * H = omega^2/2 + 2 w0sq sin^2(theta/2) would lose it to cancellation */
        it->energy0 = integrator_energy0(w0sq, w0sq_lo, theta0, omega0, &it->energy0_lo);
        it->stats.rhs_evals++;
        if (!isfinite(it->energy0))
            return -1;
    }
    integrator_rhs(it, it->y, it->f);
    it->f_prev[0] = it->f[0];
    it->f_prev[1] = it->f[1];

    method->start(it);
    return (isfinite(it->h) && it->h > 0.0) ? 0 : -1;
}

int integrator_init(Integrator *it, SolverKind kind, double w0sq, double tol,
                    double t0, double theta0, double omega0)
{
    return init_common(it, kind, w0sq, 0.0, tol, t0, theta0, omega0);
}

int integrator_init_gl(Integrator *it, SolverKind kind, double g, double L, double tol,
                       double t0, double theta0, double omega0)
{
    const double w0sq = g / L;
    if (!(g > 0.0) || !(L > 0.0) || !isfinite(w0sq) || !(w0sq > DBL_MIN_NORMAL_GUARD))
        return init_common(it, kind, w0sq, 0.0, tol, t0, theta0, omega0);
    /* g / L = w0sq + lo: the residual g - w0sq L is exact (fma), lo = residual / L */
    const double lo = fma(-w0sq, L, g) / L;
    return init_common(it, kind, w0sq, isfinite(lo) ? lo : 0.0, tol, t0, theta0, omega0);
}

double integrator_reach(SolverKind kind)
{
    const SolverMethod *method = method_of(kind);
    return method == NULL ? INTEGRATOR_REACH : method->reach;
}

int integrator_advance(Integrator *it, double t_out, double y_out[2])
{
    if (it == NULL || y_out == NULL || !isfinite(t_out))
        return -1;
    const SolverMethod *method = method_of(it->kind);
    if (method == NULL)
        return -1;
    /* Internal steps are never shortened to land on t_out: the step sequence is the same
     * for every output grid. A bounded number of steps per call: no call can hang. */
    long budget = INTEGRATOR_MAX_STEPS_PER_ADVANCE;
    if (integrator_min_steps(it, t_out) > (double)budget)
        return -2;   /* out of reach of the budget: refused before any work */
    /* the internal time is the compensated sum t + t_lo: compared as such, the same steps
     * reach t_out whatever the start time (with t alone, a step landing within ulp(t) of
     * t_out counted as done or not by the rounding of the clock) */
    while (integrator_time_before(it->t, it->t_lo, t_out)) {
        if (budget-- == 0)
            return -2;
        if (method->step(it) != 0)
            return -1;
    }
    if (it->h_last > 0.0 && t_out >= it->t_prev) {
        /* the fraction of the last step, from its exact start t_prev + t_prev_lo (at
         * t_out = t, s differs from 1 by the rounding of t: the interpolant accounts for it) */
        method->interp(it, ((t_out - it->t_prev) - it->t_prev_lo) / it->h_last, y_out);
    } else if (t_out == it->t) {
        y_out[0] = it->y[0];   /* no step taken yet */
        y_out[1] = it->y[1];
    } else {
        return -1;   /* before the last step: the contract forbids going back */
    }
    return (isfinite(y_out[0]) && isfinite(y_out[1])) ? 0 : -1;
}

/* 1 for a fixed-step method (an unknown kind counts as adaptive). */
static int is_fixed_step(SolverKind kind)
{
    const SolverMethod *method = method_of(kind);
    return method != NULL && method->fixed_step;
}

double integrator_min_steps(const Integrator *it, double t_out)
{
    if (!(t_out > it->t))
        return 0.0;
    const double largest = is_fixed_step(it->kind) ? it->h : fmax(it->h, it->hmax);
    return (t_out - it->t) / largest;
}

static double ulp_of(double x)
{
    x = fabs(x);
    return nextafter(x, INFINITY) - x;
}

StepEnd integrator_step_end(double time, double point, double step, double *t_end)
{
    if (!(isfinite(step) && step > 0.0))
        return STEP_END_BAD_SIZE;
    /* point == time, the usual case, needs no ulp (nextafter is a library call) */
    if (!isfinite(point) ||
        (point != time && !(fabs(point - time) <= INTEGRATOR_POINT_ULPS * ulp_of(fmax(fabs(time), fabs(point))))))
        return STEP_END_BAD_POINT;
    const double end = point + step;
    if (!isfinite(end))
        return STEP_END_NOT_FINITE;
    if (end < time)
        return STEP_END_BACKWARDS;
    *t_end = end;
    return STEP_END_OK;
}

static int all_finite(const double *values, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(values[i]))
            return 0;
    return 1;
}

const char *integrator_check(const Integrator *it, const Integrator *fresh)
{
    if (it->kind != fresh->kind || !(it->w0sq == fresh->w0sq) || !(it->w0sq_lo == fresh->w0sq_lo) || !(it->rtol == fresh->rtol) ||
        !(it->rate == fresh->rate) || !(it->closeness == fresh->closeness) ||
        !(it->atol[0] == fresh->atol[0]) || !(it->atol[1] == fresh->atol[1]) || !(it->hmax == fresh->hmax) ||
        !(it->energy0 == fresh->energy0) || !(it->energy0_lo == fresh->energy0_lo) || it->project_energy != fresh->project_energy)
        return "solver settings differ from those of the state's own start values";
    if (is_fixed_step(it->kind) ? !(it->h == fresh->h) : !(it->h > 0.0 && it->h <= it->hmax))
        return "solver step size out of range";
    const double times[] = {it->t, it->t_lo, it->t_prev, it->t_prev_lo, it->h_last, it->err_prev};
    if (!all_finite(times, 6) || !all_finite(it->y, 2) || !all_finite(it->f, 2) ||
        !all_finite(it->y_prev, 2) || !all_finite(it->f_prev, 2) ||
        !all_finite(&it->dense[0][0], 2 * INTEGRATOR_MAX_STAGES))
        return "solver state holds a value that is not finite";
    if (!(fabs(it->t_lo) <= ulp_of(it->t)) || !(fabs(it->t_prev_lo) <= ulp_of(it->t_prev)))
        return "solver time out of range (low part)";
    if (!(it->t_prev >= fresh->t) || !(it->t >= it->t_prev) || !(it->h_last >= 0.0))
        return "solver times out of order";
    if (it->h_last == 0.0 ? (it->t != fresh->t || it->stats.steps != 0)
                          : !(fabs((it->t - it->t_prev) + (it->t_lo - it->t_prev_lo) - it->h_last)
                              <= 4.0 * ulp_of(it->t)))
        return "solver times and last step do not match";
    if (!(it->err_prev >= 1e-4 && it->err_prev <= 1.0) || (it->last_rejected != 0 && it->last_rejected != 1))
        return "solver step-size controller state out of range";
    if (it->f[0] != it->y[1] || it->f_prev[0] != it->y_prev[1])
        return "solver slopes do not match its states";
    if (it->stats.steps < 0 || it->stats.rejected < 0 || it->stats.rhs_evals < 0)
        return "solver statistics out of range";
    return NULL;
}
