/* rkn.c: adaptive embedded Runge-Kutta-Nystrom pair RKN6(4)6 with a free 6th-order
 * continuous extension, for theta'' = f(theta) = -w0^2 sin(theta).
 *
 * Method: J. R. Dormand, P. J. Prince, "Runge-Kutta-Nystrom triples",
 * Comput. Math. Appl. 13 (1987) 937-949 (the RKN6(4)6 triple; the embedded 4th-order
 * formula supplies the error estimate, local extrapolation propagates the 6th-order
 * solution). The coefficients are exact in Q(sqrt(8581)); they are written below to 21
 * digits, evaluated from the exact expressions with mpmath at 60 digits (the exact
 * forms are given next to the irrational ones). Checked: the row sums (sum_j a_ij =
 * c_i^2/2) and quadrature conditions hold to 60 digits; one step on the pendulum against
 * a 40-digit mpmath solution gives local errors O(h^7) in x and v, O(h^5) for the
 * embedded pair, O(h^7) / O(h^6) for the dense x / v; tests/c/test_integrators.c
 * observes global order 6 at a constant step.
 *
 * With x = theta, v = omega, k_i = f(x0 + c_i h v0 + h^2 sum_j a_ij k_j):
 *   x1 = x0 + h v0 + h^2 sum b_i k_i,   v1 = v0 + h sum bp_i k_i,
 * the last stage (c6 = 1, a6j = b_j) is f(x1): first same as last, so a step costs five
 * evaluations of sin. Dense output at s in [0, 1]:
 *   x(s) = x0 + s h v0 + (s h)^2 sum b_i(s) k_i,   v(s) = v0 + s h sum bp_i(s) k_i,
 * with b_i(s), bp_i(s) quartic polynomials (b_2 = bp_2 = 0).
 *
 * Each accepted point is projected back onto the initial energy (integ_project in
 * integrator.c), which keeps a libration from turning into a rotation near the separatrix
 * and removes the secular energy drift. */
#include <math.h>

#include "integrator.h"
#include "integrator_methods.h"

#define RKN_STAGES 6

/* R = sqrt(8581); c2 = (209 - R)/900, c3 = (209 - R)/450, c4 = (209 + R)/450 */
static const double C[RKN_STAGES] = {
    0.0, 0.129295903136704415289, 0.258591806273408830578, 0.670297082615480058311, 0.9, 1.0};

/* a_ij, j < i:
 *   a21 = (26131 - 209 R)/810000,  a31 = (26131 - 209 R)/607500,  a32 = 2 a31,
 *   a41 = (980403512254 + 7781688431 R)/11694469921875,
 *   a42 = -(1262884486208 + 15385481287 R)/11694469921875,
 *   a43 = (7166233891441 + 78694563299 R)/46777879687500,
 *   a51 = -9 (329260 + 3181 R)/27040000,  a52 = 27 (35129 + 3331 R)/13520000,
 *   a53 = -27 (554358343 + 31040327 R)/464060480000,
 *   a54 = 153 (8555257 - 67973 R)/2745920000,  a6j = b_j. */
static const double A[RKN_STAGES][RKN_STAGES] = {
    {0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.00835871528396802532822, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.0111449537119573671043, 0.0222899074239147342086, 0.0, 0.0, 0.0, 0.0},
    {0.145474742801091785896, -0.22986064052264747312, 0.309034987202967536529, 0.0, 0.0, 0.0},
    {-0.207668262950789954335, 0.686366784292514312274, -0.199549277872349252201,
     0.125850756530624894263, 0.0, 0.0},
    {0.0781101614434947768281, 0.0, 0.288291741189766777684, 0.122425537174570410182,
     0.0111725601921680353053, 0.0}};

/* b = (329/4212, 0, (84119543 + 366727 R)/409622616, (84119543 - 366727 R)/409622616,
 *      200/17901, 0) */
static const double B[RKN_STAGES] = {
    0.0781101614434947768281, 0.0, 0.288291741189766777684, 0.122425537174570410182,
    0.0111725601921680353053, 0.0};
/* bp = (329/4212, 0, (389225579 + 96856 R)/1024056540, (389225579 - 96856 R)/1024056540,
 *       2000/17901, 1/20) */
static const double BP[RKN_STAGES] = {
    0.0781101614434947768281, 0.0, 0.388843478705982602716, 0.371320757928842267403,
    0.111725601921680353053, 0.05};
/* error weights b - bhat, bp - bphat, with the embedded 4th-order formula
 * bhat = ((2701 + 23 R)/4563, -(9829 + 131 R)/9126, 5 (1798 + 17 R)/9126, 0, 0, 0),
 * bphat = (115/2106, 0, (84119543 + 366727 R)/256014135, (84119543 - 366727 R)/256014135,
 *          6950/17901, -1/10) */
static const double EB[RKN_STAGES] = {
    -0.980749098926923501392, 2.40675137192445205319, -1.55960037036426699729,
    0.122425537174570410182, 0.0111725601921680353053, 0.0};
static const double EBP[RKN_STAGES] = {
    0.0235042735042735042735, 0.0, -0.0724233071976442415787, 0.175439898449529611111,
    -0.276520864756158873806, 0.15};

/* dense output: b_i(s) = sum_k R_[i][k] s^k, bp_i(s) = sum_k RP[i][k] s^k.
 *   b_1 = (2106 - 5244 s + 6386 s^2 - 3819 s^3 + 900 s^4)/4212,
 *   b_3, b_4 = s (18 (81356461 +- 25954829 R) + (22190560391 -+ 1109665151 R) s
 *              - 6 (4929647204 -+ 156109769 R) s^2 + 1800 (5860823 -+ 152228 R) s^3)
 *              / 22529243880,
 *   b_5 = 200 s (195 - 620 s + 651 s^2 - 225 s^3)/17901,
 *   b_6 = s (-234 + 757 s - 823 s^2 + 300 s^3)/220,
 *   bp_1 = 1 - (15732 s - 25544 s^2 + 19095 s^3 - 5400 s^4)/4212,
 *   bp_3, bp_4 = s (27 (81356461 +- 25954829 R) + 2 (22190560391 -+ 1109665151 R) s
 *               - 15 (4929647204 -+ 156109769 R) s^2 + 5400 (5860823 -+ 152228 R) s^3)
 *               / 11264621940,
 *   bp_5 = 1000 s (117 - 496 s + 651 s^2 - 270 s^3)/17901,
 *   bp_6 = s (-702 + 3028 s - 4115 s^2 + 1800 s^3)/220. */
static const double R_[RKN_STAGES][5] = {
    {0.5, -1.24501424501424501425, 1.51614434947768281102, -0.906695156695156695157,
     0.213675213675213675214},
    {0.0, 0.0, 0.0, 0.0, 0.0},
    {0.0, 1.98593719887050319851, -3.57765287229492094385, 2.53840111641095035556,
     -0.658393701796765832534},
    {0.0, -1.85593582769266143243, 5.54758675105232911303, -5.16413355390809373506,
     1.59490816772299646465},
    {0.0, 2.17864923747276688453, -6.92698731914418188928, 7.27333668510139098374,
     -2.51382604323780794369},
    {0.0, -1.06363636363636363636, 3.44090909090909090909, -3.74090909090909090909,
     1.36363636363636363636}};
static const double RP[RKN_STAGES][5] = {
    {1.0, -3.73504273504273504274, 6.06457739791073124406, -4.53347578347578347578,
     1.28205128205128205128},
    {0.0, 0.0, 0.0, 0.0, 0.0},
    {0.0, 5.95781159661150959554, -14.3106114891796837754, 12.6920055820547517778,
     -3.9503622107805949952},
    {0.0, -5.5678074830779842973, 22.1903470042093164521, -25.8206677695404686753,
     9.56944900633797878788},
    {0.0, 6.53594771241830065359, -27.7079492765767275571, 36.3666834255069549187,
     -15.0829562594268476621},
    {0.0, -3.19090909090909090909, 13.7636363636363636364, -18.7045454545454545455,
     8.18181818181818181818}};

void integ_rkn_start(Integrator *it)
{
    it->h = integ_initial_step(it, 5);
}

int integ_rkn_step(Integrator *it)
{
    const double x0 = it->y[0], v0 = it->y[1];
    double k[RKN_STAGES];
    k[0] = it->f[1];   /* FSAL: f(x0) from the previous step */

    for (;;) {
        const double h = it->h;
        if (!(h >= integ_hmin(it->t)) || !isfinite(h))
            return -1;   /* step-size underflow */
        for (int i = 1; i < RKN_STAGES; i++) {
            double s = 0.0;
            for (int j = 0; j < i; j++)
                s += A[i][j] * k[j];
            k[i] = integ_accel(it, x0 + h * (C[i] * v0 + h * s));
        }
        /* stage 6 was evaluated at x1 (a6j = b_j), so x1 is recomputed identically */
        double sx = 0.0, sv = 0.0, ex = 0.0, ev = 0.0;
        for (int i = 0; i < RKN_STAGES; i++) {
            sx += B[i] * k[i];
            sv += BP[i] * k[i];
            ex += EB[i] * k[i];
            ev += EBP[i] * k[i];
        }
        double y1[2] = {x0 + h * (v0 + h * sx), v0 + h * sv};
        double e[2] = {h * h * ex, h * ev};
        double err = integ_err_norm(it, e, it->y, y1);
        if (!isfinite(err) || !isfinite(y1[0]) || !isfinite(y1[1]))
            return -1;

        int accept;
        double hnew = integ_control(it, h, err, 5, &accept);
        if (!accept) {
            it->h = hnew;
            continue;
        }
        for (int i = 0; i < RKN_STAGES; i++)
            it->dense[i][0] = k[i];
        double f1[2] = {y1[1], k[RKN_STAGES - 1]};
        double y1_unprojected[2] = {y1[0], y1[1]};
        integ_project(it, it->y, y1, f1);
        /* the interpolant is shifted by s (y1 - y1_unprojected), so it ends where the next
         * step starts (a change of the order of the local error) */
        it->dense[RKN_STAGES][0] = y1[0] - y1_unprojected[0];
        it->dense[RKN_STAGES][1] = y1[1] - y1_unprojected[1];
        integ_accept(it, h, y1, f1);
        it->h = hnew;
        return 0;
    }
}

void integ_rkn_interp(const Integrator *it, double t, double y[2])
{
    const double h = it->h_last;
    const double s = (t - it->t_prev) / h;
    double sx = 0.0, sv = 0.0;
    for (int i = 0; i < RKN_STAGES; i++) {
        const double *r = R_[i], *rp = RP[i];
        double bi = r[0] + s * (r[1] + s * (r[2] + s * (r[3] + s * r[4])));
        double bpi = rp[0] + s * (rp[1] + s * (rp[2] + s * (rp[3] + s * rp[4])));
        sx += bi * it->dense[i][0];
        sv += bpi * it->dense[i][0];
    }
    const double sh = s * h;
    y[0] = it->y_prev[0] + sh * (it->y_prev[1] + sh * sx) + s * it->dense[RKN_STAGES][0];
    y[1] = it->y_prev[1] + sh * sv + s * it->dense[RKN_STAGES][1];
}
