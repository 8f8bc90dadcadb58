/* integrator.c: initialisation, dispatch to the methods, and helpers shared by them
 * (initial step, step-size control, energy projection, Hermite interpolation). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "integrator.h"
#include "methods.h"

/* The adaptive methods never go below this tolerance (about 45 ulp of 1): tighter
 * requests only make the step-size controller chase rounding noise. */
#define INTEG_MIN_TOL 1e-14

/* Largest adaptive step in units of 1/w0 (DOPRI5; rkn.c sets its own). Only binds near the
 * equilibria, where the error estimate vanishes and the step would otherwise grow without
 * limit. */
#define INTEG_HMAX_W0 1.0

/* Closeness to the separatrix below which no step rule tightens further (the tolerance is
 * promised down to 1e-6, README): without a floor the steps would vanish on it. */
#define INTEG_MIN_CLOSENESS 1e-7

/* DOPRI5's local tolerance relative to the user's, scaled by the closeness too. */
#define INTEG_DOPRI5_TOL_FACTOR 0.1

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
    /* The motion's scales (documentation/math.html): m = s^2 + q^2, m1 = (|c| - |q|)(|c| + |q|) with
     * s, c = sin, cos(theta0/2), q = omega0 / (2 w0). The time scale is 1/rate, and near the
     * separatrix an energy error dH shifts the period by ~dH / (w0^2 closeness) (dK/dm ~
     * 1/(2 m1)), so the global error over a period grows like 1/closeness: the step rules of
     * the fixed-step methods and DOPRI5's local tolerance take both into account (without,
     * symplectic at tol 1e-8 was 1.7e-3 off over three revolutions at omega0 = 30 w0, and
     * 0.056 at tol 1e-6 next to the separatrix; tests/c/test_solver_tolerance.c). */
    {
        const double w0 = sqrt(w0sq), s = sin(0.5 * theta0), c = fabs(cos(0.5 * theta0));
        const double q = fabs(omega0) / (2.0 * w0);
        const double m = s * s + q * q, m1 = (c - q) * (c + q);
        it->rate = isfinite(m) ? w0 * fmax(1.0, sqrt(m)) : INFINITY;
        it->closeness = fmin(1.0, fmax(INTEG_MIN_CLOSENESS, fabs(m1) / fmax(1.0, m)));
        if (!(it->rate > 0.0) || !isfinite(it->rate))
            return -1;
    }
    it->rtol = tol;
    if (kind == SOLVER_DOPRI5)
        it->rtol = tol * it->closeness * INTEG_DOPRI5_TOL_FACTOR;
    if (kind == SOLVER_DOPRI5 || kind == SOLVER_RKN)
        it->rtol = fmax(it->rtol, INTEG_MIN_TOL);
    it->atol = it->rtol;
    it->t = t0;
    it->y[0] = theta0;
    it->y[1] = omega0;
    it->hmax = INTEG_HMAX_W0 / it->rate;
    it->err_prev = 1e-4;
    it->project_energy = (kind == SOLVER_DOPRI5 || kind == SOLVER_RKN);
    it->t_prev = t0;
    it->y_prev[0] = theta0;
    it->y_prev[1] = omega0;
    it->h_last = 0.0;
    if (it->project_energy) {
        /* the energy measured from the separatrix, G = H - 2 w0sq (integrator.h): near the
         * top both of its terms are small, so it keeps its relative accuracy where
         * H = omega^2/2 + 2 w0sq sin^2(theta/2) would lose it to cancellation */
        double c = cos(0.5 * theta0);
        it->energy0 = 0.5 * omega0 * omega0 - 2.0 * w0sq * c * c;
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

static void method_interp(const Integrator *it, double s, double y[2])
{
    switch (it->kind) {
    case SOLVER_DOPRI5: integ_dopri5_interp(it, s, y); return;
    case SOLVER_RK4: integ_rk4_interp(it, s, y); return;
    case SOLVER_RKN: integ_rkn_interp(it, s, y); return;
    case SOLVER_SYMPLECTIC: integ_symplectic_interp(it, s, y); return;
    }
}

int integrator_advance(Integrator *it, double t_out, double y_out[2])
{
    if (it == NULL || y_out == NULL || !isfinite(t_out))
        return -1;
    /* Internal steps are never shortened to land on t_out: the step sequence is the same
     * for every output grid. A bounded number of steps per call: no call can hang. */
    long budget = INTEGRATOR_MAX_STEPS_PER_ADVANCE;
    if (integrator_min_steps(it, t_out) > (double)budget)
        return -2;   /* out of reach of the budget: refused before any work */
    while (it->t < t_out) {
        if (budget-- == 0)
            return -2;
        if (method_step(it) != 0)
            return -1;
    }
    if (it->h_last > 0.0 && t_out >= it->t_prev) {
        /* the fraction of the last step, from its exact start t_prev + t_prev_lo (at
         * t_out = t, s differs from 1 by the rounding of t: the interpolant accounts for it) */
        method_interp(it, ((t_out - it->t_prev) - it->t_prev_lo) / it->h_last, y_out);
    } else if (t_out == it->t) {
        y_out[0] = it->y[0];   /* no step taken yet */
        y_out[1] = it->y[1];
    } else {
        return -1;   /* before the last step: the contract forbids going back */
    }
    return (isfinite(y_out[0]) && isfinite(y_out[1])) ? 0 : -1;
}

static int is_fixed_step(SolverKind kind)
{
    return kind == SOLVER_RK4 || kind == SOLVER_SYMPLECTIC;
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
    if (!isfinite(point) ||
        !(fabs(point - time) <= INTEGRATOR_POINT_ULPS * ulp_of(fmax(fabs(time), fabs(point)))))
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
    if (it->kind != fresh->kind || !(it->w0sq == fresh->w0sq) || !(it->rtol == fresh->rtol) ||
        !(it->rate == fresh->rate) || !(it->closeness == fresh->closeness) ||
        !(it->atol == fresh->atol) || !(it->hmax == fresh->hmax) ||
        !(it->energy0 == fresh->energy0) || it->project_energy != fresh->project_energy)
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

double integ_control(Integrator *it, double h, double err, int q, double safe, int *accept)
{
    /* PI step-size control (Gustafsson; HNW I, IV.2 (2.43c), in the form of Hairer's
     * DOPRI5 code): h_new = h * err^-alpha * err_prev^beta / safe, factor limited to
     * [0.2, 10], with beta = 0.4/q and alpha = 1/q - 0.75 beta = 0.7/q (Gustafsson's
     * recommendation; for q = 5, beta = 0.08). Why not DOPRI5's default beta = 0.04: with
     * it the pendulum's libration rejected two steps per period and a rotation 13 % of its
     * steps (the controller overshoots where the step must shrink); 0.08 rejects none in
     * either case, for about the same cost at equal error. A fixed beta would not do for
     * every order: 0.08 against alpha = 1/11 - 0.06 made the 12th-order pair shrink its
     * step after every accepted step.
     * On a smooth stretch the controller settles where err = safe^(1/(alpha - beta)) =
     * safe^(q/0.3): the margin below the rejection threshold err = 1. */
    const double fac_min = 0.2, fac_max = 10.0;
    if (err <= 1.0) {
        /* err^alpha / err_prev^beta = (err^7 / err_prev^4)^(0.1/q): one pow per step
         * (err_prev >= 1e-4; an err^7 that underflows only means the largest growth) */
        const double e2 = err * err, p2 = it->err_prev * it->err_prev;
        const double ratio = (e2 * e2 * e2 * err) / (p2 * p2);
        double fac = pow(ratio, 0.1 / q) / safe;   /* = h / h_new */
        fac = fmax(1.0 / fac_max, fmin(1.0 / fac_min, fac));
        double hnew = h / fac;
        if (it->last_rejected)
            hnew = fmin(hnew, h);     /* no increase right after a rejection */
        it->err_prev = fmax(err, 1e-4);
        it->last_rejected = 0;
        *accept = 1;
        return fmin(hnew, it->hmax);
    }
    /* rejected: pure I control (err^alpha, alpha = 0.7/q), never shrink by more than fac_min */
    it->last_rejected = 1;
    it->stats.rejected++;
    *accept = 0;
    return h / fmin(1.0 / fac_min, pow(err, 0.7 / q) / safe);
}

void integ_accept(Integrator *it, double h, const double ynew[2], const double fnew[2])
{
    /* t + t_lo + h as t + t_lo again: Knuth's TwoSum gives the rounding error of t + b
     * exactly (b = h + t_lo), which becomes the new low part */
    const double b = h + it->t_lo;
    const double sum = it->t + b;
    const double bb = sum - it->t;
    const double lo = (it->t - (sum - bb)) + (b - bb);
    it->t_prev_lo = it->t_lo;
    it->t_prev = it->t;
    it->y_prev[0] = it->y[0];
    it->y_prev[1] = it->y[1];
    it->f_prev[0] = it->f[0];
    it->f_prev[1] = it->f[1];
    it->t = sum;
    it->t_lo = lo;
    it->h_last = h;
    it->y[0] = ynew[0];
    it->y[1] = ynew[1];
    it->f[0] = fnew[0];
    it->f[1] = fnew[1];
    it->stats.steps++;
}

void integ_hermite5(const Integrator *it, double s, double y[2])
{
    /* p(s), s = (t - t_prev)/h, matches theta, h theta', h^2 theta'' at s = 0 and 1:
     * p = p0 + s (v0 + s (a0/2 + s (c3 + s (c4 + s c5)))) with D = p1 - p0 and
     * c3 = 10D - 6v0 - 4v1 - (3a0 - a1)/2, c4 = -15D + 8v0 + 7v1 + (3a0 - 2a1)/2,
     * c5 = 6D - 3v0 - 3v1 - (a0 - a1)/2. */
    const double h = it->h_last;
    const double D = it->y[0] - it->y_prev[0];
    const double v0 = h * it->y_prev[1], v1 = h * it->y[1];
    const double a0 = h * h * it->f_prev[1], a1 = h * h * it->f[1];
    const double c3 = 10.0 * D - 6.0 * v0 - 4.0 * v1 - 0.5 * (3.0 * a0 - a1);
    const double c4 = -15.0 * D + 8.0 * v0 + 7.0 * v1 + 0.5 * (3.0 * a0 - 2.0 * a1);
    const double c5 = 6.0 * D - 3.0 * v0 - 3.0 * v1 - 0.5 * (a0 - a1);
    y[0] = it->y_prev[0] + s * (v0 + s * (0.5 * a0 + s * (c3 + s * (c4 + s * c5))));
    y[1] = (v0 + s * (a0 + s * (3.0 * c3 + s * (4.0 * c4 + s * 5.0 * c5)))) / h;
}

/* sin and cos of the half angle theta/2 after theta moved by dth: a rotation by dth/2.
 * Small moves (every Newton correction at tolerances below ~1e-6) use the Taylor series of
 * sin and cos of the increment, exact in double for |dth/2| <= 1e-3 (first omitted terms
 * (dth/2)^7/5040 and (dth/2)^8/40320 < 2e-25); larger ones call sin and cos (counted). */
static void rotate_half_angle(Integrator *it, double th, double dth, double *s, double *c)
{
    const double d = 0.5 * dth;
    if (fabs(d) <= 1e-3) {
        const double d2 = d * d;
        const double sd = d * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0 * (1.0 - d2 / 42.0)));
        const double cd = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0 * (1.0 - d2 / 30.0));
        const double s0 = *s, c0 = *c;
        *s = s0 * cd + c0 * sd;
        *c = c0 * cd - s0 * sd;
    } else {
        *s = sin(0.5 * th);
        *c = cos(0.5 * th);
        it->stats.rhs_evals++;
    }
}

int integ_project(Integrator *it, const double y0[2], double ynew[2], double fnew[2],
                  double trig[2])
{
    /* Orthogonal projection onto the energy level (Hairer, Lubich & Wanner, Geometric
     * Numerical Integration, IV.4.1): y <- y + lambda grad G(y), lambda = (G0 - G(y)) /
     * |grad G|^2 (Newton on the scalar lambda, converging quadratically: one iteration at
     * tight tolerances, two or three at loose ones). G = omega^2/2 - 2 w0sq c^2 with
     * s = sin(theta/2), c = cos(theta/2), grad G = (2 w0sq s c, omega) = (w0sq sin theta,
     * omega). One sin/cos pair at the new point is counted in rhs_evals (it costs what a
     * stage costs, and gives f there); the Newton corrections rotate (s, c) without new
     * trigonometric calls where they are small (rotate_half_angle). */
    const double w0sq = it->w0sq;
    const double th_in = ynew[0], om_in = ynew[1];
    const double s_in = sin(0.5 * th_in), c_in = cos(0.5 * th_in);
    double th = th_in, om = om_in, s = s_in, c = c_in;
    int moved = 0;
    it->stats.rhs_evals++;
    if (it->project_energy) {
        const double sc_th = it->atol + it->rtol * fmax(fabs(y0[0]), fabs(th_in));
        const double sc_om = it->atol + it->rtol * fmax(fabs(y0[1]), fabs(om_in));
        for (int iter = 0; iter < 4; iter++) {
            const double kin = 0.5 * om * om, pot = 2.0 * w0sq * c * c;
            const double r = it->energy0 - (kin - pot);
            if (fabs(r) <= 4.0 * DBL_EPSILON * (kin + pot))
                break;   /* at the rounding level of G itself */
            const double g0 = 2.0 * w0sq * s * c, g1 = om;
            const double gg = g0 * g0 + g1 * g1;
            if (!(gg > 0.0)) {
                moved = -1;
                break;
            }
            const double lam = r / gg, dth = lam * g0;
            th += dth;
            om += lam * g1;
            if (!(fabs(th - th_in) <= sc_th && fabs(om - om_in) <= sc_om)) {
                moved = -1;   /* ill-conditioned (grad G ~ 0 at the saddle): the move would
                                 exceed the tolerated local error */
                break;
            }
            rotate_half_angle(it, th, dth, &s, &c);
            moved = 1;
        }
    }
    if (moved == 1) {
        ynew[0] = th;
        ynew[1] = om;
    } else {
        s = s_in;
        c = c_in;
        moved = 0;
    }
    trig[0] = 2.0 * s * c;          /* sin theta */
    trig[1] = (c - s) * (c + s);    /* cos theta */
    fnew[0] = ynew[1];
    fnew[1] = -w0sq * trig[0];
    return moved;
}

/* Binomials C(M - 1 + j, j), j = 0 .. M - 1, for M = INTEG_TAYLOR_TERMS = 8. */
_Static_assert(INTEG_TAYLOR_TERMS == 8, "HERMITE_BINOM and integ_hermite_eval assume M = 8");
static const double HERMITE_BINOM[INTEG_TAYLOR_TERMS] = {1.0, 8.0, 36.0, 120.0, 330.0, 792.0,
                                                         1716.0, 3432.0};

void integ_taylor(double w0sq, double theta, double omega, const double trig[2],
                  double a[INTEG_TAYLOR_TERMS])
{
    /* Taylor coefficients A_n = theta^(n)(t) / n! from theta'' = -w0sq sin theta: with S_n,
     * C_n those of sin theta(t) and cos theta(t),
     *   n S_n = sum_{j=1..n} j A_j C_{n-j},  n C_n = -sum_{j=1..n} j A_j S_{n-j},
     *   A_{n+2} = -w0sq S_n / ((n+1)(n+2)),
     * the recurrences of the derivatives of sin and cos of a series (automatic
     * differentiation; HNW I, I.8). */
    double S[INTEG_TAYLOR_TERMS - 2], C[INTEG_TAYLOR_TERMS - 2];
    a[0] = theta;
    a[1] = omega;
    S[0] = trig[0];
    C[0] = trig[1];
    for (int n = 0; n < INTEG_TAYLOR_TERMS - 2; n++) {
        if (n > 0) {
            double sn = 0.0, cn = 0.0;
            for (int j = 1; j <= n; j++) {
                sn += j * a[j] * C[n - j];
                cn -= j * a[j] * S[n - j];
            }
            S[n] = sn / n;
            C[n] = cn / n;
        }
        a[n + 2] = -w0sq * S[n] / ((n + 1) * (n + 2));
    }
}

void integ_hermite_setup(const double left[INTEG_TAYLOR_TERMS],
                         const double right[INTEG_TAYLOR_TERMS], double dense[][2])
{
    /* Two-point Hermite interpolation matching INTEG_TAYLOR_TERMS = M Taylor coefficients
     * at both ends of [0, 1] (degree 2M - 1):
     *   p(s) = (1 - s)^M alpha(s) + s^M beta(s - 1),
     * alpha = the first M terms of the series of left(s) / (1 - s)^M, beta those of
     * right(u) / (1 + u)^M, using 1/(1 - x)^M = sum_j C(M - 1 + j, j) x^j. Stored as
     * dense[k] = (alpha_k, beta_k). */
    for (int k = 0; k < INTEG_TAYLOR_TERMS; k++) {
        double al = 0.0, be = 0.0;
        for (int i = 0; i <= k; i++) {
            al += left[i] * HERMITE_BINOM[k - i];
            be += ((k - i) % 2 ? -right[i] : right[i]) * HERMITE_BINOM[k - i];
        }
        dense[k][0] = al;
        dense[k][1] = be;
    }
}

void integ_hermite_eval(const Integrator *it, double s, double y[2])
{
    /* p(s) and p'(s) / h from the coefficients of integ_hermite_setup (Horner, with the
     * derivative alongside) */
    const double h = it->h_last;
    const double u = s - 1.0, r = 1.0 - s;
    const int M = INTEG_TAYLOR_TERMS;
    double pa = it->dense[M - 1][0], dpa = 0.0, pb = it->dense[M - 1][1], dpb = 0.0;
    for (int k = M - 2; k >= 0; k--) {
        dpa = dpa * s + pa;
        pa = pa * s + it->dense[k][0];
        dpb = dpb * u + pb;
        pb = pb * u + it->dense[k][1];
    }
    const double r2 = r * r, r4 = r2 * r2, r7 = r4 * r2 * r, r8 = r7 * r;
    const double s2 = s * s, s4 = s2 * s2, s7 = s4 * s2 * s, s8 = s7 * s;
    y[0] = r8 * pa + s8 * pb;
    y[1] = (r8 * dpa - M * r7 * pa + s8 * dpb + M * s7 * pb) / h;
}
