/* test_integrators.c: checks of the time integrators (fmu_src/solvers/integrator.h) against the
 * exact solution of theta'' + w0^2 sin(theta) = 0 released at rest.
 *
 * The reference is computed here, independently of fmu_src/math/exact.c (so that the two
 * cross-check each other instead of sharing a bug): theta(t) = 2 atan2(k cn(w0 t | m), k'),
 * omega(t) = -2 k k' w0 sn/dn, k = sin(theta0/2), k' = cos(theta0/2), m = k^2
 * (documentation/math.html), with K from the AGM and sn, cn, dn by the descending Landen scheme
 * (Abramowitz & Stegun 16.4). The reference itself is checked against values computed
 * once with mpmath at 30 digits.
 *
 * Some checks set fields of the Integrator (plain data) after integrator_init, to run
 * the adaptive tableaus at a constant step; they are marked "white box". */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "integrator.h"

static const double W0SQ = 9.81;   /* g = 9.81, L = 1: the FMU's defaults */

/* ---- reference solution -------------------------------------------------------------- */

/* K(m) = pi / (2 AGM(1, k')) */
static double ref_K(double kp)
{
    double a = 1.0, b = kp;
    for (int i = 0; i < 40 && fabs(a - b) > 4.0 * DBL_EPSILON * a; i++) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
    }
    return PI / (a + b);
}

/* sn, cn, dn(u | m) by the descending Landen transformation, A&S 16.4.
 * a0 = 1, b0 = k', c0 = k; phi_N = 2^N a_N u; phi_{n-1} = (phi_n + asin(c_n/a_n sin phi_n))/2;
 * sn = sin phi_0, cn = cos phi_0, and dn = sqrt(k'^2 + k^2 cn^2) (A&S 16.9.1), which stays
 * accurate at u = K where cos phi_0 / cos(phi_1 - phi_0) is 0/0. */
static void ref_jacobi(double u, double k, double kp, double *sn, double *cn, double *dn)
{
    double a[32], c[32], b = kp;
    int n = 0;
    a[0] = 1.0;
    c[0] = k;
    while (fabs(c[n]) > DBL_EPSILON * a[n] && n < 30) {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = sqrt(a[n] * b);
        n++;
    }
    double phi = ldexp(a[n] * u, n);
    for (int j = n; j > 0; j--)
        phi = 0.5 * (phi + asin(c[j] / a[j] * sin(phi)));
    *sn = sin(phi);
    *cn = cos(phi);
    *dn = sqrt(kp * kp + k * k * *cn * *cn);
}

/* exact (theta, omega) at t for release at rest from theta0 (|theta0| < pi) */
static void ref_solution(double theta0, double t, double y[2])
{
    const double w0 = sqrt(W0SQ);
    const double k = sin(0.5 * theta0), kp = cos(0.5 * theta0);
    const double K4 = 4.0 * ref_K(kp);
    double u = fmod(w0 * t, K4);   /* sn, cn, dn have period 4K */
    double sn, cn, dn;
    ref_jacobi(u, k, kp, &sn, &cn, &dn);
    y[0] = 2.0 * atan2(k * cn, kp);
    y[1] = -2.0 * k * kp * sqrt(W0SQ) * sn / dn;
}

static double ref_period(double theta0)
{
    return 4.0 * ref_K(cos(0.5 * theta0)) / sqrt(W0SQ);
}

static double deg(double d)
{
    return d * PI / 180.0;
}

static void test_reference(void)
{
    /* mpmath 1.3, mp.dps = 30, w0 = sqrt(9.81):
     * theta = 2 atan2(k ellipfun('cn', w0 t, m), k'), omega = -2 k k' w0 sn/dn,
     * T = 4 ellipk(m)/w0 */
    static const struct { double deg, t, theta, omega, T; } tab[] = {
        {80.0, 1.234, -1.3544871286871186213, 0.89665532662187961874, 2.281885924019639633},
        {80.0, 17.5, -0.70366295990913275056, 3.3989450911259859974, 2.281885924019639633},
        {45.0, 3.3, -0.68615514151138438225, 1.1429425620502695501, 2.086255872614367302},
        {85.0, 0.58, 0.002977209795655551374, -4.2320110318489663767, 2.3228139860270629049},
    };
    for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++) {
        double y[2];
        ref_solution(deg(tab[i].deg), tab[i].t, y);
        check(fabs(y[0] - tab[i].theta) < 1e-13 && fabs(y[1] - tab[i].omega) < 1e-12,
              "reference at %g deg, t = %g: (%.17g, %.17g)", tab[i].deg, tab[i].t, y[0], y[1]);
        check(fabs(ref_period(deg(tab[i].deg)) - tab[i].T) < 1e-14, "reference period");
    }
    check(fabs(ref_period(deg(179.99)) - 13.706926711838978701) < 1e-11,
          "reference period at 179.99 deg: %.17g", ref_period(deg(179.99)));
}

/* ---- helpers ------------------------------------------------------------------------- */

/* max |theta error| at n_out equally spaced outputs over `periods` periods */
static double max_theta_error(SolverKind kind, double tol, double theta0, double periods,
                              int n_out, long *evals)
{
    const double t_end = periods * ref_period(theta0);
    Integrator it;
    if (integrator_init(&it, kind, W0SQ, tol, 0.0, theta0, 0.0) != 0)
        return INFINITY;
    double err = 0.0;
    for (int i = 1; i <= n_out; i++) {
        double t = t_end * i / n_out, y[2], r[2];
        if (integrator_advance(&it, t, y) != 0)
            return INFINITY;
        ref_solution(theta0, t, r);
        err = fmax(err, fabs(y[0] - r[0]));
    }
    if (evals)
        *evals = it.stats.rhs_evals;
    return err;
}

/* Max error over the step points of `periods` periods at 80 deg, in N equal steps with
 * h w0 ~ hw0 (the max along the orbit: the error at one time can cancel by chance).
 * White box: fixed-step methods take it->h as their step; for the adaptive ones the error
 * test is switched off (rtol = atol huge) and hmax = h pins the step; project = 0 also
 * switches off the energy projection, leaving the bare Runge-Kutta(-Nystrom) tableau. */
static double fixed_step_error(SolverKind kind, double hw0, double periods, int project)
{
    const double theta0 = deg(80.0), t_end = periods * ref_period(theta0);
    const double n = ceil(t_end * sqrt(W0SQ) / hw0), h = t_end / n;
    Integrator it;
    integrator_init(&it, kind, W0SQ, 1e-6, 0.0, theta0, 0.0);
    it.h = h;
    if (kind == SOLVER_DOPRI5 || kind == SOLVER_RKN) {
        it.rtol = it.atol[0] = it.atol[1] = 1e200;
        it.hmax = h;
        it.project_energy = project;
    }
    double err = 0.0, y[2], r[2];
    while (it.stats.steps < (long)n) {
        if (integrator_advance(&it, it.t + 0.5 * h, y) != 0)   /* exactly one step */
            return INFINITY;
        ref_solution(theta0, it.t, r);
        err = fmax(err, fmax(fabs(it.y[0] - r[0]), fabs(it.y[1] - r[1]) / sqrt(W0SQ)));
    }
    return err;
}

/* ---- tests --------------------------------------------------------------------------- */

static void test_invalid_input(void)
{
    Integrator it;
    double y[2];
    check(integrator_init(&it, SOLVER_DOPRI5, 0.0, 1e-6, 0.0, 1.0, 0.0) == -1, "w0sq = 0");
    check(integrator_init(&it, SOLVER_DOPRI5, W0SQ, 0.0, 0.0, 1.0, 0.0) == -1, "tol = 0");
    check(integrator_init(&it, SOLVER_RK4, W0SQ, 1e-6, 0.0, NAN, 0.0) == -1, "theta0 NaN");
    check(integrator_init(&it, SOLVER_RKN, W0SQ, 1e-6, 0.0, 1.0, INFINITY) == -1,
          "omega0 inf");
    check(integrator_init(&it, (SolverKind)7, W0SQ, 1e-6, 0.0, 1.0, 0.0) == -1, "bad kind");
    /* the solver table: a name for each item of the enumeration Solver (the model descriptions'
     * names, in the certificate's messages), none for the values around them */
    static const char *const names[] = {NULL, "dopri5", "rk4", "rkn", "symplectic", NULL};
    for (int kind = -1; kind <= SOLVER_SYMPLECTIC + 1; kind++) {
        const char *name = integrator_solver_name(kind), *expected = kind < 0 ? NULL : names[kind];
        check(expected == NULL ? name == NULL : name != NULL && strcmp(name, expected) == 0,
              "solver %d is named %s, not %s", kind, name ? name : "(none)", expected ? expected : "(none)");
        if (expected == NULL)
            check(integrator_init(&it, (SolverKind)kind, W0SQ, 1e-6, 0.0, 1.0, 0.0) == -1,
                  "kind %d names no solver: refused", kind);
    }
    check(integrator_reach(SOLVER_RK4) == INTEGRATOR_REACH_RK4 && integrator_reach(SOLVER_RKN) == INTEGRATOR_REACH &&
          integrator_reach((SolverKind)0) == INTEGRATOR_REACH, "each solver's reach (an unknown one: the common line)");
    for (int kind = SOLVER_DOPRI5; kind <= SOLVER_SYMPLECTIC; kind++) {
        check(integrator_init(&it, (SolverKind)kind, W0SQ, 1e-6, 2.0, 1.0, 0.5) == 0,
              "init kind %d", kind);
        check(integrator_advance(&it, 2.0, y) == 0 && y[0] == 1.0 && y[1] == 0.5,
              "advance to t0 returns the initial state (kind %d)", kind);
        check(integrator_advance(&it, 3.0, y) == 0, "advance (kind %d)", kind);
        check(integrator_advance(&it, 1.0, y) == -1, "advance backwards (kind %d)", kind);
        check(integrator_advance(&it, NAN, y) == -1, "advance to NaN (kind %d)", kind);
    }
    /* at rest at the bottom: stays exactly there, steps grow to hmax */
    for (int kind = SOLVER_DOPRI5; kind <= SOLVER_SYMPLECTIC; kind++) {
        integrator_init(&it, (SolverKind)kind, W0SQ, 1e-8, 0.0, 0.0, 0.0);
        check(integrator_advance(&it, 1000.0, y) == 0 && y[0] == 0.0 && y[1] == 0.0,
              "equilibrium (kind %d)", kind);
    }
}

static void test_counts(void)
{
    /* one sin per stage: RK4 4 per step, + 1 at init; the composition 15 per step + one
     * cos for its interpolation, + 2 at init */
    Integrator it;
    double y[2];
    integrator_init(&it, SOLVER_RK4, W0SQ, 1e-8, 0.0, deg(80.0), 0.0);
    integrator_advance(&it, 10.0, y);
    check(it.stats.rhs_evals == 4 * it.stats.steps + 1 && it.stats.rejected == 0,
          "RK4 counts: %ld evals, %ld steps", it.stats.rhs_evals, it.stats.steps);
    integrator_init(&it, SOLVER_SYMPLECTIC, W0SQ, 1e-8, 0.0, deg(80.0), 0.0);
    integrator_advance(&it, 10.0, y);
    check(it.stats.rhs_evals == 16 * it.stats.steps + 2 && it.stats.rejected == 0,
          "symplectic counts: %ld evals, %ld steps", it.stats.rhs_evals, it.stats.steps);
    /* DOPRI5: 3 at start (f0, the initial energy, the initial-step Euler probe), 6 per
     * attempt (FSAL), and the energy projection (1 sin/cos pair per accepted step, up to
     * 4 more for Newton corrections larger than 2e-3 rad) */
    integrator_init(&it, SOLVER_DOPRI5, W0SQ, 1e-8, 0.0, deg(80.0), 0.0);
    integrator_advance(&it, 10.0, y);
    long base = 3 + 6 * (it.stats.steps + it.stats.rejected);
    check(it.stats.rhs_evals >= base + it.stats.steps &&
          it.stats.rhs_evals <= base + 5 * it.stats.steps,
          "DOPRI5 counts: %ld evals, %ld steps, %ld rejected", it.stats.rhs_evals,
          it.stats.steps, it.stats.rejected);
    /* RKN12(10): 4 at start (f0, the initial energy, the initial-step probe, sin/cos of
     * theta0 for the dense output), 16 per attempt (the first stage is f at the last
     * point), one sin/cos pair per accepted step (the energy projection), and one more for
     * each Newton correction larger than 2e-3 rad (only at loose tolerances) */
    for (double tol = 1e-3; tol > 1e-13; tol *= 1e-3) {
        integrator_init(&it, SOLVER_RKN, W0SQ, tol, 0.0, deg(80.0), 0.0);
        integrator_advance(&it, 10.0, y);
        base = 4 + 16 * (it.stats.steps + it.stats.rejected) + it.stats.steps;
        check(it.stats.rhs_evals >= base && it.stats.rhs_evals <= base + 3 * it.stats.steps &&
              (tol > 1e-6 || it.stats.rhs_evals == base),
              "RKN counts at tol %g: %ld evals, %ld steps, %ld rejected", tol,
              it.stats.rhs_evals, it.stats.steps, it.stats.rejected);
    }
}

/* Least-squares slope of log(error) against log(h) over n constant steps h w0 from hw0_max
 * down to hw0_min (geometric): the observed global order. */
static double fitted_order(SolverKind kind, double hw0_max, double hw0_min, int n,
                           double periods, int project)
{
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (int k = 0; k < n; k++) {
        double hw0 = hw0_max * pow(hw0_min / hw0_max, (double)k / (n - 1));
        double x = log(hw0), y = log(fixed_step_error(kind, hw0, periods, project));
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

static void test_fixed_step_orders(void)
{
    /* global order at a constant step: the error ratio when the step halves */
    static const struct {
        SolverKind kind;
        const char *name;
        int project;
        double order, hw0;
    } m[] = {
        {SOLVER_RK4, "RK4", 0, 4.0, 0.2},
        {SOLVER_DOPRI5, "DOPRI5 tableau", 0, 5.0, 0.1},
        {SOLVER_DOPRI5, "DOPRI5 + energy projection", 1, 0.0, 0.1},
        {SOLVER_SYMPLECTIC, "symplectic p8 s15", 0, 8.0, 0.4},
    };
    for (size_t i = 0; i < sizeof m / sizeof m[0]; i++) {
        double e1 = fixed_step_error(m[i].kind, m[i].hw0, 1.0, m[i].project);
        double e2 = fixed_step_error(m[i].kind, m[i].hw0 / 2, 1.0, m[i].project);
        double e3 = fixed_step_error(m[i].kind, m[i].hw0 / 4, 1.0, m[i].project);
        double p1 = log2(e1 / e2), p2 = log2(e2 / e3);
        printf("  order %-30s h w0 = %.2g, /2, /4: errors %.2e %.2e %.2e, observed %.2f %.2f\n",
               m[i].name, m[i].hw0, e1, e2, e3, p1, p2);
        if (m[i].order > 0.0)
            check(fabs(p2 - m[i].order) < 0.3 && fabs(p1 - m[i].order) < 0.5,
                  "%s: observed order %.2f %.2f, expected %.0f", m[i].name, p1, p2,
                  m[i].order);
        else   /* with the projection the order can only improve */
            check(p2 > 4.7, "%s: observed order %.2f", m[i].name, p2);
    }
    /* The 12th-order pair: between its pre-asymptotic range (h w0 > 1.6) and rounding
     * (errors below 1e-13 for h w0 < 0.5), single halvings scatter between 10 and 15
     * (the leading error terms change sign along the orbit); the least-squares slope over
     * eight steps from h w0 = 1.6 to 0.5, 10 periods, measures the order. */
    for (int project = 0; project <= 1; project++) {
        double p = fitted_order(SOLVER_RKN, 1.6, 0.5, 8, 10.0, project);
        printf("  order RKN12(10) %-21s h w0 = 1.6 .. 0.5 (fit over 8 steps): observed %.2f\n",
               project ? "+ energy projection" : "tableau", p);
        check(project ? p > 11.0 : fabs(p - 12.0) < 1.0, "RKN12(10)%s: observed order %.2f",
              project ? " + energy projection" : "", p);
    }
}

static void test_tolerance_convergence(void)
{
    /* adaptive methods: the error falls with the tolerance, roughly in proportion, down to
     * the rounding floor (RKN12 reaches 3e-14 at tol 1e-9: its range is 1e-3 .. 1e-9) */
    static const SolverKind kinds[] = {SOLVER_DOPRI5, SOLVER_RKN};
    static const char *names[] = {"DOPRI5", "RKN"};
    static const double loosest[] = {1e-5, 1e-3}, tightest[] = {1e-11, 1e-9};
    for (int k = 0; k < 2; k++) {
        double prev = 0.0;
        for (double tol = loosest[k]; tol > 0.1 * tightest[k]; tol *= 1e-2) {
            long ev = 0;
            double e = max_theta_error(kinds[k], tol, deg(80.0), 10.0, 500, &ev);
            printf("  %-6s 80 deg, 10 periods, tol %.0e: max |theta err| %.2e, %ld evals\n",
                   names[k], tol, e, ev);
            check(e < 100.0 * tol, "%s tol %g: error %.3g", names[k], tol, e);
            if (prev > 0.0)
                /* not exactly in proportion: DOPRI5's local tolerance is scaled by the motion
                 * (integrator.c), and its projected error falls unevenly (830, 16, 230 per
                 * 100x at 80 deg); at least 10x per 100x */
                check(prev / e > 10.0, "%s tol %g: error fell only by %.3g for 100x tol",
                      names[k], tol, prev / e);
            prev = e;
        }
    }
}

static void test_acceptance(void)
{
    /* the FMU's acceptance figure: DOPRI5, tol 1e-8, 10 periods of 75..90 deg,
     * max |theta error| <= 1e-6 (outputs every 0.01 s as a co-simulation master would) */
    double worst = 0.0;
    for (double d = 75.0; d <= 90.0; d += 2.5) {
        const double theta0 = deg(d), t_end = 10.0 * ref_period(theta0);
        Integrator it;
        integrator_init(&it, SOLVER_DOPRI5, W0SQ, 1e-8, 0.0, theta0, 0.0);
        for (int i = 1; i / 100.0 <= t_end; i++) {
            double y[2], r[2], t = i / 100.0;
            if (integrator_advance(&it, t, y) != 0) {
                worst = INFINITY;
                break;
            }
            ref_solution(theta0, t, r);
            worst = fmax(worst, fabs(y[0] - r[0]));
        }
    }
    printf("  DOPRI5 tol 1e-8, 75..90 deg, 10 periods, output every 0.01 s: "
           "max |theta err| %.2e\n", worst);
    check(worst <= 1e-6, "DOPRI5 acceptance: %.3g > 1e-6", worst);
}

static void test_grid_independence(void)
{
    /* outputs every 0.01 s and every 0.5 s agree at the common points: the internal steps
     * never depend on the output times */
    static const SolverKind kinds[] = {SOLVER_DOPRI5, SOLVER_RKN, SOLVER_RK4, SOLVER_SYMPLECTIC};
    for (int k = 0; k < 4; k++) {
        Integrator fine, coarse;
        integrator_init(&fine, kinds[k], W0SQ, 1e-10, 0.0, deg(80.0), 0.0);
        integrator_init(&coarse, kinds[k], W0SQ, 1e-10, 0.0, deg(80.0), 0.0);
        double diff = 0.0;
        int ok = 1;
        for (int i = 1; i <= 2000; i++) {
            double yf[2], yc[2], t = i / 100.0;
            ok &= integrator_advance(&fine, t, yf) == 0;
            if (i % 50 == 0) {
                ok &= integrator_advance(&coarse, t, yc) == 0;
                diff = fmax(diff, fmax(fabs(yf[0] - yc[0]), fabs(yf[1] - yc[1])));
            }
        }
        check(ok && diff <= 1e-12, "grid independence, kind %d: difference %.3g",
              (int)kinds[k], diff);
    }
}

static void test_interpolation(void)
{
    /* dense output between the internal steps is as accurate as the step points */
    static const SolverKind kinds[] = {SOLVER_DOPRI5, SOLVER_RKN, SOLVER_RK4, SOLVER_SYMPLECTIC};
    for (int k = 0; k < 4; k++) {
        const double tol = 1e-9, theta0 = deg(85.0), t_end = 3.0 * ref_period(theta0);
        Integrator it;
        integrator_init(&it, kinds[k], W0SQ, tol, 0.0, theta0, 0.0);
        double err_dense = 0.0, err_step = 0.0, y[2], r[2];
        for (int i = 1; i <= 3000; i++) {
            double t = t_end * i / 3000;
            integrator_advance(&it, t, y);
            ref_solution(theta0, t, r);
            err_dense = fmax(err_dense, fmax(fabs(y[0] - r[0]), fabs(y[1] - r[1]) / 3.0));
            ref_solution(theta0, it.t, r);
            err_step = fmax(err_step, fmax(fabs(it.y[0] - r[0]), fabs(it.y[1] - r[1]) / 3.0));
        }
        check(err_dense <= 10.0 * err_step + tol,
              "dense output, kind %d: %.3g vs %.3g at the steps", (int)kinds[k], err_dense,
              err_step);
    }
}

static void test_near_separatrix(void)
{
    /* released at rest at 179.99 deg: the exact motion librates with amplitude
     * 179.99 deg, its energy 7.6e-9 (relative) below the separatrix. The adaptive methods
     * must never carry it over the top, at any tolerance. */
    static const SolverKind kinds[] = {SOLVER_DOPRI5, SOLVER_RKN};
    const double theta0 = deg(179.99), t_end = 20.0 * ref_period(theta0);
    for (int k = 0; k < 2; k++) {
        for (int e = 3; e <= 12; e++) {
            const double tol = pow(10.0, -e);
            Integrator it;
            integrator_init(&it, kinds[k], W0SQ, tol, 0.0, theta0, 0.0);
            double max_abs = 0.0;
            int ok = 1;
            for (int i = 1; i <= 20000 && ok; i++) {
                double y[2];
                ok = integrator_advance(&it, t_end * i / 20000, y) == 0;
                max_abs = fmax(max_abs, fabs(y[0]));
            }
            check(ok && max_abs < PI, "179.99 deg, kind %d, tol %g: max |theta| = %.17g",
                  (int)kinds[k], tol, max_abs);
        }
    }
}

static void test_rkn_dense_output(void)
{
    /* the 12th-order pair's Hermite interpolant of degree 15 (integrator.c): between the
     * steps as accurate as at them, at every tolerance, on a wide libration (85 deg) and
     * next to the separatrix (179.99 deg, steps of up to h w0 = 2 across the top) */
    static const double amplitudes[] = {85.0, 179.99}, periods[] = {10.0, 5.0};
    for (int a = 0; a < 2; a++) {
        const double theta0 = deg(amplitudes[a]), t_end = periods[a] * ref_period(theta0);
        for (int e = 3; e <= 11; e += 2) {
            Integrator it;
            integrator_init(&it, SOLVER_RKN, W0SQ, pow(10.0, -e), 0.0, theta0, 0.0);
            double err_dense = 0.0, err_step = 0.0, y[2], r[2];
            for (int i = 1; i <= 4000; i++) {
                double t = t_end * i / 4000;
                integrator_advance(&it, t, y);
                ref_solution(theta0, t, r);
                err_dense = fmax(err_dense, fabs(y[0] - r[0]));
                ref_solution(theta0, it.t, r);
                err_step = fmax(err_step, fabs(it.y[0] - r[0]));
            }
            check(err_dense <= 2.0 * err_step + 2e-14,
                  "RKN dense output, %g deg, tol 1e-%d: %.3g vs %.3g at the steps",
                  amplitudes[a], e, err_dense, err_step);
        }
    }
}

static void test_default_near_separatrix(void)
{
    /* P2 of the study for the default solver (RKN12(10)): 179.99 deg from rest, 20
     * periods, 50 points a period. Its error must shrink as the tolerance does, at every
     * decade from 1e-3 to 1e-12, down to the rounding floor of double precision: near
     * the top theta = pi - 1.7e-4 is held to ulp(pi) = 4.4e-16, 2.5e-12 of its distance
     * from the saddle, and those rounding errors shift the time spent up there at every
     * passage. The error stops at 1e-11 to 4e-11, depending on the rounding of the steps
     * (the same projected pair at fixed steps: 3e-12 to 8e-12 in double, 1.4e-13 in long
     * double; README). */
    const double theta0 = deg(179.99), T = ref_period(theta0), floor_err = 5e-11;
    double prev = INFINITY;
    for (int e = 3; e <= 12; e++) {
        const double tol = pow(10.0, -e);
        Integrator it;
        integrator_init(&it, SOLVER_RKN, W0SQ, tol, 0.0, theta0, 0.0);
        double err = 0.0, max_abs = 0.0, y[2], r[2];
        int ok = 1;
        for (int i = 1; i <= 20 * 50 && ok; i++) {
            ok = integrator_advance(&it, T * i / 50.0, y) == 0;
            ref_solution(theta0, T * i / 50.0, r);
            err = fmax(err, fabs(y[0] - r[0]));
            max_abs = fmax(max_abs, fabs(y[0]));
        }
        printf("  RKN 179.99 deg, 20 periods, tol 1e-%02d: max |theta err| %.2e, max |theta| "
               "pi - %.2e, %ld evals, %ld rejected\n", e, err, PI - max_abs,
               it.stats.rhs_evals, it.stats.rejected);
        check(ok && max_abs < PI, "P2 tol %g: max |theta| = %.17g", tol, max_abs);
        /* within 2 tol: since omega's absolute tolerance is tol w0 (the same steps at every
         * scale), tol 1e-6 gives 1.8e-6 here (the certificate's bound is 100 tol) */
        check(err <= fmax(2.0 * tol, floor_err), "P2 tol %g: error %.3g above twice the tolerance", tol,
              err);
        check(err < prev || prev < floor_err, "P2 tol %g: error %.3g did not shrink (%.3g)",
              tol, err, prev);
        prev = err;
    }
}

static void test_long_horizon(void)
{
    /* P3 of the study, shortened: 90 deg for 1000 periods at 20 points a period. The
     * projected pair keeps the energy to rounding and its phase error grows only linearly
     * (with the time summed in plain double the rounding of t += h alone, ulp(t)/2 a step,
     * was 1.1e-10 here); the symplectic method's energy error stays bounded. */
    const double theta0 = deg(90.0), T = ref_period(theta0);
    const double H0 = 2.0 * W0SQ * pow(sin(0.5 * theta0), 2);
    static const SolverKind kinds[] = {SOLVER_RKN, SOLVER_DOPRI5, SOLVER_SYMPLECTIC};
    static const double tols[] = {1e-10, 1e-10, 1e-10};
    static const double max_err[] = {1e-11, 5e-8, 2e-7}, max_dh[] = {1e-13, 1e-9, 5e-9};
    for (int k = 0; k < 3; k++) {
        Integrator it;
        integrator_init(&it, kinds[k], W0SQ, tols[k], 0.0, theta0, 0.0);
        double err = 0.0, dh = 0.0, y[2], r[2];
        for (int i = 1; i <= 1000 * 20; i++) {
            integrator_advance(&it, T * i / 20.0, y);
            ref_solution(theta0, T * i / 20.0, r);
            err = fmax(err, fabs(y[0] - r[0]));
            dh = fmax(dh, fabs(0.5 * y[1] * y[1] + 2.0 * W0SQ * pow(sin(0.5 * y[0]), 2) - H0) /
                              H0);
        }
        printf("  kind %d, 90 deg, 1000 periods, tol 1e-10: max |theta err| %.2e, "
               "max |dH/H| %.2e, %ld evals\n", (int)kinds[k], err, dh, it.stats.rhs_evals);
        check(err < max_err[k] && dh < max_dh[k],
              "long horizon, kind %d: error %.3g, energy %.3g", (int)kinds[k], err, dh);
    }
}

static void test_symplectic_energy(void)
{
    /* bounded energy error over 2000 periods: no drift (the last 200 periods are no worse
     * than the first 200), while RK4 drifts */
    const double theta0 = deg(80.0), T = ref_period(theta0);
    const double H0 = 2.0 * W0SQ * pow(sin(0.5 * theta0), 2);
    Integrator it;
    integrator_init(&it, SOLVER_SYMPLECTIC, W0SQ, 1e-8, 0.0, theta0, 0.0);
    double first = 0.0, last = 0.0, y[2];
    const int n = 2000 * 20;
    for (int i = 1; i <= n; i++) {
        integrator_advance(&it, T * i / 20.0, y);
        double dH = fabs(0.5 * y[1] * y[1] + 2.0 * W0SQ * pow(sin(0.5 * y[0]), 2) - H0) / H0;
        if (i <= n / 10)
            first = fmax(first, dH);
        if (i > n - n / 10)
            last = fmax(last, dH);
    }
    printf("  symplectic tol 1e-8, 80 deg: max |dH/H| first 200 periods %.2e, "
           "last 200 of 2000 %.2e (%ld evals)\n", first, last, it.stats.rhs_evals);
    check(last < 1e-6 && last < 1.5 * first, "symplectic energy drift: %.3g then %.3g", first,
          last);

    integrator_init(&it, SOLVER_RK4, W0SQ, 1e-8, 0.0, theta0, 0.0);
    double rk_first = 0.0, rk_last = 0.0;
    for (int i = 1; i <= n; i++) {
        integrator_advance(&it, T * i / 20.0, y);
        double dH = fabs(0.5 * y[1] * y[1] + 2.0 * W0SQ * pow(sin(0.5 * y[0]), 2) - H0) / H0;
        if (i <= n / 10)
            rk_first = fmax(rk_first, dH);
        if (i > n - n / 10)
            rk_last = fmax(rk_last, dH);
    }
    printf("  RK4        tol 1e-8, 80 deg: max |dH/H| first 200 periods %.2e, "
           "last 200 of 2000 %.2e (%ld evals)\n", rk_first, rk_last, it.stats.rhs_evals);
    check(rk_last > 5.0 * rk_first, "RK4 is expected to drift: %.3g then %.3g", rk_first,
          rk_last);
}

static void test_rkn_efficiency(void)
{
    /* at equal error the Nystrom pair needs fewer sin evaluations than DOPRI5: the
     * loosest tolerance 10^(-e/4) reaching the target over 10 periods at 80 deg */
    static const SolverKind kinds[] = {SOLVER_DOPRI5, SOLVER_RKN};
    static const double targets[] = {1e-6, 1e-8, 1e-10};
    for (int t = 0; t < 3; t++) {
        long best[2] = {0, 0};
        for (int k = 0; k < 2; k++) {
            for (int e = 12; e <= 52; e++) {
                long ev = 0;
                double err = max_theta_error(kinds[k], pow(10.0, -0.25 * e), deg(80.0), 10.0,
                                             200, &ev);
                if (err <= targets[t]) {
                    best[k] = ev;
                    break;
                }
            }
        }
        printf("  evaluations for max |theta err| <= %.0e (80 deg, 10 periods): "
               "DOPRI5 %ld, RKN %ld\n", targets[t], best[0], best[1]);
        check(best[1] > 0 && best[0] > 0 && best[1] < best[0],
              "RKN not cheaper than DOPRI5 at error %g", targets[t]);
    }
}

/* `test_integrators --table`: cost and accuracy of every method, 80 deg, 10 periods */
static void print_table(void)
{
    static const char *names[] = {"", "DOPRI5", "RK4", "RKN", "SYMPLECTIC"};
    const double theta0 = deg(80.0), t_end = 10.0 * ref_period(theta0);
    printf("  method      tol    rhs_evals  steps  rejected  max|theta err|  max|omega err|\n");
    for (int kind = SOLVER_DOPRI5; kind <= SOLVER_SYMPLECTIC; kind++) {
        for (int e = 4; e <= 12; e += 2) {
            Integrator it;
            integrator_init(&it, (SolverKind)kind, W0SQ, pow(10.0, -e), 0.0, theta0, 0.0);
            double et = 0.0, eo = 0.0, y[2], r[2];
            for (int i = 1; i <= 1000; i++) {
                double t = t_end * i / 1000;
                integrator_advance(&it, t, y);
                ref_solution(theta0, t, r);
                et = fmax(et, fabs(y[0] - r[0]));
                eo = fmax(eo, fabs(y[1] - r[1]));
            }
            printf("  %-10s  1e-%02d  %9ld  %5ld  %8ld  %14.2e  %14.2e\n", names[kind], e,
                   it.stats.rhs_evals, it.stats.steps, it.stats.rejected, et, eo);
        }
    }
}

/* The problem is dimensionless in w0 t: at w0^2 = 1e-300 and 1e300 (g/L near the ends of the
 * doubles) every solver takes the steps it takes at w0^2 = 1 and ends at the same theta, to
 * rounding. Before, the initial step's norm squared w0/tol (1e154 and beyond), and rkn,
 * dopri5 and rk4 refused to start above w0^2 ~ 1e292. symplectic keeps its third derivative
 * unscaled (w0^3), so its range ends near w0^2 = 1e205: checked at 1e+-200. */
static void test_extreme_scales(void)
{
    const SolverKind kinds[] = {SOLVER_DOPRI5, SOLVER_RK4, SOLVER_RKN, SOLVER_SYMPLECTIC};
    for (int k = 0; k < 4; k++) {
        const double far = kinds[k] == SOLVER_SYMPLECTIC ? 1e200 : 1e300;
        const double scales[] = {1.0, far, 1.0 / far};
        double theta[3];
        long steps[3];
        for (int i = 0; i < 3; i++) {
            Integrator it;
            double y[2] = {NAN, NAN};
            const int init = integrator_init(&it, kinds[k], scales[i], 1e-8, 0.0, deg(80.0), 0.0);
            const int done = init == 0 ? integrator_advance(&it, 6.0 * PI / sqrt(scales[i]), y) : -1;
            check(init == 0 && done == 0, "kind %d at w0^2 = %g: init %d, advance %d", kinds[k], scales[i], init, done);
            theta[i] = y[0];
            steps[i] = it.stats.steps;
        }
        for (int i = 1; i < 3; i++)
            check(steps[i] == steps[0] && fabs(theta[i] - theta[0]) <= 1e-13,
                  "kind %d at w0^2 = %g: %ld steps and theta %.17g, at w0^2 = 1: %ld and %.17g", kinds[k], scales[i],
                  steps[i], theta[i], steps[0], theta[0]);
    }
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "--table") == 0)
        print_table();
    test_reference();
    test_invalid_input();
    test_counts();
    test_fixed_step_orders();
    test_tolerance_convergence();
    test_acceptance();
    test_grid_independence();
    test_interpolation();
    test_near_separatrix();
    test_rkn_dense_output();
    test_default_near_separatrix();
    test_long_horizon();
    test_symplectic_energy();
    test_rkn_efficiency();
    test_extreme_scales();
    return check_summary("test_integrators");
}
