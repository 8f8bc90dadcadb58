/* test_exact.c: checks of fmu_src/math/exact.{h,c}, the exact solution of theta'' + w0^2 sin theta = 0.
 *
 * Tabulated values were generated once with mpmath 1.4.1 at 50 significant digits from the
 * closed form (documentation/math.html: libration 2 atan2(k sn u, dn u), rotation 2 am(v | 1/m),
 * separatrix 2 atan(sinh u); mpmath's ellipfun, ellipk, ellipf with the argument reduced by
 * the period in mpmath), at the same binary inputs (theta0, omega0, w0 = sqrt(g/L) rounded
 * as in the FMU, t0, t), and printed with 17 significant digits. The same closed form is
 * checked against mpmath.odefun (Taylor integration of the ODE) in tests/exact/test_exact_mpmath.py.
 * Prints one summary line; exit status 0 iff every check passed. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "exact.h"
#include "check.h"


static PendulumExact make(double theta0, double omega0, double w0, double t0)
{
    PendulumExact ex;
    int status = pendulum_exact_init(&ex, theta0, omega0, w0, t0);
    check(status == 0, "pendulum_exact_init(%.17g, %.17g, %.17g, %g) = %d", theta0, omega0, w0, t0, status);
    return ex;
}

/* {theta0, omega0, w0, t0, t, theta(t), omega(t), period}: the cases are, in order,
 * 10 deg (g = 9.81, L = 1); 90 deg (L = 2) posed at t0 = 12.5; 170 deg (w0 = 1); a moving
 * start; pi - 1e-12 and pi + 1e-12 at rest (the latter falls to the other side: theta
 * continues from theta0 towards 3 pi); theta0 = 20 rad; the separatrix both ways
 * (omega0 = 2 w0 exactly); rotation both ways; fast rotation; libration and rotation
 * 1e-12 below and above the separatrix; creeping over the top from theta0 = pi; and
 * 170 deg after 1e6 periods (t = 1e6 * 4K in double, and 3.3 s later). */
static const double SOLUTION_TABLE[][8] = {
    {0.17453292519943295, 0.0, 3.132091952673165, 0.0, 0.0, 0.17453292519943295, -5.7832497770282934e-52, 2.0098926272986004},  /* 10 deg */
    {0.17453292519943295, 0.0, 3.132091952673165, 0.0, 0.3, 0.10328444861843641, -0.4399033634946644, 2.0098926272986004},  /* 10 deg */
    {0.17453292519943295, 0.0, 3.132091952673165, 0.0, 1.7, 0.09888385435179495, 0.4496973181314743, 2.0098926272986004},  /* 10 deg */
    {0.17453292519943295, 0.0, 3.132091952673165, 0.0, 5.0, -0.17401221188695273, -0.042088464340871413, 2.0098926272986004},  /* 10 deg */
    {1.5707963267948966, 0.0, 2.2147234590350102, 12.5, 12.5, 1.5707963267948966, -1.9521727037479612e-52, 3.3486341958182377},  /* 90 deg t0 */
    {1.5707963267948966, 0.0, 2.2147234590350102, 12.5, 13.0, 0.9652130311541911, -2.363104204807239, 3.3486341958182377},  /* 90 deg t0 */
    {1.5707963267948966, 0.0, 2.2147234590350102, 12.5, 14.2, -1.5691786298308272, 0.1259746017889198, 3.3486341958182377},  /* 90 deg t0 */
    {1.5707963267948966, 0.0, 2.2147234590350102, 12.5, 20.0, 0.10772395832747403, -3.1230009909070806, 3.3486341958182377},  /* 90 deg t0 */
    {2.9670597283903604, 0.0, 1.0, 0.0, 0.0, 2.9670597283903604, -7.657670400768193e-52, 15.326967999136587},  /* 170 deg */
    {2.9670597283903604, 0.0, 1.0, 0.0, 3.0, 1.4935170753716567, -1.4574018716336463, 15.326967999136587},  /* 170 deg */
    {2.9670597283903604, 0.0, 1.0, 0.0, 7.7, -2.966943942892982, 0.006342324791432612, 15.326967999136587},  /* 170 deg */
    {2.9670597283903604, 0.0, 1.0, 0.0, 40.0, -2.6594212820424143, 0.4445618396423042, 15.326967999136587},  /* 170 deg */
    {0.3, -1.2, 2.0, 0.0, 0.0, 0.3, -1.2, 3.2358684838890275},  /* moving */
    {0.3, -1.2, 2.0, 0.0, 0.4, -0.2210632993031465, -1.2659490200325179, 3.2358684838890275},  /* moving */
    {0.3, -1.2, 2.0, 0.0, 2.0, 0.19822318463094363, 1.2808795108981146, 3.2358684838890275},  /* moving */
    {0.3, -1.2, 2.0, 0.0, 9.0, 0.6620976609843112, 0.3270216379597211, 3.2358684838890275},  /* moving */
    {3.141592653588793, 0.0, 3.132091952673165, 0.0, 0.0, 3.141592653588793, -3.161967492384958e-51, 37.94301286630315},  /* pi-1e-12 */
    {3.141592653588793, 0.0, 3.132091952673165, 0.0, 5.0, 3.1415894890318743, -9.91168639156615e-06, 37.94301286630315},  /* pi-1e-12 */
    {3.141592653588793, 0.0, 3.132091952673165, 0.0, 9.5, -0.08921486973190934, -6.2579526293367165, 37.94301286630315},  /* pi-1e-12 */
    {3.141592653588793, 0.0, 3.132091952673165, 0.0, 20.0, -3.14159265357724, 3.9193397795320135e-11, 37.94301286630315},  /* pi-1e-12 */
    {3.141592653588793, 0.0, 3.132091952673165, 0.0, 37.9, 3.141592653588784, 4.23323219802459e-13, 37.94301286630315},  /* pi-1e-12 */
    {3.141592653590793, 0.0, 3.132091952673165, 0.0, 0.0, 3.141592653590793, -3.161967492358661e-51, 37.94332563820427},  /* pi+1e-12 */
    {3.141592653590793, 0.0, 3.132091952673165, 0.0, 5.0, 3.141595817372783, 9.909259241578631e-06, 37.94332563820427},  /* pi+1e-12 */
    {3.141592653590793, 0.0, 3.132091952673165, 0.0, 9.5, 6.371910846309132, 6.258020785984775, 37.94332563820427},  /* pi+1e-12 */
    {3.141592653590793, 0.0, 3.132091952673165, 0.0, 20.0, 9.424777960756835, -3.9164550876755595e-11, 37.94332563820427},  /* pi+1e-12 */
    {20.0, 0.3, 1.7, 0.0, 0.0, 20.0, 0.3, 4.037849248130193},  /* theta0=20 */
    {20.0, 0.3, 1.7, 0.0, 1.0, 19.077639325152475, -1.8334646509531083, 4.037849248130193},  /* theta0=20 */
    {20.0, 0.3, 1.7, 0.0, 3.3, 19.14294458524302, 1.8067381374191678, 4.037849248130193},  /* theta0=20 */
    {0.0, 6.26418390534633, 3.132091952673165, 0.0, 0.0, 0.0, 6.26418390534633, INFINITY},  /* sep + */
    {0.0, 6.26418390534633, 3.132091952673165, 0.0, 0.5, 2.317956144894546, 2.5074038993559435, INFINITY},  /* sep + */
    {0.0, 6.26418390534633, 3.132091952673165, 0.0, 1.0, 2.967197488488433, 0.5455297642903826, INFINITY},  /* sep + */
    {0.0, 6.26418390534633, 3.132091952673165, 0.0, 3.0, 3.1412605227261787, 0.001040264400380102, INFINITY},  /* sep + */
    {0.0, 6.26418390534633, 3.132091952673165, 0.0, 300.0, 3.141592653589793, 0.0, INFINITY},  /* sep + */
    {0.0, -6.26418390534633, 3.132091952673165, 0.0, 0.0, 0.0, -6.26418390534633, INFINITY},  /* sep - */
    {0.0, -6.26418390534633, 3.132091952673165, 0.0, 0.5, -2.317956144894546, -2.5074038993559435, INFINITY},  /* sep - */
    {0.0, -6.26418390534633, 3.132091952673165, 0.0, 3.0, -3.1412605227261787, -0.001040264400380102, INFINITY},  /* sep - */
    {0.5, 2.5, 1.0, 0.0, 0.0, 0.5, 2.5, 3.087464122439551},  /* rot + */
    {0.5, 2.5, 1.0, 0.0, 1.0, 2.5838239285825835, 1.6727099059107406, 3.087464122439551},  /* rot + */
    {0.5, 2.5, 1.0, 0.0, 4.0, 8.718527025107498, 1.724306893023199, 3.087464122439551},  /* rot + */
    {0.5, 2.5, 1.0, 0.0, 30.0, 61.218487016036995, 2.099933601487862, 3.087464122439551},  /* rot + */
    {0.5, -2.5, 1.0, 0.0, 0.0, 0.5, -2.5, 3.087464122439551},  /* rot - */
    {0.5, -2.5, 1.0, 0.0, 1.0, -1.8688333188362132, -1.9767514425207313, 3.087464122439551},  /* rot - */
    {0.5, -2.5, 1.0, 0.0, 4.0, -7.975411447540152, -2.0621764339728728, 3.087464122439551},  /* rot - */
    {0.5, -2.5, 1.0, 0.0, 30.0, -60.46233111015858, -1.74982844200263, 3.087464122439551},  /* rot - */
    {-1.0, -100.0, 1.2909944487358056, 0.0, 0.0, -1.0, -100.0, 0.06283751317827528},  /* rot fast */
    {-1.0, -100.0, 1.2909944487358056, 0.0, 0.01, -1.999921253987627, -99.98405910381284, 0.06283751317827528},  /* rot fast */
    {-1.0, -100.0, 1.2909944487358056, 0.0, 0.5, -50.9954671278386, -100.00341464702147, 0.06283751317827528},  /* rot fast */
    {0.0, 1.999999999998, 1.0, 0.0, 0.0, -3.63317623363248e-56, 1.999999999998, 59.4209695591751},  /* near sep lib */
    {0.0, 1.999999999998, 1.0, 0.0, 5.0, 3.114641273377833, 0.0269505643684547, 59.4209695591751},  /* near sep lib */
    {0.0, 1.999999999998, 1.0, 0.0, 15.0, 3.1415897955079832, -4.10863246064026e-07, 59.4209695591751},  /* near sep lib */
    {0.0, 1.999999999998, 1.0, 0.0, 50.0, -3.141268617659504, 0.00032402358459931194, 59.4209695591751},  /* near sep lib */
    {0.0, 2.000000000002, 1.0, 0.0, 0.0, -3.63308105790756e-56, 2.000000000002, 29.71037376096311},  /* near sep rot */
    {0.0, 2.000000000002, 1.0, 0.0, 5.0, 3.114641273526379, 0.02695056451677176, 29.71037376096311},  /* near sep rot */
    {0.0, 2.000000000002, 1.0, 0.0, 15.0, 3.141593064634506, 2.858263277021071e-06, 29.71037376096311},  /* near sep rot */
    {0.0, 2.000000000002, 1.0, 0.0, 50.0, 9.425102056310743, 0.0003241078828463917, 29.71037376096311},  /* near sep rot */
    {3.141592653589793, 1e-10, 1.0, 0.0, 0.0, 3.141592653589793, 1e-10, 50.21058494324208},  /* creep over top */
    {3.141592653589793, 1e-10, 1.0, 0.0, 10.0, 3.141593754911732, 1.1013219432782101e-06, 50.21058494324208},  /* creep over top */
    {3.141592653589793, 1e-10, 1.0, 0.0, 25.0, 6.072985961645985, 1.9889642227760882, 50.21058494324208},  /* creep over top */
    {3.141592653589793, 1e-10, 1.0, 0.0, 60.0, 9.424778852961557, 8.921921834725715e-07, 50.21058494324208},  /* creep over top */
    {2.9670597283903604, 0.0, 1.0, 0.0, 15326967.999136586, 2.9670597283903604, 1.483424353953936e-10, 15.326967999136587},  /* 170 deg after 1e6 periods */
    {2.9670597283903604, 0.0, 1.0, 0.0, 15326971.299136586, 1.0127551250874962, -1.7403064851215995, 15.326967999136587},  /* 170 deg after 1e6 periods */
};

static void test_solution_table(void)
{
    for (size_t i = 0; i < sizeof SOLUTION_TABLE / sizeof SOLUTION_TABLE[0]; ++i) {
        const double *row = SOLUTION_TABLE[i];
        PendulumExact ex = make(row[0], row[1], row[2], row[3]);
        double theta, omega;
        pendulum_exact_eval(&ex, row[4], &theta, &omega);
        const int long_run = row[4] > 1e6;
        /* 5e-14 rad (plus the rounding of a wound-up theta); 1e-10 after 1e6 periods */
        const double theta_tol = long_run ? 1e-10 : 5e-14 + 4e-16 * fabs(row[5]);
        const double omega_tol = long_run ? 1e-10 : 5e-14 * fmax(fabs(row[1]), 2.0 * row[2]);
        check(fabs(theta - row[5]) <= theta_tol, "theta(%g) for (%.17g, %.17g, w0=%.17g): %.17g, ref %.17g",
              row[4], row[0], row[1], row[2], theta, row[5]);
        check(fabs(omega - row[6]) <= omega_tol, "omega(%g) for (%.17g, %.17g, w0=%.17g): %.17g, ref %.17g",
              row[4], row[0], row[1], row[2], omega, row[6]);
        const double period = pendulum_exact_period(&ex);
        if (isinf(row[7])) {
            check(isinf(period) && period > 0.0 && ex.regime == PENDULUM_SEPARATRIX,
                  "separatrix: period %g, regime %d", period, (int)ex.regime);
        } else {
            check(fabs(period - row[7]) <= 4.5e-16 * row[7], "period for (%.17g, %.17g): %.17g, ref %.17g",
                  row[0], row[1], period, row[7]);
        }
    }
}

static void test_invalid_input(void)
{
    PendulumExact ex, untouched;
    memset(&ex, 0xA5, sizeof ex);
    memcpy(&untouched, &ex, sizeof ex);
    check(pendulum_exact_init(&ex, NAN, 0.0, 1.0, 0.0) == -1, "theta0 NaN rejected");
    check(pendulum_exact_init(&ex, INFINITY, 0.0, 1.0, 0.0) == -1, "theta0 inf rejected");
    check(pendulum_exact_init(&ex, 0.1, -INFINITY, 1.0, 0.0) == -1, "omega0 -inf rejected");
    check(pendulum_exact_init(&ex, 0.1, 0.0, 0.0, 0.0) == -1, "w0 = 0 rejected");
    check(pendulum_exact_init(&ex, 0.1, 0.0, -2.0, 0.0) == -1, "w0 < 0 rejected");
    check(pendulum_exact_init(&ex, 0.1, 0.0, NAN, 0.0) == -1, "w0 NaN rejected");
    check(pendulum_exact_init(&ex, 0.1, 0.0, INFINITY, 0.0) == -1, "w0 inf rejected");
    check(pendulum_exact_init(&ex, 0.1, 0.0, 1.0, NAN) == -1, "t0 NaN rejected");
    check(pendulum_exact_init(NULL, 0.1, 0.0, 1.0, 0.0) == -1, "NULL rejected");
    check(memcmp(&ex, &untouched, sizeof ex) == 0, "a rejected init leaves the struct untouched");
}

/* At rest at the bottom: theta = omega = 0 exactly at every time (no 0/0 anywhere). */
static void test_rest(void)
{
    static const double times[] = {0.0, 1.0, -5.0, 1e6, 1e12, 3.7e15};
    static const double zeros[] = {0.0, -0.0};
    for (int z = 0; z < 2; ++z) {
        PendulumExact ex = make(zeros[z], 0.0, 3.13, 0.0);
        check(ex.regime == PENDULUM_LIBRATION && pendulum_exact_period(&ex) == 2.0 * PI / 3.13,
              "rest: libration with the small-angle period");
        for (size_t i = 0; i < sizeof times / sizeof times[0]; ++i) {
            double theta, omega;
            pendulum_exact_eval(&ex, times[i], &theta, &omega);
            check(theta == 0.0 && omega == 0.0, "rest at t=%g: theta %g omega %g", times[i], theta, omega);
        }
    }
}

/* Tiny amplitudes: the linear solution theta0 cos(w0 t) + omega0/w0 sin(w0 t) to relative
 * accuracy (the nonlinear correction is O(theta0^2), far below rounding here). */
static void test_tiny_amplitudes(void)
{
    static const double amplitudes[] = {1e-8, 1e-100, 1e-300};
    const double w0 = 2.5;
    for (size_t i = 0; i < sizeof amplitudes / sizeof amplitudes[0]; ++i) {
        const double a = amplitudes[i];
        PendulumExact ex = make(a, -0.5 * a * w0, w0, 0.0);
        for (int j = 0; j < 50; ++j) {
            const double t = 0.173 * j;
            double theta, omega;
            pendulum_exact_eval(&ex, t, &theta, &omega);
            const double lin = a * cos(w0 * t) - 0.5 * a * sin(w0 * t);
            const double lin_omega = -a * w0 * sin(w0 * t) - 0.5 * a * w0 * cos(w0 * t);
            check(fabs(theta - lin) <= 2e-15 * a, "tiny %g at t=%g: theta %.17g, linear %.17g", a, t, theta, lin);
            check(fabs(omega - lin_omega) <= 2e-15 * a * w0, "tiny %g at t=%g: omega %.17g, linear %.17g", a, t,
                  omega, lin_omega);
        }
    }
}

/* Regimes on both sides of the separatrix, at theta0 = 0 where omega0 = 2 w0 is exact. */
static void test_regimes(void)
{
    const double w0 = sqrt(9.81);
    const double on = 2.0 * w0, below = nextafter(on, 0.0), above = nextafter(on, INFINITY);
    check(make(0.0, on, w0, 0.0).regime == PENDULUM_SEPARATRIX, "omega0 = 2 w0: separatrix");
    check(make(0.0, -on, w0, 0.0).regime == PENDULUM_SEPARATRIX, "omega0 = -2 w0: separatrix");
    check(make(0.0, below, w0, 0.0).regime == PENDULUM_LIBRATION, "omega0 just below 2 w0: libration");
    check(make(0.0, above, w0, 0.0).regime == PENDULUM_ROTATION, "omega0 just above 2 w0: rotation");
    check(make(PI, 0.0, w0, 0.0).regime == PENDULUM_LIBRATION, "theta0 = pi (the double) at rest: libration");
    check(make(3.0, -40.0, w0, 0.0).regime == PENDULUM_ROTATION, "fast: rotation");
    /* continuity across the border: the three motions agree while w0 t <= 3 */
    PendulumExact lib = make(0.0, below, w0, 0.0), sep = make(0.0, on, w0, 0.0), rot = make(0.0, above, w0, 0.0);
    for (int i = 0; i <= 100; ++i) {
        const double t = 3.0 / w0 * i / 100.0;
        double th_l, om_l, th_s, om_s, th_r, om_r;
        pendulum_exact_eval(&lib, t, &th_l, &om_l);
        pendulum_exact_eval(&sep, t, &th_s, &om_s);
        pendulum_exact_eval(&rot, t, &th_r, &om_r);
        check(fabs(th_l - th_s) <= 1e-12 && fabs(th_r - th_s) <= 1e-12, "continuity of theta at t=%g: %.3g %.3g",
              t, th_l - th_s, th_r - th_s);
        check(fabs(om_l - om_s) <= 1e-11 * w0 && fabs(om_r - om_s) <= 1e-11 * w0,
              "continuity of omega at t=%g: %.3g %.3g", t, om_l - om_s, om_r - om_s);
    }
    check(isinf(pendulum_exact_period(&sep)), "separatrix period is +inf");
    /* one ulp from the separatrix, m1 ~ 2e-16: 4K = 4 ln(4/k') ~ 78, 2K ~ 39 */
    check(pendulum_exact_period(&lib) * w0 > 70.0 && pendulum_exact_period(&rot) * w0 > 35.0,
          "periods diverge at the separatrix: %g %g", pendulum_exact_period(&lib), pendulum_exact_period(&rot));
}

/* Rotation: theta winds up continuously and monotonically, one turn per period. */
static void test_winding(void)
{
    static const double speeds[] = {2.5, -2.5, 2.0000001, -300.0};
    for (size_t i = 0; i < sizeof speeds / sizeof speeds[0]; ++i) {
        const double omega0 = speeds[i], theta0 = 0.5;
        PendulumExact ex = make(theta0, omega0, 1.0, 0.0);
        check(ex.regime == PENDULUM_ROTATION, "omega0 = %g rotates", omega0);
        const double period = pendulum_exact_period(&ex);
        double previous = theta0;
        int monotone = 1, small_steps = 1;
        for (int j = 1; j <= 4000; ++j) {
            double theta, omega;
            pendulum_exact_eval(&ex, 20.0 * period * j / 4000.0, &theta, &omega);
            monotone &= (theta - previous) * omega0 > 0.0;
            small_steps &= fabs(theta - previous) < 0.1;
            previous = theta;
        }
        check(monotone && small_steps, "omega0 = %g: theta monotone and continuous", omega0);
        const double turns = copysign(40.0 * PI, omega0);
        check(fabs(previous - (theta0 + turns)) <= 1e-13 * fabs(turns), "omega0 = %g: 20 turns give %.17g", omega0,
              previous - theta0);
    }
}

/* H = omega^2/2 + 2 w0^2 sin^2(theta/2) stays at its initial value. */
static void test_energy(void)
{
    static const double states[][3] = {
        {0.3, 0.0, 3.13}, {2.9, -0.4, 1.0}, {PI - 1e-12, 0.0, 3.13}, {-20.0, 1.5, 0.7},
        {0.0, 2.0, 1.0}, {1.0, 5.0, 2.0}, {3.0, -1e3, 0.1}, {PI, 1e-10, 1.0},
    };
    for (size_t i = 0; i < sizeof states / sizeof states[0]; ++i) {
        const double theta0 = states[i][0], omega0 = states[i][1], w0 = states[i][2];
        PendulumExact ex = make(theta0, omega0, w0, 0.0);
        const double h0 = 0.5 * omega0 * omega0 + 2.0 * w0 * w0 * pow(sin(0.5 * theta0), 2);
        double worst = 0.0;
        for (int j = 0; j < 500; ++j) {
            double theta, omega;
            pendulum_exact_eval(&ex, 0.731 * j / w0, &theta, &omega);
            const double h = 0.5 * omega * omega + 2.0 * w0 * w0 * pow(sin(0.5 * theta), 2);
            worst = fmax(worst, fabs(h - h0));
        }
        check(worst <= 2e-14 * (h0 + 2.0 * w0 * w0), "energy drift %.3g for state %zu", worst, i);
    }
}

/* theta(t0) = theta0 and omega(t0) = omega0 to rounding; release from rest is even in time. */
static void test_start_and_symmetry(void)
{
    static const double states[][4] = {
        {0.3, 0.0, 3.13, 0.0}, {2.9, -0.4, 1.0, 5.0}, {PI - 1e-12, 0.0, 3.13, -2.0}, {-20.0, 1.5, 0.7, 1e3},
        {0.0, 2.0, 1.0, 0.0}, {1.0, 5.0, 2.0, 0.25}, {3.0, -1e3, 0.1, 0.0}, {PI, 1e-10, 1.0, 7.0},
    };
    for (size_t i = 0; i < sizeof states / sizeof states[0]; ++i) {
        const double *s = states[i];
        PendulumExact ex = make(s[0], s[1], s[2], s[3]);
        double theta, omega;
        pendulum_exact_eval(&ex, s[3], &theta, &omega);
        check(fabs(theta - s[0]) <= 2.0 * DBL_EPSILON * fmax(1.0, fabs(s[0])), "theta(t0) = %.17g for %.17g", theta,
              s[0]);
        check(fabs(omega - s[1]) <= 4.0 * DBL_EPSILON * fmax(fabs(s[1]), s[2]), "omega(t0) = %.17g for %.17g", omega,
              s[1]);
    }
    static const double amplitudes[] = {0.1, 1.5, 3.0, PI - 1e-9};
    for (size_t i = 0; i < sizeof amplitudes / sizeof amplitudes[0]; ++i) {
        PendulumExact ex = make(amplitudes[i], 0.0, 1.7, 0.0);
        for (int j = 1; j < 40; ++j) {
            const double t = 0.61 * j;
            double th_p, om_p, th_m, om_m;
            pendulum_exact_eval(&ex, t, &th_p, &om_p);
            pendulum_exact_eval(&ex, -t, &th_m, &om_m);
            check(fabs(th_p - th_m) <= 1e-14 && fabs(om_p + om_m) <= 1e-14 * 1.7,
                  "time reversal at amplitude %g, t=%g: %.3g %.3g", amplitudes[i], t, th_p - th_m, om_p + om_m);
        }
    }
}

/* Far-away times: finite up to PENDULUM_EXACT_MAX_QUARTERS quarter periods, refused (NaN and
 * pendulum_exact_resolvable 0) beyond, except on the separatrix (always resolved). */
static void test_large_times(void)
{
    static const double states[][2] = {{1.0, 0.0}, {0.0, 2.0}, {0.0, 3.0}, {PI, 0.0}};
    static const double times[] = {1e9, -1e12, 1e15, 1e17, 1e300};
    for (size_t i = 0; i < sizeof states / sizeof states[0]; ++i) {
        PendulumExact ex = make(states[i][0], states[i][1], 1.0, 0.0);
        for (size_t j = 0; j < sizeof times / sizeof times[0]; ++j) {
            double theta, omega;
            pendulum_exact_eval(&ex, times[j], &theta, &omega);
            const int resolvable = pendulum_exact_resolvable(&ex, times[j]);
            const int expected = ex.regime == PENDULUM_SEPARATRIX || times[j] < 1e300;
            check(resolvable == expected, "state %zu at t=%g: resolvable %d", i, times[j], resolvable);
            check(resolvable ? isfinite(theta) && isfinite(omega) : isnan(theta) && isnan(omega),
                  "state %zu at t=%g: %g %g", i, times[j], theta, omega);
        }
    }
}

int main(void)
{
    test_solution_table();
    test_invalid_input();
    test_rest();
    test_tiny_amplitudes();
    test_regimes();
    test_winding();
    test_energy();
    test_start_and_symmetry();
    test_large_times();
    return check_summary("test_exact");
}
