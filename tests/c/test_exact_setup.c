/* test_exact_setup.c: invariants of the exact solution's set-up (fmu_src/math/exact.c,
 * elliptic.c) that no output shows directly:
 *  - every byte of a set-up is written (a struct filled with 0x00 and one filled with 0xFF
 *    before pendulum_exact_init_gl end up the same bytes), for every regime and either path of
 *    the set-up (from rest, moving);
 *  - pendulum_exact_init_gl forms w0 = sqrt(g / L) directly for g and L within 2^+-400 and
 *    with powers of two outside: scaling g and L by the same power of 4 (into the other path)
 *    changes no byte of the set-up but the recorded g and L;
 *  - K and the rate in quarter periods agree to double-double accuracy: rho K = the rate of the
 *    elliptic argument (w0, or sqrt(m) w0 in rotation) within 1e-30 relative, and the period
 *    is 4 K / w0 (2 K / rate in rotation) rounded to nearest.
 * Over random states of every regime (seeded). Prints one summary line; exit status 0 iff
 * every check passed. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "exact.h"
#include "check.h"

static unsigned long long rng_state = 0x0DDB1A5E5BAD5EEDULL;

static double uniform(void)   /* xorshift64*, [0, 1) */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-53;
}

/* A random state of kind i mod 8 for w0: from rest (any angle, next to the top, beyond pi, tiny),
 * moving libration, rotation, next to the separatrix, wound up. */
static void draw_state(long i, double w0, double *theta0, double *omega0)
{
    const double th = (2.0 * uniform() - 1.0) * PI, edge = 2.0 * w0 * cos(th / 2);
    *omega0 = 0.0;
    switch (i % 8) {
    case 0: *theta0 = th; break;
    case 1: *theta0 = (uniform() < 0.5 ? -PI : PI) * (1.0 - pow(10.0, -1.0 - 15.0 * uniform())); break;
    case 2: *theta0 = PI + 0.058 * uniform(); break;   /* just past pi: moved by a turn */
    case 3: *theta0 = th * pow(10.0, -12.0 * uniform()); break;
    case 4: *theta0 = th; *omega0 = (2.0 * uniform() - 1.0) * edge; break;
    case 5: *theta0 = th; *omega0 = (uniform() < 0.5 ? -1 : 1) * edge * (1.0 + 10.0 * uniform()); break;
    case 6: *theta0 = th; *omega0 = edge * (1.0 + (uniform() < 0.5 ? -1 : 1) * pow(10.0, -16.0 * uniform())); break;
    default: *theta0 = th + 2.0 * PI * floor(uniform() * 1e6); *omega0 = (2.0 * uniform() - 1.0) * 3.0 * w0; break;
    }
}

/* x y and x + y of double-doubles, long-hand (the test does not rely on dd.h) */
static void dd_product(double a_hi, double a_lo, double b_hi, double b_lo, double *hi, double *lo)
{
    const double p = a_hi * b_hi;
    const double e = fma(a_hi, b_hi, -p) + (a_hi * b_lo + a_lo * b_hi);
    *hi = p + e;
    *lo = e - (*hi - p);
}

int main(void)
{
    long written = 0, scaled = 0, agree = 0, periods = 0, states = 0;
    for (long i = 0; i < 40000; ++i) {
        const double g = exp(log(1e-2) + uniform() * log(1e5)), L = exp(log(1e-2) + uniform() * log(1e4));
        double theta0, omega0;
        draw_state(i, sqrt(g / L), &theta0, &omega0);
        const double t0 = uniform() < 0.5 ? 0.0 : 100.0 * (2.0 * uniform() - 1.0);
        PendulumExact zeros, ones;
        memset(&zeros, 0x00, sizeof zeros);
        memset(&ones, 0xFF, sizeof ones);
        if (pendulum_exact_init_gl(&zeros, theta0, omega0, g, L, t0) != 0
            || pendulum_exact_init_gl(&ones, theta0, omega0, g, L, t0) != 0) {
            check(0, "set-up of theta0 = %.17g, omega0 = %.17g, g = %.17g, L = %.17g refused", theta0, omega0, g, L);
            continue;
        }
        states++;
        written += memcmp(&zeros, &ones, sizeof zeros) == 0;

        /* g and L by 4^k outside 2^+-400 (the scaled path), the same w0 */
        const double power = uniform() < 0.5 ? 0x1p500 : 0x1p-500;
        PendulumExact far;
        check(pendulum_exact_init_gl(&far, theta0, omega0, g * power, L * power, t0) == 0,
              "set-up with g, L scaled by %a refused", power);
        far.g = zeros.g;
        far.L = zeros.L;
        scaled += memcmp(&far, &zeros, sizeof far) == 0;

        if (zeros.regime == PENDULUM_SEPARATRIX) {
            agree++;
            periods++;
            continue;
        }
        /* rho K against the rate of the elliptic argument, both in double-double */
        double hi, lo;
        dd_product(zeros.rho_hi, zeros.rho_lo, zeros.K_hi, zeros.K_lo, &hi, &lo);
        const double rate_hi = zeros.scale, rate_lo = zeros.scale_lo;   /* w0, or sqrt(m) w0 */
        const double off = fabs((hi - rate_hi) + (lo - rate_lo));
        agree += off <= 1e-30 * rate_hi;
        if (off > 1e-30 * rate_hi) {
            check(0, "rho K - rate = %.3g relative (theta0 = %.17g, omega0 = %.17g)", off / rate_hi, theta0, omega0);
        }
        /* the period rounded to nearest: |period rate - quarters K| <= ulp(period)/2 rate */
        const double quarters = zeros.regime == PENDULUM_LIBRATION ? 4.0 : 2.0;
        const double period = pendulum_exact_period(&zeros);
        dd_product(period, 0.0, rate_hi, rate_lo, &hi, &lo);
        const double miss = fabs((hi - quarters * zeros.K_hi) + (lo - quarters * zeros.K_lo));
        periods += miss <= 0.5 * (nextafter(period, INFINITY) - period) * rate_hi;
    }
    check(written == states, "every byte written: %ld of %ld set-ups", written, states);
    check(scaled == states, "the same set-up with g, L beyond 2^+-400: %ld of %ld", scaled, states);
    check(agree == states, "rho K = rate within 1e-30: %ld of %ld", agree, states);
    check(periods == states, "period 4K / rate within an ulp: %ld of %ld", periods, states);
    return check_summary("test_exact_setup");
}
