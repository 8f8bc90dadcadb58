/* rkn.c: adaptive embedded Runge-Kutta-Nystrom pair RKN12(10)17M for
 * theta'' = f(theta) = -w0^2 sin(theta), with energy projection and a dense output of
 * degree 15 taken from the differential equation.
 *
 * Method: J. R. Dormand, M. E. A. El-Mikkawy, P. J. Prince, "High-order embedded
 * Runge-Kutta-Nystrom formulae", IMA J. Numer. Anal. 7 (1987) 423-430: 17 stages, a
 * 12th-order solution (local extrapolation) and an embedded 10th-order one for the error
 * estimate. The coefficients are rationals (as published, and as transcribed in
 * OrdinaryDiffEq.jl's DPRKN12 tableau, where they were taken from); the doubles below are
 * those rationals correctly rounded (Python's fractions). Checked in exact rational
 * arithmetic: the quadrature conditions sum bp_i c_i^(q-1) = 1/q for q <= 12 and
 * sum b_i c_i^(q-1) = 1/(q (q+1)) for q <= 11, those of the embedded pair for q <= 10 and
 * q <= 9, and sum_j a_ij = c_i^2 / 2 (exactly, except for the last four stages: to 1e-53);
 * tests/c/test_integrators.c observes global order 12 at a constant step.
 *
 * Why this pair: measured on the pendulum (docs/solvers.md, "Solvers and the
 * speed-against-error study"), it reaches every error from 1e-4 to 1e-12 over 10 periods at
 * 75..90 deg with 2.4 to 4.8 times fewer evaluations of sin than scipy's Dormand-Prince
 * 8(5,3) (DOP853), and 2 to 4 times fewer than an RKN6(4) pair (80 deg, 10 periods:
 * 786, 1211, 1670 evaluations for errors 1e-6, 1e-8, 1e-10, against 1612, 3552, 7102).
 *
 * With x = theta, v = omega, k_i = f(x0 + c_i h v0 + h^2 sum_j a_ij k_j):
 *   x1 = x0 + h v0 + h^2 sum b_i k_i,   v1 = v0 + h sum bp_i k_i,
 *   error estimate (h^2 sum (b_i - bhat_i) k_i, h sum (bp_i - bphat_i) k_i).
 * The first stage is f(x0), known from the end of the previous step, so a step costs 16
 * evaluations of sin, plus one sin/cos pair at the new point, which gives its energy for
 * the projection, f for the next step, and sin/cos for the dense output.
 *
 * Each accepted point is projected back onto the initial energy (integrator_project in
 * integrator_core.c), which keeps a libration from turning into a rotation near the separatrix
 * and removes the secular energy drift, so the global error grows linearly, not
 * quadratically, with time.
 *
 * Dense output: the pair has no continuous extension of its own; the interpolant is the
 * two-point Hermite polynomial of degree 15 matching theta and its first 7 derivatives at
 * both ends of the step (integrator_taylor / integrator_hermite_setup), all of which follow from
 * theta, omega, sin theta and cos theta without evaluating f again. Its error, of the
 * order of h^16 max|theta^(16)| / 16! / 4^8, stays below the step's own error (measured:
 * between the steps within a factor 2 of the step points at every tolerance, up to the
 * largest steps, tests/c/test_integrators.c). */
#include <math.h>

#include "integrator.h"
#include "integrator_core.h"
#include "methods.h"
#include "trig.h"

#define RKN_STAGES 17
/* error estimate of order 10 (local error h^11): controller exponent q = 11 */
#define RKN_ERR_Q 11
/* Largest step, in units of 1/w0 (a period of small oscillations is 2 pi). Binds near the
 * equilibria and near the top of a libration close to the separatrix, where the error
 * estimate is tiny; 2 is 3.6 steps a period at 80 deg. At 3, the steps that cross the fast
 * swing after a slow passage of the top leave the pair's asymptotic range: at tol 1e-3,
 * 5 periods at 179.99 deg end 3.4e-3 off instead of 4.0e-5. */
#define RKN_HMAX_W0 2.0
/* Safety factor of the step-size controller. With the PI controller's exponents for
 * q = 11, a smooth stretch settles at err = 0.8^36.7 = 2.8e-4 of the tolerance (0.9 would
 * settle at 0.02): steps stay a factor ~2 below the size the error test would reject. At
 * 0.9 the steps into the fast swing after a slow passage of the top are rejected 30 to
 * 110 times over P2 (20 periods at 179.99 deg), and the error there stops shrinking
 * with the tolerance (6.3e-7 at tol 1e-6, 7.2e-7 at 1e-7); at 0.8 there is no rejection
 * and the error falls at every decade of tol from 1e-3 down to its rounding floor (1e-11
 * to 4e-11, reached near tol 1e-10). At equal error the cost is the same (the tolerance
 * buys more accuracy per step). */
#define RKN_SAFETY 0.8

static const double C[RKN_STAGES] = {
    0.0, 0.02, 0.04, 0.1, 0.13333333333333333, 0.16, 0.05, 0.2, 0.25, 0.3333333333333333, 0.5,
    0.5555555555555556, 0.75, 0.8571428571428571, 0.9452162222720143, 1.0, 1.0};
static const double A[RKN_STAGES][RKN_STAGES - 1] = {
    {0.0},
    {0.0002},
    {0.0002666666666666667, 0.0005333333333333334},
    {0.002916666666666667, -0.004166666666666667, 0.00625},
    {0.0016460905349794238, 0.0, 0.0054869684499314125, 0.0017558299039780521},
    {0.0019456, 0.0, 0.007151746031746032, 0.0029127111111111113, 0.0007899428571428571},
    {0.00056640625, 0.0, 0.0008809730489417989, -0.0004369212962962963, 0.00033900669642857143,
     -9.946469907407407e-05},
    {0.0030833333333333333, 0.0, 0.0, 0.0017777777777777779, 0.0027, 0.0015782828282828283,
     0.01086060606060606},
    {0.00365183937480113, 0.0, 0.003965171714072343, 0.0031972582629306284,
     0.008221467306855435, -0.0013130926959572379, 0.009771586968064868, 0.003755769069232834},
    {0.003707241068718501, 0.0, 0.005082045854555286, 0.001174708002175412,
     -0.021147629915126993, 0.06010463698107881, 0.02010573476850619, -0.02835075012293358,
     0.014879568918581932},
    {0.03512537656073344, 0.0, -0.008615749195138479, -0.005791448051007917, 1.945554823782616,
     -3.4351238674565137, -0.10930701107475221, 2.3496383118995166, -0.7560094086870229,
     0.10952897222156927},
    {0.020527792537482496, 0.0, -0.00728644676448018, -0.0021153556079618403,
     0.9275807968723522, -1.6522824844257367, -0.02107956300568657, 1.2065364326207872,
     -0.4137144770010661, 0.09079873982809654, 0.005355552600533985},
    {-0.14324078875545515, 0.0, 0.012528703773091817, 0.006826019163969827, -4.799555395574387,
     5.6986250439519415, 0.7553430369523645, -0.12755487858281084, -1.9605926051117384,
     0.9185609056635262, -0.23880085505284432, 0.15911081357234216},
    {0.8045019205520489, 0.0, -0.016658527067011247, -0.021415834042629735, 16.827235928962466,
     -11.172835357176098, -3.377159297226324, -15.243326655360846, 17.179835738215417,
     -5.437719239823995, 1.3878671618364655, -0.5925827732652812, 0.029603873171297354},
    {-0.913296766697358, 0.0, 0.0024112725757805178, 0.01765812269386174, -14.851649779720384,
     2.1589708670045757, 3.99791558311788, 28.434151800232232, -25.2593643549416,
     7.733878542362238, -1.8913028948478674, 1.0014845070224718, 0.004641199599109052,
     0.011218755022148957},
    {-0.27519629720559396, 0.0, 0.03661188877915492, 0.009789519688231562, -12.293062345886211,
     14.207226453937903, 1.5866476906789537, 2.4577735327595946, -8.935193694403273,
     4.373672731613407, -1.8347181765449492, 1.1592085289061491, -0.017290253165383924,
     0.019325977904460768, 0.005204442937554993},
    {1.3076391847404059, 0.0, 0.017364109189745843, -0.018544456454265796, 14.811522032867726,
     9.38317630848247, -5.2284261999445425, -48.95128052584765, 38.297096034337926,
     -10.58738133697598, 2.4332304376226275, -1.0453406042575444, 0.0717732095086726,
     0.0021622109708082783, 0.007009595759602514},
};
static const double B[RKN_STAGES] = {
    0.012127868517185414, 0.0, 0.0, 0.0, 0.0, 0.0, 0.08629746251568875, 0.2525469581187147,
    -0.1974186799326823, 0.2031869190789726, -0.020775808077714918, 0.10967804874502014,
    0.038065132526466504, 0.01163406880432423, 0.0046580297040248785, 0.0, 0.0};
static const double BP[RKN_STAGES] = {
    0.012127868517185414, 0.0, 0.0, 0.0, 0.0, 0.0, 0.09083943422704079, 0.3156836976483934,
    -0.2632249065769097, 0.3047803786184589, -0.041551616155429835, 0.2467756096762953,
    0.15226053010586602, 0.08143848163026961, 0.08502571193890811, -0.009155189630077963,
    0.025};
static const double EB[RKN_STAGES] = {
    -0.004880833389821577, 0.0, 0.0, 0.0, 0.0, 0.0, 0.014038126584857338, -0.11947921920803832,
    0.20440246507662121, -0.1322681492223791, 0.11053069299761689, -0.07975385787102851,
    0.011224330486437457, -0.004671596801593694, 0.0008580413473282841, 0.0, 0.0};
static const double EBP[RKN_STAGES] = {
    -0.004880833389821577, 0.0, 0.0, 0.0, 0.0, 0.0, 0.014776975352481408, -0.1493490240100479,
    0.2725366201021616, -0.19840222383356862, 0.22106138599523378, -0.17944618020981415,
    0.04489732194574983, -0.03270117761115586, 0.015662325288859434, -0.029155189630077964,
    0.025};

/* it->dense holds: rows 0 .. INTEGRATOR_TAYLOR_TERMS - 1 the Hermite coefficients of the last
 * step (integrator_hermite_setup); row TRIG_ROW sin and cos of theta at the current point, from
 * which the next step builds the left end of its interpolant. Both ends are expanded in the
 * step's own time unit (integrator_taylor with w0^2 h^2 and omega h), so no coefficient overflows
 * however large g/L is (unscaled, the 14th derivative of theta grows like w0^14). */
#define TRIG_ROW INTEGRATOR_TAYLOR_TERMS
/* Rows RIGHT_ROW .. RIGHT_ROW + 3 keep the last step's right-end Taylor coefficients (in its
 * time unit h_last), which are the next step's left end: A_n h^n = (A_n h_last^n) (h / h_last)^n,
 * so a step expands only its new end. Row RIGHT_H_ROW [0] is 1 while they are valid, 0 after
 * integrator_rkn_start (the first step expands both ends). A flag of its own, not h_last > 0: the
 * FMU state format does not version these rows, and a state that holds zeros here (as one
 * serialized without them does, flag included) must expand both ends after it is restored. */
#define RIGHT_ROW (TRIG_ROW + 1)
#define RIGHT_H_ROW (RIGHT_ROW + INTEGRATOR_TAYLOR_TERMS / 2)
_Static_assert(RIGHT_H_ROW < INTEGRATOR_MAX_STAGES, "dense[] holds the Hermite coefficients, sin/cos and the right end");

void integrator_rkn_start(Integrator *it)
{
    it->hmax = RKN_HMAX_W0 / sqrt(it->w0sq);
    it->h = integrator_initial_step(it, 12);
    it->dense[TRIG_ROW][0] = sin(it->y[0]);
    it->dense[TRIG_ROW][1] = cos(it->y[0]);
    it->dense[RIGHT_H_ROW][0] = 0.0;
    it->stats.rhs_evals++;
}

int integrator_rkn_step(Integrator *it)
{
    const double x0 = it->y[0], v0 = it->y[1];
    /* The stages hold sin theta; the acceleration -w0^2 sin theta enters through w0^2 h^2 once
     * per sum, not once per stage. A stage's move is
     *   x_i - x0 = h c_i v0 + h^2 sum_j a_ij f_j
     *            = ((h c_i v0 - w0^2 h^2 sum_{j<i-1} a_ij sn_j) - W lead_i-1) - W rest_i-1,
     * W = w0^2 h^2 a_i,i-1 and sn_i-1 = lead_i-1 + rest_i-1 (trig_sin_moved), so that between one
     * stage's move and the next lie only the rest of the sine's polynomial, a product and a
     * subtraction: everything else is summed while the previous stage is evaluated. The
     * solution's sums take w0^2 in double-double (the period over many steps); a stage's move
     * needs only its double (the low part, 1e-16 of the term, is below the move's own rounding). */
    const double sin_x0 = it->dense[TRIG_ROW][0], cos_x0 = it->dense[TRIG_ROW][1];
    double taylor_sin[TRIG_TERMS];   /* sin about x0, the polynomial every stage evaluates */
    trig_moved_coefficients(sin_x0, cos_x0, taylor_sin);
    double sn[RKN_STAGES];
    sn[0] = sin_x0;   /* sin x0, kept from the end of the previous step */

    for (;;) {
        const double h = it->h;
        if (!(h >= integrator_hmin(it)) || !isfinite(h))
            return -1;   /* step-size underflow */
        const double wh = it->w0sq * (h * h), wl = it->w0sq_lo * (h * h);
        double lead = sin_x0, rest = 0.0;
        for (int i = 1; i < RKN_STAGES; i++) {
            double s = 0.0;
            for (int j = 0; j < i - 1; j++)
                s += A[i][j] * sn[j];
            const double W = wh * A[i][i - 1];
            const double move = ((h * (C[i] * v0) - wh * s) - W * lead) - W * rest;
            lead = trig_sin_moved(x0, taylor_sin, move, &rest);
            sn[i] = lead + rest;
        }
        it->stats.rhs_evals += RKN_STAGES - 1;
        double sx = 0.0, sv = 0.0, ex = 0.0, ev = 0.0;
        for (int i = 0; i < RKN_STAGES; i++) {
            sx += B[i] * sn[i];
            sv += BP[i] * sn[i];
            ex += EB[i] * sn[i];
            ev += EBP[i] * sn[i];
        }
        const double hw = h * it->w0sq, hwl = h * it->w0sq_lo;
        double y1[2] = {x0 + (h * v0 - (wh * sx + wl * sx)), v0 - (hw * sv + hwl * sv)};
        const double e[2] = {wh * ex + wl * ex, hw * ev + hwl * ev};
        const double err = integrator_err_norm(it, e, it->y, y1);
        if (!isfinite(err) || !isfinite(y1[0]) || !isfinite(y1[1]))
            return -1;

        int accept;
        const double hnew = integrator_control(it, h, err, RKN_ERR_Q, RKN_SAFETY, &accept);
        if (!accept) {
            it->h = hnew;
            continue;
        }
        double f1[2], trig1[2], left[INTEGRATOR_TAYLOR_TERMS], right[INTEGRATOR_TAYLOR_TERMS];
        integrator_project(it, it->y, y1, f1, trig1);
        if (it->dense[RIGHT_H_ROW][0] == 1.0) {
            const double rho = h / it->h_last;
            double scale = 1.0;
            for (int n = 0; n < INTEGRATOR_TAYLOR_TERMS; n++, scale *= rho)
                left[n] = it->dense[RIGHT_ROW + n / 2][n % 2] * scale;
        } else {
            integrator_taylor(wh, x0, v0 * h, it->dense[TRIG_ROW], left);   /* sin/cos of x0: stored */
        }
        integrator_taylor(wh, y1[0], y1[1] * h, trig1, right);
        integrator_hermite_setup(left, right, it->dense);
        for (int n = 0; n < INTEGRATOR_TAYLOR_TERMS; n++)
            it->dense[RIGHT_ROW + n / 2][n % 2] = right[n];
        it->dense[RIGHT_H_ROW][0] = 1.0;
        it->dense[TRIG_ROW][0] = trig1[0];
        it->dense[TRIG_ROW][1] = trig1[1];
        integrator_accept(it, h, y1, f1);
        it->h = hnew;
        return 0;
    }
}

void integrator_rkn_interp(const Integrator *it, double s, double y[2])
{
    integrator_hermite_eval(it, s, y);
}
