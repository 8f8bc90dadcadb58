/* exact_eval_paths.h: the body of test_exact_eval_paths.c and test_exact_eval_paths_fma.c,
 * included after the exact port's sources (dd.c, elliptic.c, exact.c), whose static functions
 * it calls.
 *
 * pendulum_exact_eval takes its common case, a libration within 2^50 quarter periods,
 * through eval_libration (inline, its own operations: Fast2Sum for t - t0, the phase without
 * a zero cross term, branches by the quarter and the arctangent's sector, half the last
 * Landen step) and everything else through eval_any (phase_at, the Landen pair,
 * libration_angle_omega's weights, add_half_turns). The two must give the same bits: this
 * program evaluates both on every time where eval_libration takes the point, over random
 * librations of every kind (from rest at any amplitude and within 1e-15 of the top, so that
 * the Landen chain is longer than ELLIPTIC_LEVELS_WITHOUT_RESCALE; moving starts; near the
 * separatrix; wound-up angles; tiny amplitudes; t0 = 0 and t0 != 0; any g and L) at random
 * times up to 2^50 quarter periods, at whole quarter periods and the doubles beside them (the
 * fraction of the phase at or next to zero, both signs of r), and next to t0 (subnormal
 * steps). It also counts the cases it went through, so that it cannot pass without them. */
#include <stdlib.h>
#include <string.h>

#include "check.h"

static unsigned long long rng_state = 0x243F6A8885A308D3ULL;

static double uniform(void)   /* xorshift64*, [0, 1) */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-53;
}

/* A libration (mostly) of kind i mod 8: (theta0, omega0) for w0 */
static void draw_libration(long i, double w0, double *theta0, double *omega0)
{
    const double th = (2.0 * uniform() - 1.0) * PI, edge = 2.0 * w0 * cos(th / 2);
    switch (i % 8) {
    case 0: *theta0 = th; *omega0 = 0.0; break;
    case 1: *theta0 = (uniform() < 0.5 ? -PI : PI) * (1.0 - pow(10.0, -1.0 - 14.5 * uniform())); *omega0 = 0.0; break;
    case 2: *theta0 = th; *omega0 = (2.0 * uniform() - 1.0) * edge; break;
    case 3: *theta0 = th; *omega0 = edge * (1.0 - pow(10.0, -15.0 * uniform())) * (uniform() < 0.5 ? -1.0 : 1.0); break;
    case 4: *theta0 = th + 2.0 * PI * floor((2.0 * uniform() - 1.0) * 1e9); *omega0 = (2.0 * uniform() - 1.0) * edge; break;
    case 5: *theta0 = th * pow(10.0, -12.0 * uniform()); *omega0 = 0.0; break;
    case 6: *theta0 = 0.0; *omega0 = (uniform() < 0.5 ? -2.0 : 2.0) * w0 * (1.0 - pow(10.0, -14.0 * uniform())); break;
    default: *theta0 = th * pow(10.0, -6.0 * uniform()); *omega0 = (2.0 * uniform() - 1.0) * w0 * pow(10.0, -6.0 * uniform()); break;
    }
}

#define STATES 12000
#define TIMES 64

static int run_paths(const char *program)
{
    long common = 0, other = 0, differing = 0, long_chains = 0, late = 0, moved_t0 = 0, negative = 0;
    for (long i = 0; i < STATES; ++i) {
        double g = exp(log(1e-2) + uniform() * log(1e5)), L = exp(log(1e-2) + uniform() * log(1e4));
        if (i % 5 == 0) {
            g = 1.0;
            L = 1.0;
        }
        double theta0, omega0;
        draw_libration(i, sqrt(g / L), &theta0, &omega0);
        const double t0 = uniform() < 0.5 ? 0.0 : (2.0 * uniform() - 1.0) * pow(10.0, 4.0 * uniform());
        PendulumExact ex;
        if (pendulum_exact_init_gl(&ex, theta0, omega0, g, L, t0) != 0 || ex.regime != PENDULUM_LIBRATION) {
            continue;
        }
        const double T = pendulum_exact_period(&ex);
        double t[TIMES];
        for (int j = 0; j < 24; ++j) {   /* up to 1e3 periods, then up to 2^50 quarter periods */
            const double span = j < 16 ? 1e3 * T : 0x1p48 * T * pow(2.0, -30.0 * uniform());
            t[j] = t0 + (2.0 * uniform() - 1.0) * span;
        }
        for (int j = 24; j < 56; j += 4) {   /* whole quarter periods and the doubles beside them */
            const double q = t0 + 0.25 * T * (double)((long)((2.0 * uniform() - 1.0) * 40.0));
            t[j] = q;
            t[j + 1] = nextafter(q, INFINITY);
            t[j + 2] = nextafter(q, -INFINITY);
            t[j + 3] = q + 0.25 * T * (2.0 * uniform() - 1.0) * 1e-12;
        }
        const double next_to_t0[8] = {5e-324, -5e-324, 1e-320, -1e-320, 1e-300, -1e-300, 1e-17, -1e-17};
        for (int j = 56; j < TIMES; ++j) {
            t[j] = t0 + next_to_t0[j - 56];
        }
        long_chains += ex.ell.levels > ELLIPTIC_LEVELS_WITHOUT_RESCALE;
        moved_t0 += t0 != 0.0;
        for (int j = 0; j < TIMES; ++j) {
            double theta_a, omega_a, theta_b, omega_b;
            if (!eval_libration(&ex, t[j], &theta_a, &omega_a)) {
                other++;
                continue;
            }
            common++;
            late += fabs(ex.rho_hi * (t[j] - t0)) > 0x1p40;
            double quarters;
            negative += phase_near(&ex, t[j] - t0, 0.0, ex.rho_hi * (t[j] - t0), &quarters) < 0.0;
            eval_any(&ex, t[j], &theta_b, &omega_b);
            if (memcmp(&theta_a, &theta_b, sizeof theta_a) != 0 || memcmp(&omega_a, &omega_b, sizeof omega_a) != 0) {
                if (++differing <= 10) {
                    check(0, "theta0 = %a, omega0 = %a, g = %a, L = %a, t0 = %a, t = %a: theta %a / %a, omega %a / %a",
                          theta0, omega0, g, L, t0, t[j], theta_a, theta_b, omega_a, omega_b);
                }
            }
        }
    }
    check(differing == 0, "%ld of %ld points of the common case differ from eval_any", differing, common);
    check(common > 10L * other, "the common case took %ld points, the other paths %ld", common, other);
    check(long_chains > 100 && moved_t0 > 1000 && late > 1000 && negative > common / 4,
          "cases: %ld chains past the rescaling's bound, %ld states with t0 != 0, %ld points past 2^40 "
          "quarter periods, %ld with r < 0",
          long_chains, moved_t0, late, negative);
    printf("%s: %ld points of the common case, %ld elsewhere; %ld long chains, %ld states with t0 != 0\n", program,
           common, other, long_chains, moved_t0);
    return check_summary(program);
}
