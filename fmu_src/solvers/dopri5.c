/* dopri5.c: Dormand-Prince 5(4) with FSAL, PI step-size control and 4th-order dense output.
 *
 * Coefficients: J. R. Dormand, P. J. Prince, "A family of embedded Runge-Kutta formulae",
 * J. Comput. Appl. Math. 6 (1980) 19-26 (RK5(4)7M), as tabulated in Hairer, Norsett &
 * Wanner, Solving ODEs I (2nd ed.), Table II.5.2. Dense output: Shampine's continuous
 * extension, HNW I, II.6 (6.12)-(6.13), in the form of Hairer's DOPRI5 code (CONTD5).
 * Checked: one step on the pendulum against a 40-digit mpmath solution gives local
 * errors O(h^6) for the 5th-order solution, O(h^5) for the embedded one and for the dense
 * output; tests/c/test_integrators.c observes global order 5.0 at a constant step. */
#include <math.h>

#include "integrator.h"
#include "integrator_core.h"
#include "methods.h"

/* nodes c_i */
#define C2 (1.0 / 5.0)
#define C3 (3.0 / 10.0)
#define C4 (4.0 / 5.0)
#define C5 (8.0 / 9.0)
/* a_ij */
#define A21 (1.0 / 5.0)
#define A31 (3.0 / 40.0)
#define A32 (9.0 / 40.0)
#define A41 (44.0 / 45.0)
#define A42 (-56.0 / 15.0)
#define A43 (32.0 / 9.0)
#define A51 (19372.0 / 6561.0)
#define A52 (-25360.0 / 2187.0)
#define A53 (64448.0 / 6561.0)
#define A54 (-212.0 / 729.0)
#define A61 (9017.0 / 3168.0)
#define A62 (-355.0 / 33.0)
#define A63 (46732.0 / 5247.0)
#define A64 (49.0 / 176.0)
#define A65 (-5103.0 / 18656.0)
/* 5th-order weights b_i (= a_7i: the 7th stage is f at the new point, FSAL) */
#define B1 (35.0 / 384.0)
#define B3 (500.0 / 1113.0)
#define B4 (125.0 / 192.0)
#define B5 (-2187.0 / 6784.0)
#define B6 (11.0 / 84.0)
/* e_i = b_i - bhat_i (bhat: the embedded 4th-order weights) */
#define E1 (71.0 / 57600.0)
#define E3 (-71.0 / 16695.0)
#define E4 (71.0 / 1920.0)
#define E5 (-17253.0 / 339200.0)
#define E6 (22.0 / 525.0)
#define E7 (-1.0 / 40.0)
/* dense output d_i (Shampine 1986, HNW I II.6) */
#define D1 (-12715105075.0 / 11282082432.0)
#define D3 (87487479700.0 / 32700410799.0)
#define D4 (-10690763975.0 / 1880347072.0)
#define D5 (701980252875.0 / 199316789632.0)
#define D6 (-1453857185.0 / 822651844.0)
#define D7 (69997945.0 / 29380423.0)

void integrator_dopri5_start(Integrator *it)
{
    it->h = integrator_initial_step(it, 5);
}

int integrator_dopri5_step(Integrator *it)
{
    const double *y = it->y;
    const double *k1 = it->f;   /* FSAL: f(t, y) from the previous step */
    double k2[2], k3[2], k4[2], k5[2], k6[2], k7[2], ys[2], y5[2], e[2];

    for (;;) {
        const double h = it->h;
        if (!(h >= integrator_hmin(it)) || !isfinite(h))
            return -1;   /* step-size underflow */
        for (int i = 0; i < 2; i++)
            ys[i] = y[i] + h * A21 * k1[i];
        integrator_rhs(it, ys, k2);
        for (int i = 0; i < 2; i++)
            ys[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i]);
        integrator_rhs(it, ys, k3);
        for (int i = 0; i < 2; i++)
            ys[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
        integrator_rhs(it, ys, k4);
        for (int i = 0; i < 2; i++)
            ys[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
        integrator_rhs(it, ys, k5);
        for (int i = 0; i < 2; i++)
            ys[i] = y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] +
                                A65 * k5[i]);
        integrator_rhs(it, ys, k6);
        for (int i = 0; i < 2; i++)
            y5[i] = y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] +
                                B6 * k6[i]);
        integrator_rhs(it, y5, k7);
        for (int i = 0; i < 2; i++)
            e[i] = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] +
                        E7 * k7[i]);
        double err = integrator_err_norm(it, e, y, y5);
        if (!isfinite(err) || !isfinite(y5[0]) || !isfinite(y5[1]))
            return -1;

        int accept;
        double hnew = integrator_control(it, h, err, 5, 0.9, &accept);
        if (!accept) {
            it->h = hnew;
            continue;
        }

        /* dense output (HNW CONTD5): r1 = y0, r2 = y1 - y0, r3 = h k1 - r2,
         * r4 = r2 - h k7 - r3, r5 = h sum d_i k_i; then
         * u(s) = r1 + s (r2 + (1-s) (r3 + s (r4 + (1-s) r5))).
         * r5 uses the stages of the step; r2 and r4 use the end point after the energy
         * projection and f there, so the interpolant ends where the next step starts, with
         * its slope (a change of the order of the local error). */
        for (int i = 0; i < 2; i++)
            it->dense[4][i] = h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] +
                                   D6 * k6[i] + D7 * k7[i]);
        if (it->project_energy) {
            double trig[2];
            integrator_project(it, y, y5, k7, trig);
        }
        for (int i = 0; i < 2; i++) {
            double r2 = y5[i] - y[i];
            double r3 = h * k1[i] - r2;
            it->dense[0][i] = y[i];
            it->dense[1][i] = r2;
            it->dense[2][i] = r3;
            it->dense[3][i] = r2 - h * k7[i] - r3;
        }
        integrator_accept(it, h, y5, k7);
        it->h = hnew;
        return 0;
    }
}

void integrator_dopri5_interp(const Integrator *it, double s, double y[2])
{
    const double s1 = 1.0 - s;
    for (int i = 0; i < 2; i++)
        y[i] = it->dense[0][i] +
               s * (it->dense[1][i] +
                    s1 * (it->dense[2][i] + s * (it->dense[3][i] + s1 * it->dense[4][i])));
}
