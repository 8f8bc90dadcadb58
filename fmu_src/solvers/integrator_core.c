/* integrator_core.c: the parts every method shares (initial step, step-size control,
 * accepting a step, energy projection, Hermite and Taylor dense output). Below both
 * integrator.c (init, dispatch) and the method files: it calls neither, so the
 * dependency graph integrator.c -> {dopri5, rk4, rkn, symplectic}.c -> integrator_core.c
 * has no cycle. */
#include <float.h>
#include <math.h>

#include "dd.h"
#include "integrator_core.h"

double integrator_hmin(const Integrator *it)
{
    /* 16 eps in the motion's time unit 1/rate: a shorter step moves the state by less than
     * 16 ulps of its own scale, so its error estimate measures rounding and the step size has
     * collapsed (HNW's DOPRI5 stops at 0.1 |h| <= eps |t|, in absolute time; here the time is a
     * compensated sum, t + t_lo, which resolves steps far below ulp(t), so the test needs no
     * clock and the same problem takes the same steps from every start time) */
    return 16.0 * DBL_EPSILON / it->rate;
}

double integrator_energy0(double w0sq, double w0sq_lo, double theta0, double omega0, double *lo)
{
    /* G = omega0^2/2 - 2 w0sq cos^2(theta0/2): the cosine in double-double (dd_sincos, dd.c;
     * a correctly rounded double cosine is up to 1e-16 off, a bias of 1 - m that near the
     * separatrix becomes the error), the products split exactly (two-product), the sum in
     * double-double. dd_sincos takes |theta0/2| <= 2 pi; beyond, the double cosine. */
    DoubleDouble c;
    if (fabs(theta0) <= 4.0 * 3.141592653589793) {
        DoubleDouble s;
        dd_sincos(dd_of(0.5 * theta0), &s, &c);
    } else {
        c = dd_of(cos(0.5 * theta0));
    }
    const DoubleDouble kin = dd_two_prod(0.5 * omega0, omega0);   /* 0.5 omega0 exact scaling */
    const DoubleDouble cc = dd_mul(c, c);
    const DoubleDouble w2 = {2.0 * w0sq, 2.0 * w0sq_lo};
    const DoubleDouble pot = dd_mul(w2, cc);
    const DoubleDouble g = dd_add(kin, dd_neg(pot));
    if (!(isfinite(g.hi) && isfinite(g.lo))) {
        /* the exact products split their factors (Dekker), which overflows for factors near
         * DBL_MAX / 2^27 (g/L or omega0^2 beyond about 1e300): G in double there, finite or
         * not (integrator_init refuses a G that is not) */
        *lo = 0.0;
        return 0.5 * omega0 * omega0 - 2.0 * w0sq * (c.hi * c.hi);
    }
    *lo = g.lo;
    return g.hi;
}

/* sqrt(mean (v_i scale / sc_i)^2): the weighted RMS of v in the time unit `scale`, each term
 * scaled before it is squared. integrator_initial_step squares first (HNW's norm as written; scaling
 * first rounds differently and would move the first step of every run) and takes this only
 * where that overflows: beyond w0 / tol ~ 1e154 the slope's square does. */
static double scaled_rms(const double v[2], const double sc[2], double scale)
{
    const double r0 = v[0] / sc[0] * scale, r1 = v[1] / sc[1] * scale;
    return sqrt(0.5 * (r0 * r0 + r1 * r1));
}

double integrator_initial_step(Integrator *it, int order)
{
    /* HNW I, II.4: d0 = ||y0||, d1 = ||f0||, h0 = 0.01 d0/d1; one explicit Euler step
     * gives d2 = ||f1 - f0|| / h0; h1 = (0.01 / max(d1, d2))^(1/(order+1));
     * h = min(100 h0, h1). Norms weighted by sc_i = atol_i + rtol |y0_i|. Every quantity in
     * the motion's time unit 1/w0 (HNW's formula for h1 assumes time of order 1): the rule
     * gives the same h w0 for every L and g. */
    const double tscale = 1.0 / sqrt(it->w0sq);
    double d0 = 0.0, d1 = 0.0, d2 = 0.0, sc[2];
    for (int i = 0; i < 2; i++) {
        sc[i] = it->atol[i] + it->rtol * fabs(it->y[i]);
        d0 += (it->y[i] / sc[i]) * (it->y[i] / sc[i]);
        d1 += (it->f[i] / sc[i]) * (it->f[i] / sc[i]);
    }
    d0 = sqrt(0.5 * d0);
    d1 = sqrt(0.5 * d1) * tscale;   /* per unit of w0 t */
    if (!isfinite(d1))
        d1 = scaled_rms(it->f, sc, tscale);
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;   /* in units of 1/w0 */
    h0 = fmin(h0 * tscale, it->hmax);

    double y1[2], f1[2], df[2];
    y1[0] = it->y[0] + h0 * it->f[0];
    y1[1] = it->y[1] + h0 * it->f[1];
    integrator_rhs(it, y1, f1);
    for (int i = 0; i < 2; i++) {
        df[i] = f1[i] - it->f[i];
        d2 += (df[i] / sc[i]) * (df[i] / sc[i]);
    }
    d2 = sqrt(0.5 * d2) / h0 * tscale * tscale;   /* per unit of (w0 t)^2 */
    if (!isfinite(d2))
        d2 = scaled_rms(df, sc, tscale) / h0 * tscale;

    double dmax = fmax(d1, d2);
    double h1 = (dmax <= 1e-15) ? fmax(1e-6 * tscale, h0 * 1e-3)
                                : pow(0.01 / dmax, 1.0 / (order + 1)) * tscale;
    return fmin(fmin(100.0 * h0, h1), it->hmax);
}

double integrator_control(Integrator *it, double h, double err, int q, double safe, int *accept)
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
        fac = integrator_max(1.0 / fac_max, integrator_min(1.0 / fac_min, fac));   /* err finite: no NaN here */
        double hnew = h / fac;
        if (it->last_rejected)
            hnew = integrator_min(hnew, h);     /* no increase right after a rejection */
        it->err_prev = integrator_max(err, 1e-4);
        it->last_rejected = 0;
        *accept = 1;
        return integrator_min(hnew, it->hmax);
    }
    /* rejected: pure I control (err^alpha, alpha = 0.7/q), never shrink by more than fac_min */
    it->last_rejected = 1;
    it->stats.rejected++;
    *accept = 0;
    return h / fmin(1.0 / fac_min, pow(err, 0.7 / q) / safe);
}

void integrator_accept(Integrator *it, double h, const double ynew[2], const double fnew[2])
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

void integrator_hermite5(const Integrator *it, double s, double y[2])
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

int integrator_project(Integrator *it, const double y0[2], double ynew[2], double fnew[2],
                  double trig[2])
{
    /* Orthogonal projection onto the energy level (Hairer, Lubich & Wanner, Geometric
     * Numerical Integration, IV.4.1): y <- y + lambda grad G(y), lambda = (G0 - G(y)) /
     * |grad G|^2 (Newton on the scalar lambda, converging quadratically: one iteration at
     * tight tolerances, two or three at loose ones). G = omega^2/2 - 2 w0sq c^2 with
     * s = sin(theta/2), c = cos(theta/2). Orthogonal in the coordinates (theta, u = omega/w0),
     * where G = w0sq (u^2/2 - 2 c^2) has the gradient w0sq (sin theta, u): in (theta, omega)
     * the move is lambda (sin theta, omega), lambda = (G0 - G) / (w0sq sin^2 theta + omega^2),
     * the same at every L and g (a projection orthogonal in (theta, omega) depends on w0: the
     * scale ladder's results then differ at 3e-11 between w0 = 1 and 2^20). One sin/cos pair
     * at the new point is counted in rhs_evals (it costs what a stage costs, and gives f
     * there); the Newton corrections rotate (s, c) without new trigonometric calls where they
     * are small (rotate_half_angle). */
    const double w0sq = it->w0sq;
    const double th_in = ynew[0], om_in = ynew[1];
    const double s_in = sin(0.5 * th_in), c_in = cos(0.5 * th_in);
    double th = th_in, om = om_in, s = s_in, c = c_in;
    int moved = 0;
    it->stats.rhs_evals++;
    if (it->project_energy) {
        const double sc_th = it->atol[0] + it->rtol * integrator_max(fabs(y0[0]), fabs(th_in));
        const double sc_om = it->atol[1] + it->rtol * integrator_max(fabs(y0[1]), fabs(om_in));
        for (int iter = 0; iter < 4; iter++) {
            const double kin = 0.5 * om * om, pot = 2.0 * w0sq * c * c + 2.0 * it->w0sq_lo * c * c;
            const double r = (it->energy0 - (kin - pot)) + it->energy0_lo;
            if (fabs(r) <= 4.0 * DBL_EPSILON * (kin + pot))
                break;   /* at the rounding level of G itself */
            /* orthogonal in the dimensionless coordinates (theta, omega / w0), so that the
             * projection is the same at every L and g: along (sin theta, omega) with
             * lambda = r / (w0sq sin^2 theta + omega^2) */
            const double g0 = 2.0 * s * c, g1 = om;
            const double gg = w0sq * (g0 * g0) + g1 * g1;
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
    fnew[1] = -(w0sq * trig[0] + it->w0sq_lo * trig[0]);
    return moved;
}

/* Binomials C(M - 1 + j, j), j = 0 .. M - 1, for M = INTEGRATOR_TAYLOR_TERMS = 8. */
_Static_assert(INTEGRATOR_TAYLOR_TERMS == 8, "HERMITE_BINOM and integrator_hermite_eval assume M = 8");
static const double HERMITE_BINOM[INTEGRATOR_TAYLOR_TERMS] = {1.0, 8.0, 36.0, 120.0, 330.0, 792.0,
                                                         1716.0, 3432.0};

void integrator_taylor(double w0sq, double theta, double omega, const double trig[2],
                  double a[INTEGRATOR_TAYLOR_TERMS])
{
    /* Taylor coefficients A_n = theta^(n)(t) / n! from theta'' = -w0sq sin theta: with S_n,
     * C_n those of sin theta(t) and cos theta(t),
     *   n S_n = sum_{j=1..n} j A_j C_{n-j},  n C_n = -sum_{j=1..n} j A_j S_{n-j},
     *   A_{n+2} = -w0sq S_n / ((n+1)(n+2)),
     * the recurrences of the derivatives of sin and cos of a series (automatic
     * differentiation; HNW I, I.8). */
    double S[INTEGRATOR_TAYLOR_TERMS - 2], C[INTEGRATOR_TAYLOR_TERMS - 2];
    a[0] = theta;
    a[1] = omega;
    S[0] = trig[0];
    C[0] = trig[1];
    for (int n = 0; n < INTEGRATOR_TAYLOR_TERMS - 2; n++) {
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

void integrator_hermite_setup(const double left[INTEGRATOR_TAYLOR_TERMS],
                         const double right[INTEGRATOR_TAYLOR_TERMS], double dense[][2])
{
    /* Two-point Hermite interpolation matching INTEGRATOR_TAYLOR_TERMS = M Taylor coefficients
     * at both ends of [0, 1] (degree 2M - 1):
     *   p(s) = (1 - s)^M alpha(s) + s^M beta(s - 1),
     * alpha = the first M terms of the series of left(s) / (1 - s)^M, beta those of
     * right(u) / (1 + u)^M, using 1/(1 - x)^M = sum_j C(M - 1 + j, j) x^j. Stored as
     * dense[k] = (alpha_k, beta_k). */
    for (int k = 0; k < INTEGRATOR_TAYLOR_TERMS; k++) {
        double al = 0.0, be = 0.0;
        for (int i = 0; i <= k; i++) {
            al += left[i] * HERMITE_BINOM[k - i];
            be += ((k - i) % 2 ? -right[i] : right[i]) * HERMITE_BINOM[k - i];
        }
        dense[k][0] = al;
        dense[k][1] = be;
    }
}

void integrator_hermite_eval(const Integrator *it, double s, double y[2])
{
    /* p(s) and p'(s) / h from the coefficients of integrator_hermite_setup (Horner, with the
     * derivative alongside) */
    const double h = it->h_last;
    const double u = s - 1.0, r = 1.0 - s;
    const int M = INTEGRATOR_TAYLOR_TERMS;
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
