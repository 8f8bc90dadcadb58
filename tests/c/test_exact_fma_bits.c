/* test_exact_fma_bits.c: the fma build of the exact solution (exact_fma.c, chosen at run time
 * on a processor with an fma) gives the bits of the baseline build (Dekker's two-products).
 *
 * This program compiles dd.c, elliptic.c and exact.c once more as the baseline alone
 * (PENDULUM_NO_FMA_BUILD: no second build, no hand-over), its public functions renamed with the
 * suffix _baseline, and compares them with the core's functions, which on this processor may
 * run the fma build: the set-up's bytes (every field, the FMU state's content) and theta,
 * omega (scalar and batch), sin and cos of theta over random states of every regime
 * (libration, from rest near the top, within ulps and relative 1e-16 of the separatrix,
 * rotation, wound-up and huge angles, tiny states, any g and L) and times from t0 to
 * 1e16 periods. Where the processor has no fma both sides are the baseline and agree
 * trivially; the program says which it compared. */
#define PENDULUM_NO_FMA_BUILD 1
#define EXACT_COPY(name) name##_baseline
#include "core_copy.h"
#undef pendulum_exact_init_gl
#undef pendulum_exact_eval
#undef pendulum_exact_sin_cos
#undef pendulum_exact_eval_many
#undef pendulum_exact_period

#include <stdio.h>
#include <stdlib.h>

#include "check.h"

/* the core's functions (pendulum_core: the hand-over to the fma build where there is one) */
int pendulum_exact_init_gl(PendulumExact *ex, double theta0, double omega0, double g, double L, double t0);
void pendulum_exact_eval(const PendulumExact *ex, double t, double *theta, double *omega);
void pendulum_exact_sin_cos(const PendulumExact *ex, double t, double *sin_theta, double *cos_theta);
void pendulum_exact_eval_many(const PendulumExact *ex, size_t n, const double *t, double *theta, double *omega);
double pendulum_exact_period(const PendulumExact *ex);

#define STATES 20000
#define TIMES 24

static unsigned long long rng_state = 0x12345678ABCDEFULL;

static double uniform(void)   /* xorshift64*, [0, 1) */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-53;
}

static int same_bits(const double *a, const double *b, int n)
{
    return memcmp(a, b, (size_t)n * sizeof *a) == 0;
}

/* A random state of kind i mod 10: (theta0, omega0) for w0 */
static void draw_state(long i, double w0, double *theta0, double *omega0)
{
    const double th = (2.0 * uniform() - 1.0) * PI, edge = 2.0 * w0 * cos(th / 2);
    switch (i % 10) {
    case 0: *theta0 = th; *omega0 = 0.0; break;
    case 1: *theta0 = PI * (1.0 - pow(10.0, -1.0 - 14.0 * uniform())); *omega0 = 0.0; break;
    case 2: *theta0 = th; *omega0 = (2.0 * uniform() - 1.0) * edge; break;
    case 3: *theta0 = th; *omega0 = (uniform() < 0.5 ? -1 : 1) * edge * (1.001 + 10.0 * uniform()); break;
    case 4: {   /* within 10 ulps of the separatrix speed */
        double o = edge;
        const long k = (long)(uniform() * 21) - 10;
        for (long j = 0; j < labs(k); ++j) {
            o = nextafter(o, k > 0 ? INFINITY : 0.0);
        }
        *theta0 = th;
        *omega0 = uniform() < 0.5 ? -o : o;
        break;
    }
    case 5: {
        const double e = pow(10.0, -16.0 * uniform());
        *theta0 = th;
        *omega0 = edge * (1.0 + (uniform() < 0.5 ? -e : e));
        break;
    }
    case 6: *theta0 = th + 2.0 * PI * floor(uniform() * 1e6); *omega0 = (2.0 * uniform() - 1.0) * 3.0 * w0; break;
    case 7: *theta0 = (2.0 * uniform() - 1.0) * pow(10.0, 20.0 * uniform()); *omega0 = (2.0 * uniform() - 1.0) * 3.0 * w0; break;
    case 8: *theta0 = th * pow(10.0, -10.0 * uniform()); *omega0 = (2.0 * uniform() - 1.0) * w0 * pow(10.0, -8.0 * uniform()); break;
    default: *theta0 = th; *omega0 = (2.0 * uniform() - 1.0) * w0 * pow(10.0, 6.0 * uniform()); break;
    }
}

int main(void)
{
    long differing_setups = 0, differing_outputs = 0;
    for (long i = 0; i < STATES; ++i) {
        double g = exp(log(1e-2) + uniform() * log(1e5)), L = exp(log(1e-2) + uniform() * log(1e4));
        if (i % 7 == 0) {
            g = 9.81;
            L = 1.0;
        }
        double theta0, omega0;
        draw_state(i, sqrt(g / L), &theta0, &omega0);
        const double t0 = uniform() < 0.5 ? 0.0 : (2.0 * uniform() - 1.0) * 100.0;
        PendulumExact a, b;
        memset(&a, 0, sizeof a);
        memset(&b, 0, sizeof b);
        const int status_a = pendulum_exact_init_gl_baseline(&a, theta0, omega0, g, L, t0);
        const int status_b = pendulum_exact_init_gl(&b, theta0, omega0, g, L, t0);
        if (status_a != status_b || memcmp(&a, &b, sizeof a) != 0) {
            differing_setups++;
            check(0, "set-up of theta0 = %.17g, omega0 = %.17g, g = %.17g, L = %.17g: other bytes", theta0, omega0, g, L);
            continue;
        }
        if (status_a != 0) {
            continue;
        }
        const double period = pendulum_exact_period(&a);
        const double T = isfinite(period) && period > 0.0 ? period : 2.0 * PI / sqrt(g / L);
        double t[TIMES];
        for (int j = 0; j < TIMES; ++j) {
            const double scale = j < 8 ? 1.0 : j < 14 ? 1e3 : j < 18 ? 1e6 : j < 20 ? 1e12 : 1e16;
            t[j] = t0 + (2.0 * uniform() - 1.0) * scale * T;
        }
        t[0] = t0;
        double out_a[6][TIMES], out_b[6][TIMES];
        for (int j = 0; j < TIMES; ++j) {
            pendulum_exact_eval_baseline(&a, t[j], &out_a[0][j], &out_a[1][j]);
            pendulum_exact_sin_cos_baseline(&a, t[j], &out_a[2][j], &out_a[3][j]);
            pendulum_exact_eval(&b, t[j], &out_b[0][j], &out_b[1][j]);
            pendulum_exact_sin_cos(&b, t[j], &out_b[2][j], &out_b[3][j]);
        }
        pendulum_exact_eval_many_baseline(&a, TIMES, t, out_a[4], out_a[5]);
        pendulum_exact_eval_many(&b, TIMES, t, out_b[4], out_b[5]);
        for (int k = 0; k < 6; ++k) {
            if (!same_bits(out_a[k], out_b[k], TIMES)) {
                differing_outputs++;
                check(0, "output %d of theta0 = %.17g, omega0 = %.17g, g = %.17g, L = %.17g: other bits", k, theta0,
                      omega0, g, L);
            }
        }
    }
    check(differing_setups == 0 && differing_outputs == 0, "%ld set-ups and %ld output rows differ",
          differing_setups, differing_outputs);
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
    printf("test_exact_fma_bits: this processor %s an fma: %s\n", __builtin_cpu_supports("fma") ? "has" : "lacks",
           __builtin_cpu_supports("fma") ? "the fma build against the baseline" : "the baseline against itself");
#endif
    return check_summary("test_exact_fma_bits");
}
