/* test_exact_sin_cos.c: pendulum_exact_sin_cos, the sine and cosine of the exact angle formed
 * from the elliptic functions of the half angle (the output derivatives' source):
 *  - wherever the rounded theta is good enough, it agrees with sin and cos of
 *    pendulum_exact_eval's theta, in every regime, both directions, every quarter period
 *    (a wrong sign or quarter would show as an error of order 1), and sin^2 + cos^2 = 1;
 *  - released at rest within ulps of the top (theta0 = pi as a double), it follows the
 *    linearised motion about the top, sin theta(t) = sin(theta0) cosh(w0 t) to O(sin^3),
 *    relative to its own tiny size, where sin of the rounded theta is off by 10 % or more. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "exact.h"

static void test_agrees_with_the_rounded_angle(void)
{
    const double thetas[] = {0.0, 0.3, -1.2, 2.9, -3.1, 1e3 + 0.25};
    const double speeds[] = {0.0, 0.5, -1.7, 1.999, 2.0 + 1e-9, -2.3, 7.0, -40.0};   /* omega0 / w0 */
    const double w0s[] = {1.0, 3.1, 1e-3, 1e3};
    int n = 0, worst_case = 0;
    double worst = 0.0, worst_unit = 0.0;
    for (size_t a = 0; a < sizeof thetas / sizeof thetas[0]; ++a) {
        for (size_t b = 0; b < sizeof speeds / sizeof speeds[0]; ++b) {
            for (size_t c = 0; c < sizeof w0s / sizeof w0s[0]; ++c) {
                PendulumExact ex;
                const double w0 = w0s[c];
                if (pendulum_exact_init(&ex, thetas[a], speeds[b] * w0, w0, 0.5) != 0) {
                    check(0, "init failed");
                    continue;
                }
                for (int i = 1; i <= 40; ++i) {
                    const double t = 0.5 + 0.37 * i / w0;   /* 15 w0-units: every quarter */
                    double theta, omega, s, co;
                    pendulum_exact_eval(&ex, t, &theta, &omega);
                    pendulum_exact_sin_cos(&ex, t, &s, &co);
                    /* sin of the rounded theta is off by ~ulp(theta) + the eval's own error */
                    const double allowed = 1e-14 * fmax(1.0, fabs(theta));
                    const double error = fmax(fabs(s - sin(theta)), fabs(co - cos(theta)));
                    const double unit = fabs(s * s + co * co - 1.0);
                    if (error / allowed > worst) {
                        worst = error / allowed;
                        worst_case = n;
                    }
                    worst_unit = fmax(worst_unit, unit);
                    check(error <= allowed, "theta0 %g, omega0 %g w0, w0 %g, t %g: sin/cos off by %.2e",
                          thetas[a], speeds[b], w0, t, error);
                    ++n;
                }
            }
        }
    }
    check(worst_unit <= 1e-15, "sin^2 + cos^2 - 1 up to %.1e", worst_unit);
    printf("test_exact_sin_cos: %d states x times, worst |error| / allowance %.2f (case %d), "
           "max |sin^2 + cos^2 - 1| %.1e\n", n, worst, worst_case, worst_unit);
}

static void test_relative_accuracy_next_to_the_top(void)
{
    const double w0s[] = {1.0, 3.1320919526731652, 1e6, 1e-6};
    double worst = 0.0;
    for (size_t c = 0; c < sizeof w0s / sizeof w0s[0]; ++c) {
        PendulumExact ex;
        const double w0 = w0s[c];
        check(pendulum_exact_init(&ex, PI, 0.0, w0, 0.0) == 0, "init at the top");
        for (int i = 1; i <= 10; ++i) {
            const double t = 1.5 * i / w0;    /* sin theta stays below 1e-9: linear to 1e-18 */
            double s, co, theta, omega;
            pendulum_exact_sin_cos(&ex, t, &s, &co);
            pendulum_exact_eval(&ex, t, &theta, &omega);
            const double expected = sin(PI) * cosh(w0 * t);
            const double relative = fabs(s - expected) / expected;
            worst = fmax(worst, relative);
            check(relative <= 1e-13, "w0 %g, w0 t %g: sin theta %.17g, linearised %.17g", w0, w0 * t, s, expected);
            check(co < 0.0 && fabs(co + 1.0) < 1e-15, "cos theta next to -1");
        }
    }
    printf("test_exact_sin_cos: released at pi, worst relative error of sin theta %.1e\n", worst);
}

int main(void)
{
    test_agrees_with_the_rounded_angle();
    test_relative_accuracy_next_to_the_top();
    return check_summary("test_exact_sin_cos");
}
