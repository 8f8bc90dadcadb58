/* exact.c: the exact solution of theta'' + w0^2 sin(theta) = 0 (see exact.h and
 * documentation/math.html for the formulas).
 *
 * Initial state: theta0 = 2 pi j + th with th in (-pi, pi], s = sin(th/2), c = cos(th/2) >= 0,
 * q = omega0 / (2 w0). c, q and the complementary parameter (and s for a rotation, where
 * it enters the parameter) are formed in double-double, so K (and with it the period) is
 * right to ~1e-30 relative for the binary inputs: over 1e6 periods the phase needs K to
 * better than 1e-18, which a double m1 (two roundings of cos) does not give.
 *
 * Libration, m = s^2 + q^2 < 1, m1 = (c - q)(c + q) > 0 (A&S 16 / documentation/math.html):
 *   sin(theta/2) = k sn u,  cos(theta/2) = dn u,  omega = 2 k w0 cn u,  u = w0 (t - t0) + u0,
 *   theta = 2 atan2(k sn u, dn u). With u = n K + r, |r| <= K/2 (A&S 16.8):
 *     n = 0 mod 4: theta = 2 atan2( k sn r, dn r),   omega =  2 k w0 cn r
 *     n = 1 mod 4: theta = 2 atan2( k cn r, k'),     omega = -2 k w0 k' sn r / dn r
 *     n = 2 mod 4: theta = 2 atan2(-k sn r, dn r),   omega = -2 k w0 cn r
 *     n = 3 mod 4: theta = 2 atan2(-k cn r, k'),     omega =  2 k w0 k' sn r / dn r
 *   (the common positive factor 1/dn r of sn and dn is dropped inside atan2). Evaluated one
 *   Landen level lower (elliptic.h): atan2(k sn u, dn u) = 2 atan(sqrt(k_1) sn(u_1 | m_1)),
 *   u_1 = u / (1 + k_1), where sn(u_1) = +-sn r_1 or +-cd r_1 by the same table, so
 *   theta = 4 atan(sqrt(k_1) sn(u_1)) with an argument of modulus <= sqrt(k_1) < 1; the last
 *   Landen step is only needed for omega.
 *   Initial phase: k sn u0 = s, k cn u0 = q, dn u0 = c, so am u0 = atan2(s, q) and by
 *   DLMF 19.25.5 with the homogeneity of R_F (DLMF 19.16.1 scaled by k^2):
 *     F(phi0 | m) = (|s|/k) R_F((q/k)^2, c^2, 1)  for |phi0| <= pi/2,
 *   all three arguments known without cancellation; q < 0 uses F(pi - phi) = 2K - F(phi).
 *
 * Rotation, m > 1, parameter mu = 1/m, mu1 = -m1/m, for omega0 > 0 (mirror for omega0 < 0):
 *   theta = 2 am(v | mu),  omega = 2 sqrt(m) w0 dn(v | mu),  v = sqrt(m) w0 (t - t0) + v0,
 *   v0 = F(th/2 | mu) = s R_F(c^2, 1 - mu s^2, 1), 1 - mu s^2 = q^2/m = 1/(1 + (s/q)^2).
 *   With rho = s/q and gamma = c/q (both formed as ratios to |omega0|/2, no overflow):
 *   mu = (w0/(|omega0|/2))^2 / (1 + rho^2), mu1 = (1 - gamma)(1 + gamma) / (1 + rho^2),
 *   sqrt(m) w0 = |omega0|/2 sqrt(1 + rho^2) (kept in double-double), and
 *   am(n K + r) = n pi/2 + atan2(sn r, cn r) (n even), n pi/2 + atan2(k' sn r, cn r) (n odd).
 *
 * Separatrix, m1 == 0: theta = 2 atan(sinh u), omega = 2 w0 sech u, u = w0 (t - t0) + u0,
 *   u0 = asinh(tan(th/2)) = asinh(s/c), mirrored for omega0 < 0. */
#include "exact.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "exact_fma.h"

/* The baseline build hands its entry points to the fma build (exact_fma.c) on a processor
 * with an fma: the same bits, fewer operations per two-product (exact_fma.h). */
#if defined(PENDULUM_EXACT_FMA_BUILD) && !defined(PENDULUM_EXACT_FMA_PASS)
#include "cpu_level.h"
#define EXACT_HANDS_ON_TO_FMA 1
int pendulum_exact_init_fma(PendulumExact *ex, double theta0, double omega0, double w0, double t0);
int pendulum_exact_init_gl_fma(PendulumExact *ex, double theta0, double omega0, double g, double L, double t0);
void pendulum_exact_eval_fma(const PendulumExact *ex, double t, double *theta, double *omega);
void pendulum_exact_sin_cos_fma(const PendulumExact *ex, double t, double *sin_theta, double *cos_theta);
void pendulum_exact_eval_many_fma(const PendulumExact *ex, size_t n, const double *t, double *theta,
                                  double *omega);
size_t pendulum_exact_once_gl_many_fma(size_t n, const double *theta0, const double *omega0, const double *g,
                                       const double *L, double t0, const double *t, double *theta, double *omega);
#define EXACT_FMA_HERE() (cpu_level() >= 1)
#endif

/* The numerical core (PENDULUM_EXACT_AVX512, pendulum_core) hands pendulum_exact_once_gl_many
 * on to the AVX-512 build (avx512_copy.c) where the processor has AVX-512F: eight new states a
 * vector, the same bits. */
#if defined(EXACT_HANDS_ON_TO_FMA) && defined(PENDULUM_EXACT_AVX512)
#define EXACT_HANDS_ON_TO_AVX512 1
size_t pendulum_exact_once_gl_many_avx512(size_t n, const double *theta0, const double *omega0, const double *g,
                                          const double *L, double t0, const double *t, double *theta,
                                          double *omega);
#define EXACT_AVX512_HERE() (cpu_level() >= 2)
#endif

#define PI_HI   DD_PI_HI
#define PI_LO   DD_PI_LO
#define PI_LOLO DD_PI_LOLO

/* The larger and the smaller of two numbers that are not NaN: fmax and fmin without their NaN
 * rules, which keep gcc from inlining them (a libm call each). */
static inline double larger(double a, double b)
{
    return a > b ? a : b;
}

static inline double smaller(double a, double b)
{
    return a < b ? a : b;
}

/* x - j (2 pi), 2 pi in three parts, the two leading products exact. */
static DoubleDouble subtract_turns(DoubleDouble x, double j)
{
    x = dd_sub(x, dd_two_prod(j, 2.0 * PI_HI));
    x = dd_sub(x, dd_two_prod(j, 2.0 * PI_LO));
    return dd_add(x, dd_of(-j * 2.0 * PI_LOLO));
}

static void init_separatrix(PendulumExact *e, DoubleDouble s, DoubleDouble c, double omega0, DoubleDouble w0)
{
    e->regime = PENDULUM_SEPARATRIX;
    e->m = 1.0;
    e->m1 = 0.0;
    e->k = 1.0;
    e->kc = 0.0;
    e->K_hi = INFINITY;
    e->K_lo = 0.0;
    e->scale = w0.hi;
    e->scale_lo = w0.lo;
    e->omega_half = w0.hi;
    e->period = INFINITY;
    DoubleDouble unused;
    (void)elliptic_param_init_root(&e->ell, 1.0, 0.0, 0.0, NULL, &unused);   /* K = +inf; accepted */
    if (omega0 == 0.0) {
        /* At rest on the unstable equilibrium (c == 0): stays there. */
        e->direction = 0.0;
        e->u0 = 0.0;
    } else {
        e->direction = omega0 > 0.0 ? 1.0 : -1.0;
        e->u0 = asinh(e->direction * s.hi / c.hi);   /* u0 = asinh(tan(th/2)), mirrored */
    }
}

/* 1/(2 pi) in 24-bit chunks: 1/(2 pi) = sum_i INV_2PI_BITS[i] 2^(-24 (i + 1)), 1248 bits
 * (generated with mpmath at 1400 bits), enough for every finite double (Payne & Hanek,
 * "Radian reduction for trigonometric functions", SIGNUM Newsletter 18 (1983) 19-24). */
static const double INV_2PI_BITS[] = {
    0x28BE60, 0xDB9391, 0x054A7F, 0x09D5F4, 0x7D4D37, 0x7036D8, 0xA5664F, 0x10E410, 0x7F9458,
    0xEAF7AE, 0xF1586D, 0xC91B8E, 0x909374, 0xB80192, 0x4BBA82, 0x746487, 0x3F877A, 0xC72C4A,
    0x69CFBA, 0x208D7D, 0x4BAED1, 0x213A67, 0x1C09AD, 0x17DF90, 0x4E6475, 0x8E60D4, 0xCE7D27,
    0x2117E2, 0xEF7E4A, 0x0EC7FE, 0x25FFF7, 0x816603, 0xFBCBC4, 0x62D682, 0x9B47DB, 0x4D9FB3,
    0xC9F2C2, 0x6DD3D1, 0x8FD9A7, 0x97FA8B, 0x5D49EE, 0xB1FAF9, 0x7C5ECF, 0x41CE7D, 0xE294A4,
    0xBA9AFE, 0xD7EC47, 0xE35742, 0x1580CC, 0x11BF1E, 0xDAEAFC, 0x33EF08};
#define INV_2PI_CHUNKS ((int)(sizeof INV_2PI_BITS / sizeof INV_2PI_BITS[0]))

/* theta mod 2 pi for a large |theta| (any finite double), as a double-double in about
 * [-pi, pi], and the number of whole turns (rounded; only its size matters to the caller).
 * theta = M 2^E with M < 2^53 split into three 24-bit digits M_j; theta / (2 pi) is the sum of
 * the exact products M_j INV_2PI_BITS[i] 2^(E + 24 j - 24 (i + 1)): the terms that are whole
 * numbers are whole turns and dropped, of the others only the fraction is kept (exact), down
 * to 2^-170; the sum of fractions times 2 pi is the angle, to ~1e-31 rad. */
static DoubleDouble reduce_large_angle(double theta, double *turns)
{
    int exponent;
    const double mantissa = ldexp(frexp(fabs(theta), &exponent), 53);   /* an integer < 2^53 */
    const int E = exponent - 53;
    double digit[3];
    digit[0] = fmod(mantissa, 0x1p24);
    digit[1] = fmod((mantissa - digit[0]) * 0x1p-24, 0x1p24);
    digit[2] = (mantissa - digit[0] - digit[1] * 0x1p24) * 0x1p-48;
    DoubleDouble fraction = dd_of(0.0);
    for (int i = 0; i < INV_2PI_CHUNKS; ++i) {
        for (int j = 2; j >= 0; --j) {
            const int power = E + 24 * j - 24 * (i + 1);
            if (power >= 0 || power < -170) {
                continue;   /* a whole number of turns, or below 2^-122 in all */
            }
            const double term = ldexp(digit[j] * INV_2PI_BITS[i], power);   /* exact: < 2^48 bits */
            fraction = dd_add(fraction, dd_of(term - nearbyint(term)));
        }
    }
    fraction = dd_add(fraction, dd_of(-nearbyint(fraction.hi)));   /* |f| <= 1/2 */
    DoubleDouble two_pi = dd_two_sum(2.0 * PI_HI, 2.0 * PI_LO);
    DoubleDouble angle = dd_mul(fraction, two_pi);
    if (theta < 0.0) {
        angle = dd_neg(angle);
    }
    *turns = nearbyint((theta - angle.hi) / (2.0 * PI_HI));
    return angle;
}


/* ---------------------------------------------------------------------------------------
 * Triple-double, only for m1 next to the separatrix. There m1 = c^2 - q^2 (c = cos(th/2),
 * q = |omega0| / (2 w0)) cancels: with c and q in double-double (absolute error ~1e-32) a
 * state within 1e-13 of the separatrix would keep only ~18 digits of m1, and the period,
 * hence the phase after 1e6 periods, would inherit the rest (about 2e-12 rad). A value is
 * an expansion x[0] + x[1] + x[2] (relative error ~2^-150), formed by error-free transformations and
 * renormalised by repeated vector sums (Ogita, Rump & Oishi, SIAM J. Sci. Comput. 26 (2005)
 * 1955-1988, Algorithm 4.8, SumK with K = 3), which run only once per initial state.
 * --------------------------------------------------------------------------------------- */
typedef struct {
    double x[3];
} TripleDouble;

/* Takes an accurate double out of the sum of v[0..n-1] and leaves the rest in v (exactly). */
static double take_leading(double *v, int n)
{
    for (int pass = 0; pass < 3; ++pass) {
        for (int i = 1; i < n; ++i) {
            const DoubleDouble t = dd_two_sum(v[i], v[i - 1]);
            v[i] = t.hi;
            v[i - 1] = t.lo;
        }
    }
    const double leading = v[n - 1];
    v[n - 1] = 0.0;
    return leading;
}

static TripleDouble td_from_terms(double *v, int n)
{
    TripleDouble r;
    for (int i = 0; i < 3; ++i) {
        r.x[i] = take_leading(v, n);
    }
    return r;
}

static TripleDouble td_add(TripleDouble a, TripleDouble b)
{
    double v[6] = {a.x[2], b.x[2], a.x[1], b.x[1], a.x[0], b.x[0]};
    return td_from_terms(v, 6);
}

static TripleDouble td_neg(TripleDouble a)
{
    for (int i = 0; i < 3; ++i) {
        a.x[i] = -a.x[i];
    }
    return a;
}

static TripleDouble td_mul(TripleDouble a, TripleDouble b)
{
    /* products of order <= 2 exactly (two-products), of order 3 rounded (~2^-159) */
    double v[14];
    int n = 0;
    v[n++] = a.x[1] * b.x[2];
    v[n++] = a.x[2] * b.x[1];
    for (int order = 2; order >= 0; --order) {
        for (int i = 0; i <= order; ++i) {
            const DoubleDouble p = dd_two_prod(a.x[i], b.x[order - i]);
            v[n++] = p.lo;
            v[n++] = p.hi;
        }
    }
    return td_from_terms(v, n);
}

static TripleDouble td_of(double x)
{
    TripleDouble r = {{x, 0.0, 0.0}};
    return r;
}

/* a / b by long division: three quotient digits, each from the remainder so far */
static TripleDouble td_div(TripleDouble a, TripleDouble b)
{
    double q[3];
    TripleDouble r = a;
    for (int i = 0; i < 3; ++i) {
        q[i] = r.x[0] / b.x[0];
        r = td_add(r, td_neg(td_mul(b, td_of(q[i]))));
    }
    double v[3] = {q[2], q[1], q[0]};
    return td_from_terms(v, 3);
}

/* sin y (odd = 1) or cos y (odd = 0) for |y| <= pi/4 + small, Maclaurin series (A&S 4.3.65-66) */
static TripleDouble td_sin_cos_series(TripleDouble y, int odd)
{
    const TripleDouble y2 = td_mul(y, y);
    TripleDouble term = odd ? y : td_of(1.0), sum = term;
    for (int k = odd; k < 60; k += 2) {
        term = td_div(td_mul(term, y2), td_of(-(double)(k + 1) * (double)(k + 2)));
        sum = td_add(sum, term);
        if (fabs(term.x[0]) < 1e-52 * fabs(sum.x[0])) {
            break;
        }
    }
    return sum;
}

/* m1 = cos^2(th/2) - q^2 to ~1e-45 absolute, th = theta0 - 2 pi turns (|theta0| < 2^50,
 * th in about (-pi, pi]), q^2 = (|omega0|/2)^2 / w0sq with w0sq = numerator / denominator
 * given exactly (g / L, or w0^2 as a double-double from w0). Returns 0, or -1 when the
 * squares leave the range where every product is exact. */
static int m1_near_separatrix(double theta0, double turns, double half_speed, DoubleDouble w0sq_num,
                              double w0sq_den, DoubleDouble *m1)
{
    if (!(half_speed > 0x1p-400 && half_speed < 0x1p400) || !(fabs(theta0) < 0x1p50)) {
        return -1;
    }
    /* th/2 = theta0/2 - pi turns, pi in three parts, products exact (j < 2^49) */
    const DoubleDouble p_hi = dd_two_prod(turns, PI_HI), p_lo = dd_two_prod(turns, PI_LO);
    double v[6] = {-turns * PI_LOLO, -p_lo.lo, -p_lo.hi, -p_hi.lo, -p_hi.hi, 0.5 * theta0};
    TripleDouble x = td_from_terms(v, 6);
    if (x.x[0] < 0.0) {
        x = td_neg(x);                                    /* cos is even */
    }
    TripleDouble c;
    if (x.x[0] <= ELLIPTIC_QUARTER_PI_HI) {
        c = td_sin_cos_series(x, 0);                      /* |x| <= pi/4 */
    } else {
        /* cos x = sin(pi/2 - x) */
        double w[6] = {-x.x[2], -x.x[1], -x.x[0], 0.5 * PI_LOLO, 0.5 * PI_LO, 0.5 * PI_HI};
        c = td_sin_cos_series(td_from_terms(w, 6), 1);
    }
    /* q^2 = hs^2 den / num: hs^2 exact as a two-product */
    const DoubleDouble hs2 = dd_two_prod(half_speed, half_speed);
    const DoubleDouble a = dd_two_prod(hs2.hi, w0sq_den), b = dd_two_prod(hs2.lo, w0sq_den);
    if (!(fabs(a.hi) > 0x1p-800 && fabs(a.hi) < 0x1p800) || !(w0sq_num.hi > 0x1p-800 && w0sq_num.hi < 0x1p800)) {
        return -1;                                        /* a product could lose bits */
    }
    double u[4] = {b.lo, b.hi, a.lo, a.hi};
    TripleDouble num = {{w0sq_num.hi, w0sq_num.lo, 0.0}};
    const TripleDouble q2 = td_div(td_from_terms(u, 4), num);
    const TripleDouble diff = td_add(td_mul(c, c), td_neg(q2));
    if (!isfinite(diff.x[0]) || !isfinite(diff.x[1])) {
        return -1;
    }
    *m1 = dd_two_sum(diff.x[0], diff.x[1] + diff.x[2]);
    return 0;
}

/* What the set-up knows about the initial state once the angle is reduced and the speeds are
 * scaled (the named steps of exact_init_dd below pass it along). */
typedef struct {
    double turns;         /* theta0 = 2 pi turns + th */
    DoubleDouble th;        /* th in (-pi, pi] */
    DoubleDouble s;         /* sin(th/2): the leading double only (s.lo = 0); init_rotation,
                             the one step that needs its digits, forms it again in full */
    DoubleDouble c;         /* cos(th/2) >= 0, double-double */
    int exponent;         /* common power of two of the rates: w_n = w0 2^-exponent, ... */
    DoubleDouble w_n;       /* w0 2^-exponent */
    double hs_n;          /* |omega0|/2 2^-exponent, exact */
    DoubleDouble c_w;       /* c w_n */
    DoubleDouble gap;       /* c w_n - hs_n = w_n (c - |q|): the sign of m1 */
    DoubleDouble m1_fine;   /* m1 in triple-double precision (when fine) */
    int fine;             /* 1 when m1_fine holds m1 (within 2^-30 of the separatrix speed) */
} InitialState;

/* Step 1. theta0 = 2 pi j + th, th in (-pi, pi] (double-double), and sin, cos of th/2. One
 * subtraction of whole turns does it for |theta0| < 2^50 (j < 2^48, j 2 pi exact in three
 * parts); beyond, the reduction with 1/(2 pi) to 1248 bits (Payne-Hanek, above) for every
 * finite double. For |theta0| <= 3.2 nothing is subtracted and th/2 is exact. The sine and
 * cosine in two steps (dd_cos_sin_begin, _end): between them a release from rest starts its
 * Landen chain on the leading double of cos(th/2) (init_from_rest). */
static void reduce_initial_angle(double theta0, InitialState *st, DdCosSin *trig)
{
    double turns = 0.0;
    DoubleDouble th = dd_of(theta0);
    if (fabs(theta0) >= 0x1p50) {
        th = reduce_large_angle(theta0, &turns);
    }
    for (int round = 0; round < 8 && !(fabs(th.hi) <= 3.2); ++round) {
        const double j = nearbyint(th.hi / (2.0 * PI_HI));
        th = subtract_turns(th, j);
        turns += j;
    }
    const DoubleDouble half = {0.5 * th.hi, 0.5 * th.lo};   /* exact */
    dd_cos_sin_begin(half, trig);
    st->turns = turns;
    st->th = th;
}

static void finish_initial_angle(InitialState *st, const DdCosSin *trig)
{
    DoubleDouble s = dd_of(trig->sin_x), c = dd_cos_sin_end(trig);
    if (c.hi < 0.0 || (c.hi == 0.0 && st->th.hi < 0.0)) {
        /* th just outside (-pi, pi]: move it by one turn; th/2 moves by pi, s and c change sign. */
        double shift = st->th.hi > 0.0 ? 1.0 : -1.0;
        st->turns += shift;
        st->th = subtract_turns(st->th, shift);
        s = dd_neg(s);
        c = dd_neg(c);
    }
    st->s = s;
    st->c = c;
}

/* Step 2. The side of the separatrix. Only the ratio q = |omega0| / (2 w0) enters m and m1,
 * so w0 and |omega0|/2 are scaled by a common power of two that puts the larger in [1/2, 1):
 * the double-double products below then stay far from overflow (Dekker's split needs
 * |x| < 2^996) for any inputs. Rates come back to seconds by the inverse power of two.
 * The sign of m1 = cos^2(th/2) - q^2 is that of w0 c - |omega0|/2; within 2^-30 of the
 * separatrix speed m1 itself is formed in triple-double (above): its sign decides the
 * regime and its digits the period. */
static void locate_separatrix(double theta0, double omega0, DoubleDouble w0, double g, double L,
                              InitialState *st)
{
    const double half_speed = 0.5 * fabs(omega0);          /* |omega0| / 2, exact */
    const int exponent = dd_frexp_exponent(larger(w0.hi, half_speed));   /* w0 > 0 */
    st->exponent = exponent;
    st->w_n = dd_ldexp(w0, -exponent);
    st->hs_n = dd_scalbn(half_speed, -exponent);
    st->c_w = dd_mul(st->c, st->w_n);
    st->gap = dd_sub(st->c_w, dd_of(st->hs_n));
    st->m1_fine = dd_of(0.0);
    st->fine = 0;
    if (fabs(st->gap.hi) < 0x1p-30 * st->hs_n) {
        const DoubleDouble num = g > 0.0 ? dd_of(g) : dd_two_prod(w0.hi, w0.hi);
        st->fine = m1_near_separatrix(theta0, st->turns, half_speed, num, g > 0.0 ? L : 1.0,
                                      &st->m1_fine) == 0;
    }
}

/* The parameter of a libration or rotation, formed before anything is written (so that a
 * state that cannot be set up leaves the caller's bytes untouched). */
typedef struct {
    double m;               /* the parameter the Jacobi functions are taken at (mu for a rotation) */
    DoubleDouble m1;        /* its complement */
    double k;               /* libration: sqrt(m) of the motion */
    DoubleDouble q;         /* libration: |omega0| / (2 w0) */
    int root_known;         /* libration from rest: k' = c itself */
    DoubleDouble s;         /* rotation: sin(th/2) in double-double */
    DoubleDouble one_plus_rho2;   /* rotation: 1 + (s/|q|)^2 */
} RegimeParameter;

/* Step 3a. Libration (m1 > 0): w_n >= 1/2 here, q = |omega0| / (2 w0) <= c <= 1.
 * Returns 0, 1 when m1 underflowed (the caller treats it as the separatrix), -1 when the
 * parameter is out of range (elliptic_param_acceptable). */
static int libration_parameter(double omega0, const InitialState *st, RegimeParameter *par)
{
    const DoubleDouble s = st->s, c = st->c;
    const int from_rest = omega0 == 0.0;
    /* From rest q = 0 and m1 = c^2; else m1 = (c - q)(c + q) = (gap / w_n)(c + q). */
    const DoubleDouble q = from_rest ? dd_of(0.0) : dd_div(dd_of(st->hs_n), st->w_n);
    DoubleDouble m1;
    if (st->fine) {
        m1 = st->m1_fine;
    } else if (from_rest) {
        m1 = dd_mul(c, c);
    } else {
        m1 = dd_mul(dd_div(st->gap, st->w_n), dd_add(c, q));
    }
    if (!(m1.hi > 0.0)) {
        return 1;
    }
    /* sqrt(m) = sqrt(s^2 + q^2) without underflow; from rest |s| itself (hypot(s, 0) = |s|) */
    const double k = from_rest ? fabs(s.hi) : hypot(s.hi, q.hi);
    par->k = k;
    par->m = smaller(k * k, 1.0);
    par->m1 = m1;
    par->q = q;
    /* from rest (and not next to the separatrix) k' = sqrt(m1) = c itself */
    par->root_known = from_rest && !st->fine;
    return elliptic_param_acceptable(par->m, m1.hi, m1.lo) ? 0 : -1;
}

/* The libration's parameter and scales, once e->ell is set up: m, m1 = k'^2 (its leading
 * double), k = sqrt(m), K, the scale w0 of the time and of omega. */
static void set_libration_scales(PendulumExact *e, double m, double m1, double k, DoubleDouble w0)
{
    e->m = m;
    e->m1 = m1;
    e->k = k;
    e->kc = e->ell.kc;
    e->K_hi = e->ell.K_hi;
    e->K_lo = e->ell.K_lo;
    e->scale = w0.hi;
    e->scale_lo = w0.lo;
    e->omega_half = k * w0.hi;
    e->sqrt_k1 = k / (1.0 + e->ell.kc);   /* sqrt(k_1) = k / (1 + k'), no underflow of k^2 */
}

/* Writes the libration of par into e (its bytes cleared); *rate_n is the rate of u scaled by
 * 2^-exponent. */
static void init_libration(PendulumExact *e, double omega0, DoubleDouble w0, const InitialState *st,
                           const RegimeParameter *par, DoubleDouble *rate_n, DoubleDouble *inv_K)
{
    const DoubleDouble s = st->s, c = st->c, q = par->q;
    const double k = par->k;
    const int from_rest = omega0 == 0.0;
    e->regime = PENDULUM_LIBRATION;
    (void)elliptic_param_init_root(&e->ell, par->m, par->m1.hi, par->m1.lo, par->root_known ? &c : NULL,
                                   inv_K);   /* accepted by libration_parameter */
    set_libration_scales(e, par->m, par->m1.hi, k, w0);
    *rate_n = st->w_n;
    if (k == 0.0) {
        e->u0 = 0.0;                          /* at rest at the bottom: theta = 0 */
    } else if (from_rest) {
        e->u0 = s.hi < 0.0 ? -e->K_hi : e->K_hi;   /* released at a turning point: u0 = +-K */
    } else {
        const double s_k = fabs(s.hi) / k, q_k = q.hi / k;
        /* F(|phi0| | m) = (|s|/k) R_F((q/k)^2, c^2, 1) (DLMF 19.25.5, scaled). */
        const double f = s_k * elliptic_RF(q_k * q_k, c.hi * c.hi, 1.0);
        /* omega0 < 0: |phi0| = pi - atan2(|s|, |q|), F = 2K - F(pi - |phi0|). */
        const double base = omega0 >= 0.0 ? f : (2.0 * e->K_hi - f) + 2.0 * e->K_lo;
        e->u0 = s.hi < 0.0 ? -base : base;
    }
}

/* Step 3b. Rotation (m1 < 0, omega0 != 0). Ratios to |omega0|/2: rho = s/|q|, gamma = c/|q| < 1
 * (hs_n > c w_n, and c >= ~1e-33, so hs_n is not tiny). Returns 0, or -1 when the parameter
 * is out of range (elliptic_param_acceptable). */
static int rotation_parameter(const InitialState *st, RegimeParameter *par)
{
    const DoubleDouble half = {0.5 * st->th.hi, 0.5 * st->th.lo};   /* exact */
    const DoubleDouble s = dd_sin(half);   /* sin(th/2) in double-double */
    const DoubleDouble w_n = st->w_n;
    const double hs_n = st->hs_n;
    const DoubleDouble hs = dd_of(hs_n);
    DoubleDouble rho = dd_div(dd_mul(s, w_n), hs);
    DoubleDouble one_plus_rho2 = dd_add(dd_of(1.0), dd_mul(rho, rho));
    DoubleDouble mu1;
    if (st->fine) {
        /* mu1 = -m1 mu, mu = (w_n / hs)^2 / (1 + rho^2) */
        const DoubleDouble w_hs_dd = dd_div(w_n, hs);
        mu1 = dd_mul(dd_neg(st->m1_fine),
                              dd_div(dd_mul(w_hs_dd, w_hs_dd), one_plus_rho2));
    } else {
        /* mu1 = -m1/m = (q^2 - c^2)/(q^2 + s^2) = (1 - gamma)(1 + gamma)/(1 + rho^2). */
        const DoubleDouble one_minus_gamma = dd_div(dd_neg(st->gap), hs);  /* (|q| - c)/|q| */
        const DoubleDouble gamma = dd_div(st->c_w, hs);
        mu1 = dd_div(dd_mul(one_minus_gamma, dd_add(dd_of(1.0), gamma)),
                              one_plus_rho2);
    }
    /* mu = 1/m = 1/(q^2 (1 + rho^2)). */
    const double w_hs = w_n.hi / hs_n;
    par->m = smaller(w_hs * w_hs / one_plus_rho2.hi, 1.0);   /* finite: hs_n > 0 */
    par->m1 = mu1;
    par->s = s;
    par->one_plus_rho2 = one_plus_rho2;
    return elliptic_param_acceptable(par->m, mu1.hi, mu1.lo) ? 0 : -1;
}

/* Writes the rotation of par into e (its bytes cleared). */
static void init_rotation(PendulumExact *e, double omega0, const InitialState *st, const RegimeParameter *par,
                          DoubleDouble *rate_n, DoubleDouble *inv_K)
{
    const DoubleDouble c = st->c, s = par->s, one_plus_rho2 = par->one_plus_rho2;
    const double mu = par->m;
    e->regime = PENDULUM_ROTATION;
    e->direction = omega0 > 0.0 ? 1.0 : -1.0;
    (void)elliptic_param_init_root(&e->ell, mu, par->m1.hi, par->m1.lo, NULL, inv_K);   /* accepted */
    /* sqrt(m) w0 = |q| w0 sqrt(1 + rho^2) = (|omega0|/2) sqrt(1 + rho^2). */
    *rate_n = dd_mul(dd_of(st->hs_n), dd_sqrt(one_plus_rho2));
    const DoubleDouble rate = dd_ldexp(*rate_n, st->exponent);
    e->m = 1.0 / mu;
    e->m1 = -par->m1.hi / mu;
    e->k = e->ell.k;
    e->kc = e->ell.kc;
    e->K_hi = e->ell.K_hi;
    e->K_lo = e->ell.K_lo;
    e->scale = rate.hi;
    e->scale_lo = rate.lo;
    e->omega_half = rate.hi;
    /* v0 = F(th/2 | mu) for the mirrored motion (direction * th), DLMF 19.25.5. */
    e->u0 = e->direction * s.hi * elliptic_RF(c.hi * c.hi, 1.0 / one_plus_rho2.hi, 1.0);
}

/* Step 4. Rate and initial phase in quarter periods: rho = scale / K, x0 = u0 / K (products with
 * 1/K in double-double, from elliptic_param_init_root); the period
 * 4K / w0 (libration) or 2K / rate (one revolution, rotation), all in double-double. A
 * libration released from rest starts at a turning point, x0 = +-1 exactly. */
static void set_quarter_rates(PendulumExact *e, DoubleDouble rate_n, int exponent, int from_rest,
                              DoubleDouble inv_K)
{
    const DoubleDouble K = {e->K_hi, e->K_lo};
    const DoubleDouble rho = dd_ldexp(dd_mul(rate_n, inv_K), exponent);
    DoubleDouble x0;
    if (from_rest && e->regime == PENDULUM_LIBRATION && e->u0 != 0.0) {
        x0 = dd_of(e->u0 < 0.0 ? -1.0 : 1.0);
    } else {
        x0 = dd_mul(dd_of(e->u0), inv_K);
    }
    e->rho_hi = rho.hi;
    e->rho_lo = rho.lo;
    e->rho_head = dd_head26(rho.hi);
    e->rho_tail = rho.hi - e->rho_head;
    e->x0_hi = x0.hi;
    e->x0_lo = x0.lo;
    const double quarters_per_period = e->regime == PENDULUM_LIBRATION ? 4.0 : 2.0;
    const DoubleDouble quarters_K = {quarters_per_period * K.hi, quarters_per_period * K.lo};  /* exact */
    e->period = dd_scalbn(dd_div(quarters_K, rate_n).hi, -exponent);
}

/* Every byte of *e zero (padding included: FMU states compare and checksum it,
 * pendulum_exact_same, instance/state.c), by memsets of 64 bytes, which compilers turn into a
 * few vector stores: one memset of the whole state is expanded by GCC (x86-64, generic tuning)
 * as rep stos, measured at about 15 ns a set-up. */
static void clear_state(PendulumExact *e)
{
    unsigned char *bytes = (unsigned char *)e;
    size_t done = 0;
    for (; done + 64 <= sizeof *e; done += 64) {
        memset(bytes + done, 0, 64);
    }
    memset(bytes + done, 0, sizeof *e - done);
}

/* The solution for w0 in double-double (w0.hi > 0 finite); see pendulum_exact_init. The
 * steps: reduce the angle (1), find the side of the separatrix (2), the parameter of the
 * regime (3a, 3b), then, once nothing can fail, the state written in place: its bytes cleared
 * (clear_state), the constants of the regime (3a, 3b or init_separatrix) and the rates in quarter periods (4). */
/* The common fields of every regime (the state cleared before). */
static void set_inputs(PendulumExact *e, double theta0, double omega0, DoubleDouble w0, double t0, double g,
                       double L, const InitialState *st)
{
    e->w0 = w0.hi;
    e->w0_lo = w0.lo;
    e->g = g;
    e->L = L;
    e->t0 = t0;
    e->theta0 = theta0;
    e->omega0 = omega0;
    e->direction = 1.0;
    e->theta_turns = st->turns;
    e->theta_reduced = st->th.hi;
}

/* A release from rest (omega0 = +-0) with c = cos(th/2) != 0 whose leading double is known
 * (trig->cos_lead_certain): a libration whose k' is |c| (c < 0: th is moved by a turn,
 * finish_initial_angle), and nothing can fail (m = s^2 and m1 = c^2 are in range, c^2 does
 * not underflow for |c| > 2^-500). The state is what the general path below writes (steps 2,
 * 3a and 4 for q = 0: m1 = c^2, u0 = +-K, x0 = +-1), but its Landen chain is started on c's
 * leading double before c's low part is formed (the chain of roots and quotients is the
 * set-up's longest), and the steps that only matter for a moving start are left out. */
static void init_from_rest(PendulumExact *e, double theta0, double omega0, DoubleDouble w0, double t0, double g,
                           double L, InitialState *st, const DdCosSin *trig)
{
    clear_state(e);
    const double k = fabs(trig->sin_x), m = smaller(k * k, 1.0);
    EllipticChain chain;
    elliptic_param_begin(&e->ell, m, fabs(trig->cos_lead), &chain);
    finish_initial_angle(st, trig);
    const DoubleDouble c = st->c, m1 = dd_mul(c, c);
    DoubleDouble inv_K;
    elliptic_param_finish(&e->ell, &chain, m1.hi, c.lo, &inv_K);
    set_inputs(e, theta0, omega0, w0, t0, g, L, st);
    e->regime = PENDULUM_LIBRATION;
    set_libration_scales(e, m, m1.hi, k, w0);
    /* released at a turning point: u0 = +-K (at rest at the bottom, k = 0: theta = 0) */
    e->u0 = k == 0.0 ? 0.0 : (st->s.hi < 0.0 ? -e->K_hi : e->K_hi);
    /* step 4 for rate_n = w0 2^-exponent: the powers of two drop out of every product and
     * quotient (w0 and the results are normal doubles), so rho = w0 / K, period = 4K / w0 */
    const DoubleDouble rho = dd_mul(w0, inv_K);
    e->rho_hi = rho.hi;
    e->rho_lo = rho.lo;
    e->rho_head = dd_head26(rho.hi);
    e->rho_tail = rho.hi - e->rho_head;
    e->x0_hi = e->u0 < 0.0 ? -1.0 : (e->u0 > 0.0 ? 1.0 : 0.0);   /* a turning point, x0_lo = 0 */
    const DoubleDouble four_K = {4.0 * e->K_hi, 4.0 * e->K_lo};
    e->period = dd_div(four_K, w0).hi;
}

static int exact_init_dd(PendulumExact *e, double theta0, double omega0, DoubleDouble w0, double t0,
                         double g, double L)
{
    InitialState st;
    DdCosSin trig;
    reduce_initial_angle(theta0, &st, &trig);
    if (omega0 == 0.0 && trig.cos_lead_certain && fabs(trig.cos_lead) > 0x1p-500) {
        init_from_rest(e, theta0, omega0, w0, t0, g, L, &st, &trig);
        return 0;
    }
    finish_initial_angle(&st, &trig);
    locate_separatrix(theta0, omega0, w0, g, L, &st);
    const double side = st.fine ? st.m1_fine.hi : st.gap.hi;   /* the sign of m1 */

    RegimeParameter par = {0};
    int status = 1;                        /* 1: the separatrix (also when m1 underflowed) */
    if (side > 0.0) {
        status = libration_parameter(omega0, &st, &par);
    } else if (side < 0.0) {
        status = rotation_parameter(&st, &par);
    }
    if (status < 0) {
        return -1;
    }

    clear_state(e);
    set_inputs(e, theta0, omega0, w0, t0, g, L, &st);
    if (status == 1) {
        init_separatrix(e, st.s, st.c, omega0, w0);
        return 0;
    }
    DoubleDouble rate_n, inv_K;
    if (side > 0.0) {
        init_libration(e, omega0, w0, &st, &par, &rate_n, &inv_K);
    } else {
        init_rotation(e, omega0, &st, &par, &rate_n, &inv_K);
    }
    set_quarter_rates(e, rate_n, st.exponent, omega0 == 0.0, inv_K);
    return 0;
}

/* pendulum_exact_init's check of its inputs (but w0) */
static int inputs_finite(const PendulumExact *ex, double theta0, double omega0, double t0)
{
    return ex != NULL && isfinite(theta0) && isfinite(omega0) && isfinite(t0);
}

int pendulum_exact_init(PendulumExact *ex, double theta0, double omega0, double w0, double t0)
{
#ifdef EXACT_HANDS_ON_TO_FMA
    if (EXACT_FMA_HERE()) {
        return pendulum_exact_init_fma(ex, theta0, omega0, w0, t0);
    }
#endif
    if (!inputs_finite(ex, theta0, omega0, t0) || !isfinite(w0) || !(w0 > 0.0)) {
        return -1;
    }
    return exact_init_dd(ex, theta0, omega0, dd_of(w0), t0, 0.0, 0.0);
}

/* w0 = sqrt(g / L) in double-double from the doubles g and L as given: the regime is then the
 * one of those doubles, not of fl(sqrt(fl(g / L))) (whose two roundings can move a state
 * within ~1e-16 of the separatrix to the other side). Scaled by powers of two so that neither
 * the quotient nor Dekker's split overflows or underflows. Returns -1 for g or L not finite
 * and > 0, or g / L beyond a normal double's range. */
static int w0_of_gl(double g, double L, DoubleDouble *w0)
{
    if (!isfinite(g) || !isfinite(L) || !(g > 0.0) || !(L > 0.0)) {
        return -1;
    }
    if (g >= 0x1p-400 && g <= 0x1p400 && L >= 0x1p-400 && L <= 0x1p400) {
        /* the same w0 without the scaling below: every step is exact under powers of two (the
         * quotient's and the root's parts stay normal, g / L within 2^+-800), and the root's
         * argument is the one below times a power of 4 */
        *w0 = dd_sqrt(dd_div(dd_of(g), dd_of(L)));
        return 0;
    }
    const int eg = dd_frexp_exponent(g), eL = dd_frexp_exponent(L);
    const double gm = dd_scalbn(g, -eg), Lm = dd_scalbn(L, -eL);   /* frexp's fractions */
    int shift = eg - eL;                               /* g / L = (gm / Lm) 2^shift */
    if (shift & 1) {
        shift -= 1;                                    /* even, so that the root halves it */
    }
    const DoubleDouble ratio = dd_div(dd_of(dd_scalbn(gm, eg - eL - shift)), dd_of(Lm));
    *w0 = dd_ldexp(dd_sqrt(ratio), shift / 2);
    return w0->hi > 0.0 && isfinite(w0->hi) ? 0 : -1;   /* g / L overflows or underflows */
}

int pendulum_exact_init_gl(PendulumExact *ex, double theta0, double omega0, double g, double L, double t0)
{
#ifdef EXACT_HANDS_ON_TO_FMA
    if (EXACT_FMA_HERE()) {
        return pendulum_exact_init_gl_fma(ex, theta0, omega0, g, L, t0);
    }
#endif
    DoubleDouble w0;
    if (!inputs_finite(ex, theta0, omega0, t0) || w0_of_gl(g, L, &w0) != 0) {
        return -1;
    }
    return exact_init_dd(ex, theta0, omega0, w0, t0, g, L);
}

int pendulum_exact_same(const PendulumExact *ex)
{
    PendulumExact fresh;
    const int status = pendulum_exact_init_gl(&fresh, ex->theta0, ex->omega0, ex->g, ex->L, ex->t0);
    return status == 0 && memcmp(&fresh, ex, sizeof fresh) == 0;
}

int pendulum_exact_resolvable(const PendulumExact *ex, double t)
{
    const double tau = t - ex->t0;
    if (!isfinite(tau)) {
        return 0;
    }
    if (ex->regime == PENDULUM_SEPARATRIX) {
        return 1;
    }
    return fabs(ex->rho_hi * tau) <= PENDULUM_EXACT_MAX_QUARTERS;
}

/* Phase in quarter periods: x = (scale (t - t0) + u0) / K = rho (t - t0) + x0 with rho, x0 in
 * double-double and t - t0 = tau exact as a double-double (TwoSum), split as x = N + f with N
 * an integer (a double-double of two integer-valued doubles, so that it stays exact beyond
 * 2^53) and |f| <= 1/2 (about); f is returned. Every product of the rate and the time is
 * exact (two-products), and each is split into its nearest integer and a fraction (both
 * exact), so f keeps its absolute accuracy (~1e-16) up to PENDULUM_EXACT_MAX_QUARTERS, where
 * the rate's own precision (~2^-102 relative) becomes the limit. This is the branch from 2^50
 * quarter periods on (phase_at has the one below, inline). */
static double phase_quarters_far(const PendulumExact *ex, DoubleDouble tau, DoubleDouble *N)
{
    double rho_hi = ex->rho_hi, rho_lo = ex->rho_lo;
    if (fabs(tau.hi) > 0x1p900) {
        /* keep Dekker's split (|x| < 2^995) in range; rho is then tiny, so this is exact */
        tau = dd_ldexp(tau, -200);
        rho_hi = ldexp(rho_hi, 200);
        rho_lo = ldexp(rho_lo, 200);
    }
    const DoubleDouble a = dd_two_prod(rho_hi, tau.hi);   /* the leading product */
    const DoubleDouble b = dd_two_prod(rho_lo, tau.hi);   /* ~2^-53 of it */
    const DoubleDouble c = dd_two_prod(rho_hi, tau.lo);   /* ~2^-53 of it */
    const double n_a = dd_nearest_integer(a.hi), n_al = dd_nearest_integer(a.lo);
    const double n_b = dd_nearest_integer(b.hi), n_c = dd_nearest_integer(c.hi);
    const double n_x = dd_nearest_integer(ex->x0_hi);
    const double small = ((b.lo + c.lo) + rho_lo * tau.lo) + ex->x0_lo;
    const double fraction = ((a.hi - n_a) + (ex->x0_hi - n_x))
                            + (((small + (a.lo - n_al)) + (b.hi - n_b)) + (c.hi - n_c));
    const double n_f = dd_nearest_integer(fraction);
    /* the small integers sum exactly (each well below 2^50 while |x| <= 2^60) */
    *N = dd_two_sum(n_a, (((n_al + n_b) + n_c) + n_x) + n_f);
    return fraction - n_f;
}

/* x_lo = rho_hi tau_hi - x_hi exactly, x_hi = rho_hi tau_hi rounded: the fma, or Dekker's
 * two-product with rho_hi split once in init */
static inline double phase_product_error(const PendulumExact *ex, double tau_hi, double x_hi)
{
#if defined(FP_FAST_FMA) || defined(PENDULUM_DD_FMA)
    return fma(ex->rho_hi, tau_hi, -x_hi);
#else
    const double tau_split = 134217729.0 * tau_hi;          /* Veltkamp split of tau_hi */
    const double tau_head = tau_split - (tau_split - tau_hi), tau_tail = tau_hi - tau_head;
    return ((ex->rho_head * tau_head - x_hi) + ex->rho_head * tau_tail + ex->rho_tail * tau_head)
           + ex->rho_tail * tau_tail;
#endif
}

/* The integer nearest to x_hi + x0_hi (|x_hi| < 2^50, |x0_hi| <= 2): the 1.5 * 2^52 shift, or
 * roundsd (rint, default rounding) where the build has SSE4.1 (the fma build), one operation
 * for two. rint gives -0 where the shift gives +0 (x_hi + x0_hi in [-1/2, 0]), which changes
 * the sign of a zero fraction f alone, and no output reads that sign (the quarter is n mod 4,
 * the evaluations read |f| and f < 0). */
static inline double phase_nearest_integer(const PendulumExact *ex, double x_hi)
{
#if defined(__SSE4_1__)
    return rint(x_hi + ex->x0_hi);
#else
    return (x_hi + ex->x0_hi + 0x1.8p52) - 0x1.8p52;
#endif
}

/* The phase below 2^50 quarter periods, x = rho tau + x0 with tau = t - t0 (tau = tau_hi +
 * tau_lo exact, TwoSum) and x_hi = rho_hi tau_hi given, |x_hi| < 2^50: returns the fraction
 * f = x - quarters, *quarters the integer nearest to x_hi + x0_hi. Up to 2^50 quarter periods
 * the cross terms rho_hi tau_lo, rho_lo tau_hi stay below 1/8 and need no integer split, and
 * the exact product rho_hi tau_hi = x_hi + x_lo (phase_product_error) is all the work. The
 * nearest integer (phase_nearest_integer) is the 1.5 * 2^52 shift of dd_nearest_integer,
 * whose other branch (|x| >= 2^51) cannot be taken here (|x0| <= 2).
 * Plain arithmetic without a branch: the lock-step evaluation runs it over its lanes. */
static inline double phase_near(const PendulumExact *ex, double tau_hi, double tau_lo, double x_hi,
                                double *quarters)
{
    const double x_lo = phase_product_error(ex, tau_hi, x_hi);
    const double n = phase_nearest_integer(ex, x_hi);
    *quarters = n;
    /* x_hi - n is exact once n exceeds a few (Sterbenz); below, all is small */
    return ((x_hi - n) + ex->x0_hi) + (x_lo + (ex->rho_hi * tau_lo + ex->rho_lo * tau_hi) + ex->x0_lo);
}

/* The phase of a libration or rotation at t: the fraction f of a quarter period (*f), the
 * quarter N (*N) and N mod 4 (returned, 0..3), or -1 where t is not resolvable
 * (pendulum_exact_resolvable; nothing written then). Inline, for the evaluation's common
 * case, phase_near: a phase within 2^50 quarter periods is resolvable
 * (2^50 < PENDULUM_EXACT_MAX_QUARTERS, and a time that is not finite fails |x_hi| < 2^50 as
 * rho_hi > 0). */
static inline int phase_at(const PendulumExact *ex, double t, double *f, DoubleDouble *N)
{
    const DoubleDouble tau = dd_two_sum(t, -ex->t0);
    const double x_hi = ex->rho_hi * tau.hi;
    if (fabs(x_hi) < 0x1p50) {
        double quarters;
        *f = phase_near(ex, tau.hi, tau.lo, x_hi, &quarters);
        *N = dd_of(quarters);
        return (int)((long long)quarters & 3);   /* |quarters| < 2^51 */
    }
    if (!pendulum_exact_resolvable(ex, t)) {
        return -1;
    }
    *f = phase_quarters_far(ex, tau, N);
    return (elliptic_quarter_of(N->hi) + elliptic_quarter_of(N->lo)) & 3;
}

/* half_turns pi for an integer-valued double-double half_turns (|half_turns| < 2^64), in the
 * parts an angle is added to: hi + lo = half_turns.hi pi_hi exactly (two-product), then the
 * remaining products below its rounding, half_turns.hi pi_lo and half_turns.lo pi_hi. */
typedef struct {
    double hi, lo, hi_pi_lo, lo_pi_hi;
    int zero;   /* half_turns == 0: the angle alone */
} HalfTurns;

static inline HalfTurns half_turns_pi(DoubleDouble half_turns)
{
    HalfTurns h;
    const DoubleDouble turn = dd_two_prod(half_turns.hi, PI_HI);
    h.hi = turn.hi;
    h.lo = turn.lo;
    h.hi_pi_lo = half_turns.hi * PI_LO;
    h.lo_pi_hi = half_turns.lo * PI_HI;
    h.zero = half_turns.hi == 0.0 && half_turns.lo == 0.0;
    return h;
}

/* half_turns pi + angle, for a nonzero half_turns: the parts summed smallest first. */
static inline double plus_half_turns(const HalfTurns *h, double angle)
{
    return h->hi + (h->lo + (h->hi_pi_lo + (h->lo_pi_hi + angle)));
}

static double add_half_turns(DoubleDouble half_turns, double angle)
{
    if (half_turns.hi == 0.0 && half_turns.lo == 0.0) {
        return angle;
    }
    const HalfTurns h = half_turns_pi(half_turns);
    return plus_half_turns(&h, angle);
}

/* The angle (theta without the whole turns of theta0) and omega of a libration from the
 * Jacobi functions of the reduced argument r at level 0 (h0: sn r = h0.S / h0.D, ...) and
 * level 1 (h1), and the quarter n mod 4 as exact 0/1 weights: odd = [n odd] and
 * sign = -1 for n = 2, 3 mod 4, else 1 (x * 0 + y * 1 == y exactly: no data-dependent
 * branch). By the formulas of the header comment:
 *   theta/2 = atan2(k sn u, dn u) = 2 atan(sqrt(k_1) sn(u_1 | m_1)) (elliptic.h), and at
 *   level 1 sn(u_1) = sign sn r_1 (n even) or sign cd r_1 (n odd), |sn(u_1)| <= 1;
 *   cn u = sign cn r (n even), -sign k' sn r / dn r (n odd), omega = 2 k w0 cn u. */
static inline void libration_angle_omega(const PendulumExact *ex, EllipticHomogeneous h0,
                                         EllipticHomogeneous h1, double odd, double sign, double *angle,
                                         double *omega)
{
    const double even = 1.0 - odd;
    const double y1 = even * h1.S + odd * h1.C, x1 = even * h1.D + odd * h1.E;
    *angle = 4.0 * elliptic_atan_unit(sign * ex->sqrt_k1 * y1, x1);
    const double cn_num = even * h0.C - odd * (ex->kc * h0.S), den = even * h0.D + odd * h0.E;
    *omega = 2.0 * (sign * ex->omega_half * (cn_num / den));
}

/* pendulum_exact_eval for every motion and time (the common libration below, eval_libration,
 * leaves the rest to it): out of line, so that the common case is a function without calls
 * (no registers saved and restored around it). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void eval_any(const PendulumExact *ex, double t, double *theta, double *omega)
{
    double angle, om, f = 0.0;
    DoubleDouble n = dd_of(0.0);
    DoubleDouble winding = dd_of(0.0);   /* half turns of a rotation since t0: direction N */

    if (t == ex->t0) {
        *theta = ex->theta0;   /* the initial state as given, bit for bit */
        *omega = ex->omega0;
        return;
    }
    /* the quarter n mod 4 of a libration or rotation; -1: beyond the resolved phase, or t not
     * finite */
    const int quarter = ex->regime == PENDULUM_SEPARATRIX ? (pendulum_exact_resolvable(ex, t) ? 0 : -1)
                                                          : phase_at(ex, t, &f, &n);
    if (quarter < 0) {
        *theta = *omega = NAN;
        return;
    }
    if (ex->regime == PENDULUM_LIBRATION) {
        EllipticHomogeneous h0, h1;                 /* sn r = h0.S / h0.D, ... at levels 0, 1 */
        elliptic_sncndn_homogeneous_pair(&ex->ell, f * ex->K_hi, &h0, &h1);
        libration_angle_omega(ex, h0, h1, (double)(quarter & 1), 1.0 - (double)(quarter & 2), &angle, &om);
    } else if (ex->regime == PENDULUM_ROTATION) {
        double S, C, E, D;
        elliptic_sncndn_homogeneous(&ex->ell, f * ex->K_hi, &S, &C, &E, &D); /* sn r = S/D, ... */
        const double odd = (double)(quarter & 1), even = 1.0 - odd;
        /* am(nK + r) - n pi/2 = atan(sn r / cn r) (n even), atan(k' sn r / cn r) (n odd); C > 0
         * for |r| < K, as elliptic_atan_ratio requires */
        const double delta = elliptic_atan_ratio((even + odd * ex->kc) * S, C);
        const double dn_num = even * E + odd * (ex->kc * D), den = even * D + odd * E;
        /* theta = 2 pi j + direction (n pi + 2 delta), omega = 2 sqrt(m) w0 dn(nK + r) */
        winding = ex->direction < 0.0 ? dd_neg(n) : n;
        angle = 2.0 * ex->direction * delta;
        om = 2.0 * (ex->direction * ex->omega_half * (dn_num / den));
    } else if (ex->direction != 0.0) {
        DoubleDouble tau = dd_two_sum(t, -ex->t0);
        double u = ex->scale * tau.hi + ((ex->scale * tau.lo + ex->scale_lo * tau.hi) + ex->u0);
        angle = 2.0 * ex->direction * atan(sinh(u));          /* gd(u) */
        om = 2.0 * (ex->direction * (ex->omega_half / cosh(u)));   /* 2 w0 sech u */
    } else {
        angle = ex->theta_reduced;
        om = 0.0;
    }

    /* theta = 2 pi j + winding pi + angle, j = theta_turns. */
    if (fabs(ex->theta_turns) < 0x1p50) {
        /* without winding (no rotation) the half turns are 2 j itself (exact): adding a
         * double-double 0 would change no bit */
        const DoubleDouble half_turns = ex->regime == PENDULUM_ROTATION
                                          ? dd_add(dd_of(2.0 * ex->theta_turns), winding)
                                          : dd_of(2.0 * ex->theta_turns);
        *theta = add_half_turns(half_turns, angle);
    } else {
        /* theta0 beyond 2^52 rad, where no angle is resolved (its ulp is 1 rad or more):
         * theta0 plus the change since t0. */
        *theta = ex->theta0 + add_half_turns(winding, angle - ex->theta_reduced);
    }
    *omega = om;
}

/* A libration at a phase within 2^50 quarter periods whose bottom argument is within the
 * series (always so but for overflowed inputs) and |theta_turns| < 2^50: the operations of
 * eval_any for that case (phase_at, elliptic_sncndn_homogeneous_pair, libration_angle_omega,
 * add_half_turns), the same bits, inline and without a call. Returns 0, nothing written,
 * off that case.
 *
 * The same roundings as those functions, in fewer operations and fewer steps on the longest
 * chain (t, the phase, the Landen levels, the arctangent's quotient and series), the bits
 * kept (tests/c/test_exact_fma_bits.c, scripts/compare-exact-builds.py):
 *   - t - t0 = tau_hi + tau_lo by Fast2Sum on the two terms ordered by magnitude (3 dependent
 *     operations, TwoSum's 5): the rounding error of a sum is one number, so tau_lo is
 *     dd_two_sum's, at most with the other sign of a zero. Where tau_lo is zero (t - t0
 *     exact: always for t0 = 0) the phase's sum leaves out the zero term rho_hi tau_lo. A
 *     sum changes with the sign of a zero term only where it is itself zero, so either
 *     reaches the fraction f only as the sign of a zero f, which no output reads (below);
 *   - the quarter n mod 4, known long before the Landen levels end, picks the formulas by
 *     branches instead of libration_angle_omega's exact 0/1 weights (x 1 + y 0 = x for the
 *     positive S, C, D, E): the branches are decided early, and a misprediction then costs
 *     less than the products and sums the weights put on the chain (bench_exact);
 *   - sn r is odd: the levels run on |r|, and where the weighted code negated S for r < 0,
 *     the factor copysign(1, r) enters k' sn r (omega, n odd) and the sign of the
 *     arctangent's argument (theta, n even). For r = +-0, S = +0 and both give +0 with
 *     either factor (0 - (+-0) and -0 + 0), so the sign of a zero r is read nowhere;
 *   - the arctangent (elliptic_atan_unit) on a = |sign sqrt(k_1) y1| = sqrt(k_1) y1 and
 *     b = x1, its sector by a branch: t = a / b with a base of 0 (0 + (0 + P) = P for the
 *     P >= +0 there), or (a - b) / (a + b) with a base of pi/4;
 *   - the last Landen step forms only the two coordinates that omega divides (where no
 *     rescaling can occur). */
static inline int eval_libration(const PendulumExact *ex, double t, double *theta, double *omega)
{
    if (ex->regime != PENDULUM_LIBRATION || t == ex->t0 || !(fabs(ex->theta_turns) < 0x1p50)) {
        return 0;
    }
    const double minus_t0 = -ex->t0;
    const int t_larger = fabs(t) >= fabs(minus_t0);
    const double big = t_larger ? t : minus_t0, small = t_larger ? minus_t0 : t;
    const double tau_hi = t + minus_t0;                 /* dd_two_sum(t, -t0).hi */
    const double tau_lo = small - (tau_hi - big);       /* Fast2Sum: exact, |big| >= |small| */
    const double x_hi = ex->rho_hi * tau_hi;
    if (!(fabs(x_hi) < 0x1p50)) {
        return 0;
    }
    /* phase_near's fraction f; where tau_lo is zero (t - t0 exact, as always for t0 = 0) its
     * sum leaves out the zero cross term rho_hi tau_lo */
    const double x_lo = phase_product_error(ex, tau_hi, x_hi), quarters = phase_nearest_integer(ex, x_hi);
    double cross = ex->rho_lo * tau_hi;
    if (tau_lo != 0.0) {
        cross = ex->rho_hi * tau_lo + cross;
    }
    const double v = (((x_hi - quarters) + ex->x0_hi) + ((x_lo + cross) + ex->x0_lo)) * ex->K_hi;
    const EllipticParam *p = &ex->ell;
    const double z = fabs(v) * p->bottom_scale;
    if (!(z <= ELLIPTIC_SERIES_Z_MAX)) {
        return 0;
    }
    double sz, cz;
    trig_sincos_small(z, &sz, &cz);
    EllipticHomogeneous h1 = elliptic_landen_bottom(p, z, sz, cz);
    for (int i = p->levels - 1; i >= 1; --i) {
        h1 = elliptic_landen_step(p, i, h1);   /* of |r|: S1 >= +0 */
    }

    /* the quarter n mod 4 (|quarters| < 2^51): sign = -1 for n = 2, 3 mod 4 */
    static const double QUARTER_SIGN[4] = {1.0, 1.0, -1.0, -1.0};
    const int quarter = (int)((long long)quarters & 3);
    const int odd = quarter & 1;
    const double sign = QUARTER_SIGN[quarter], r_sign = copysign(1.0, v);

    /* theta = 4 atan(sign sqrt(k_1) y1 / x1), y1 / x1 = S1 / D1 (n even), C1 / E1 (n odd) */
    const double a = ex->sqrt_k1 * (odd ? h1.C : h1.S), b = odd ? h1.E : h1.D;
    double magnitude;
    if (a > ELLIPTIC_TAN_PI_8 * b) {
        const double at = (a - b) / (a + b), s = at * at;
        magnitude = ELLIPTIC_QUARTER_PI_HI + (ELLIPTIC_QUARTER_PI_LO + (at + at * s * elliptic_atan_series(s)));
    } else {
        const double at = a / b, s = at * at;
        magnitude = at + at * s * elliptic_atan_series(s);
    }
    /* the sign of sign sqrt(k_1) y1, y1 = r_sign S1 + 0 (n even: the weighted sum's zero) or C1 */
    const double y = (sign * ex->sqrt_k1) * (odd ? h1.C : r_sign * h1.S + 0.0);
    const double angle = 4.0 * copysign(magnitude, y);

    /* omega = 2 k w0 cn u: cn u = sign C0 / D0 (n even), -sign k' r_sign S0 / E0 (n odd), the
     * last Landen step forming the two coordinates it needs (all four, and their rescaling,
     * where the chain is long enough to need it) */
    double cn_num, cn_den;
    if (p->levels <= ELLIPTIC_LEVELS_WITHOUT_RESCALE) {
        cn_num = odd ? 0.0 - (r_sign * ex->kc) * elliptic_landen_up_S(p, 0, h1) : elliptic_landen_up_C(h1);
        cn_den = odd ? elliptic_landen_up_E(p, 0, h1) : elliptic_landen_up_D(p, 0, h1);
    } else {
        const EllipticHomogeneous h0 = elliptic_landen_step(p, 0, h1);
        cn_num = odd ? 0.0 - (r_sign * ex->kc) * h0.S : h0.C;
        cn_den = odd ? h0.E : h0.D;
    }
    *omega = 2.0 * (sign * ex->omega_half * (cn_num / cn_den));
    *theta = add_half_turns(dd_of(2.0 * ex->theta_turns), angle);
    return 1;
}

void pendulum_exact_eval(const PendulumExact *ex, double t, double *theta, double *omega)
{
#ifdef EXACT_HANDS_ON_TO_FMA
    if (EXACT_FMA_HERE()) {
        pendulum_exact_eval_fma(ex, t, theta, omega);
        return;
    }
#endif
    if (!eval_libration(ex, t, theta, omega)) {
        eval_any(ex, t, theta, omega);
    }
}

/* ---------------------------------------------------------------------------------------
 * Several points in lock-step. pendulum_exact_eval spends most of its time waiting on
 * divisions and on the chain of Landen steps of one point; EXACT_LANES points of the same
 * libration run here stage by stage, each stage a short loop over the lanes (independent
 * chains the processor overlaps, and loops the compiler may vectorise at the platform's
 * baseline). The stages are pendulum_exact_eval's own: phase_near, elliptic_landen_bottom,
 * elliptic_landen_step_plain, libration_angle_omega and plus_half_turns, so the results are
 * bit for bit the scalar ones; only their order differs (every lane through one stage before
 * the next). A block with any point off the common path (t == t0, a phase beyond 2^50
 * quarter periods or not finite, a bottom argument past the series) and every motion other
 * than a libration with at most ELLIPTIC_LEVELS_WITHOUT_RESCALE Landen levels (so that
 * elliptic_landen_step is the plain step) and |theta_turns| < 2^50 go through
 * pendulum_exact_eval.
 * --------------------------------------------------------------------------------------- */
#define EXACT_LANES 16

/* 1 when the block of EXACT_LANES points went through, 0 when it needs the scalar path
 * (nothing written then). The lanes are held as arrays per quantity and every stage is a
 * loop of plain double arithmetic over them (no branch, no integer), which the compiler
 * vectorises at the platform's baseline (SSE2 on x86-64); the checks for the common path are
 * separate loops. (An array of EllipticHomogeneous in place of the four arrays S, C, E, D
 * costs 2-14 more instructions a point: bench_exact --count batch under callgrind.) */
static int eval_libration_lanes(const PendulumExact *ex, const double *t, double *theta, double *omega)
{
    const EllipticParam *p = &ex->ell;
    double tau_hi[EXACT_LANES], tau_lo[EXACT_LANES], x_hi[EXACT_LANES];
    for (int l = 0; l < EXACT_LANES; ++l) {
        const DoubleDouble tau = dd_two_sum(t[l], -ex->t0);
        tau_hi[l] = tau.hi;
        tau_lo[l] = tau.lo;
        x_hi[l] = ex->rho_hi * tau.hi;
    }
    for (int l = 0; l < EXACT_LANES; ++l) {
        /* not t == t0, and a finite phase below 2^50 quarter periods (phase_at's test) */
        if (t[l] == ex->t0 || !(fabs(x_hi[l]) < 0x1p50)) {
            return 0;
        }
    }
    /* The phase, and the quarter n mod 4 as the weights of libration_angle_omega (odd, sign)
     * without an integer: from r = n - 4 nearest(n/4) in {-2..2}, odd = [r = +-1]
     * = r^2 (4 - r^2)/3, [n mod 4 in {2, 3}] = [r = +-2] + [r = -1]
     * = r^2 (r^2 - 1)/12 + odd (1 - r)/2, all exact small integers. */
    double v[EXACT_LANES], z[EXACT_LANES], odd[EXACT_LANES], sign[EXACT_LANES];
    for (int l = 0; l < EXACT_LANES; ++l) {
        double quarters;
        v[l] = phase_near(ex, tau_hi[l], tau_lo[l], x_hi[l], &quarters) * ex->K_hi;
        const double r = quarters - 4.0 * ((0.25 * quarters + 0x1.8p52) - 0x1.8p52);
        const double r2 = r * r;
        odd[l] = r2 * (4.0 - r2) / 3.0;
        sign[l] = 1.0 - 2.0 * (r2 * (r2 - 1.0) / 12.0 + odd[l] * (1.0 - r) * 0.5);
        z[l] = fabs(v[l]) * p->bottom_scale;
    }
    for (int l = 0; l < EXACT_LANES; ++l) {
        if (!(z[l] <= ELLIPTIC_SERIES_Z_MAX)) {
            return 0;
        }
    }
    /* elliptic_sncndn_homogeneous_pair, stage by stage: the bottom level, the steps up to
     * level 1 (h), then below level 0 and the outputs */
    double S[EXACT_LANES], C[EXACT_LANES], E[EXACT_LANES], D[EXACT_LANES];   /* level by level */
    for (int l = 0; l < EXACT_LANES; ++l) {
        double sz, cz;
        trig_sincos_small(z[l], &sz, &cz);
        const EllipticHomogeneous h = elliptic_landen_bottom(p, z[l], sz, cz);
        S[l] = h.S;
        C[l] = h.C;
        E[l] = h.E;
        D[l] = h.D;
    }
    for (int i = p->levels - 1; i >= 1; --i) {
        for (int l = 0; l < EXACT_LANES; ++l) {
            const EllipticHomogeneous below = {S[l], C[l], E[l], D[l]};
            const EllipticHomogeneous h = elliptic_landen_step_plain(p, i, below);
            S[l] = h.S;
            C[l] = h.C;
            E[l] = h.E;
            D[l] = h.D;
        }
    }
    double angle[EXACT_LANES];
    for (int l = 0; l < EXACT_LANES; ++l) {
        EllipticHomogeneous h1 = {S[l], C[l], E[l], D[l]};
        EllipticHomogeneous h0 = elliptic_landen_step_plain(p, 0, h1);
        if (v[l] < 0.0) {   /* sn is odd, cn and dn are even */
            h1.S = -h1.S;
            h0.S = -h0.S;
        }
        libration_angle_omega(ex, h0, h1, odd[l], sign[l], &angle[l], &omega[l]);
    }
    /* add_half_turns with the whole turns of theta0 (a libration has no winding) */
    const HalfTurns turns = half_turns_pi(dd_of(2.0 * ex->theta_turns));
    for (int l = 0; l < EXACT_LANES; ++l) {
        theta[l] = turns.zero ? angle[l] : plus_half_turns(&turns, angle[l]);
    }
    return 1;
}

void pendulum_exact_eval_many(const PendulumExact *ex, size_t n, const double *t, double *theta, double *omega)
{
#ifdef EXACT_HANDS_ON_TO_FMA
    if (EXACT_FMA_HERE()) {
        pendulum_exact_eval_many_fma(ex, n, t, theta, omega);
        return;
    }
#endif
    size_t i = 0;
    if (ex->regime == PENDULUM_LIBRATION && ex->ell.levels <= ELLIPTIC_LEVELS_WITHOUT_RESCALE
        && fabs(ex->theta_turns) < 0x1p50) {
        for (; i + EXACT_LANES <= n; i += EXACT_LANES) {
            if (!eval_libration_lanes(ex, t + i, theta + i, omega + i)) {
                for (size_t j = i; j < i + EXACT_LANES; ++j) {
                    pendulum_exact_eval(ex, t[j], &theta[j], &omega[j]);
                }
            }
        }
    }
    for (; i < n; ++i) {
        pendulum_exact_eval(ex, t[i], &theta[i], &omega[i]);
    }
}

/* The fma build (GCC or clang on x86-64 Linux, the fma and AVX enabled) sets up and evaluates
 * four releases from rest, or four moving librations or rotations, at once in AVX vectors
 * (once_avx.h), and the AVX-512 build eight: the same bits as once_scalar below. */
#if defined(PENDULUM_DD_FMA) && defined(__GNUC__) && defined(__x86_64__)
#define EXACT_ONCE_AVX 1
#include "once_avx.h"
#endif

/* One element of pendulum_exact_once_gl_many by pendulum_exact_init_gl and _eval; returns 1
 * where it is refused (inputs or time), else 0 */
static size_t once_scalar(double theta0, double omega0, double g, double L, double t0, double t, double *theta,
                          double *omega)
{
    PendulumExact ex;
    if (pendulum_exact_init_gl(&ex, theta0, omega0, g, L, t0) != 0) {
        *theta = *omega = NAN;
        return 1;
    }
    pendulum_exact_eval(&ex, t, theta, omega);
    return !pendulum_exact_resolvable(&ex, t);
}

#ifdef EXACT_ONCE_AVX
/* sqrt(g / L) in double-double for the last g and L seen, formed again only for another g or L
 * (a run of elements with one g and L forms it once) */
typedef struct {
    double g, L;
    DoubleDouble w0;
    int ok;   /* w0_of_gl accepted g and L */
} OnceRate;

static inline int once_rate_ok(OnceRate *r, double g, double L)
{
    if (!(same_double(g, r->g) && same_double(L, r->L))) {
        r->g = g;
        r->L = L;
        r->ok = w0_of_gl(g, L, &r->w0) == 0;
    }
    return r->ok;
}

/* pendulum_exact_once_gl_many sorts its elements this many at a time */
#define ONCE_CHUNK 64

/* A chunk's elements by kind, as indices into the caller's arrays: the releases from rest and
 * the moving starts with |theta0| < 2^50 and g, L accepted (their w0 beside them), and the
 * rest, which go one by one */
typedef struct {
    size_t rest[ONCE_CHUNK], moving[ONCE_CHUNK], other[ONCE_CHUNK];
    DoubleDouble w0_rest[ONCE_CHUNK], w0_moving[ONCE_CHUNK];
    int n_rest, n_moving, n_other;
} OnceSorted;

static void once_sort(size_t start, size_t end, const double *theta0, const double *omega0, const double *g,
                      const double *L, int t0_ok, OnceRate *rate, OnceSorted *by)
{
    by->n_rest = by->n_moving = by->n_other = 0;
    for (size_t j = start; j < end; ++j) {
        if (t0_ok && fabs(theta0[j]) < 0x1p50 && once_rate_ok(rate, g[j], L[j])) {
            if (omega0[j] == 0.0) {
                by->w0_rest[by->n_rest] = rate->w0;
                by->rest[by->n_rest++] = j;
            } else {
                by->w0_moving[by->n_moving] = rate->w0;
                by->moving[by->n_moving++] = j;
            }
        } else {
            by->other[by->n_other++] = j;
        }
    }
}

/* The elements at[0..count-1] a vector at a time (ONCE_LANES): once_avx for releases from rest, else
 * (moving) once_moving_avx; an element a block leaves goes one by one (once_scalar). Returns
 * the count of refused elements. */
static size_t once_blocks(int moving, int count, const size_t *at, const DoubleDouble *w0, const double *theta0,
                          const double *omega0, const double *g, const double *L, double t0, const double *t,
                          double *theta, double *omega, int *expect_rotation)
{
    size_t refused = 0;
    for (int i = 0; i < count; i += ONCE_LANES) {
        const int lanes = count - i < ONCE_LANES ? count - i : ONCE_LANES;
        double th[ONCE_LANES], om[ONCE_LANES], times[ONCE_LANES], th_out[ONCE_LANES], om_out[ONCE_LANES];
        for (int l = 0; l < lanes; ++l) {
            th[l] = theta0[at[i + l]];
            om[l] = omega0[at[i + l]];
            times[l] = t[at[i + l]];
        }
        const int done = !moving
                             ? once_avx(lanes, th, w0 + i, t0, times, th_out, om_out)
                             : once_moving_avx(lanes, th, om, w0 + i, t0, times, th_out, om_out, expect_rotation);
        for (int l = 0; l < lanes; ++l) {
            const size_t k = at[i + l];
            if (done & (1 << l)) {
                theta[k] = th_out[l];
                omega[k] = om_out[l];
            } else {
                refused += once_scalar(theta0[k], omega0[k], g[k], L[k], t0, t[k], &theta[k], &omega[k]);
            }
        }
    }
    return refused;
}

/* The moving starts' blocks, out of line: in the releases' loop their code cost those
 * releases a tenth of their time (bench_exact's once kind) */
__attribute__((noinline)) static size_t once_moving_blocks(const OnceSorted *by, const double *theta0,
                                                           const double *omega0, const double *g,
                                                           const double *L, double t0, const double *t,
                                                           double *theta, double *omega, int *expect_rotation)
{
    return once_blocks(1, by->n_moving, by->moving, by->w0_moving, theta0, omega0, g, L, t0, t, theta, omega,
                       expect_rotation);
}
#endif

size_t pendulum_exact_once_gl_many(size_t n, const double *theta0, const double *omega0, const double *g,
                                   const double *L, double t0, const double *t, double *theta, double *omega)
{
#ifdef EXACT_HANDS_ON_TO_AVX512
    if (EXACT_AVX512_HERE()) {
        return pendulum_exact_once_gl_many_avx512(n, theta0, omega0, g, L, t0, t, theta, omega);
    }
#endif
#ifdef EXACT_HANDS_ON_TO_FMA
    if (EXACT_FMA_HERE()) {
        return pendulum_exact_once_gl_many_fma(n, theta0, omega0, g, L, t0, t, theta, omega);
    }
#endif
    size_t refused = 0;
#ifdef EXACT_ONCE_AVX
    /* sorted a chunk at a time: the releases from rest and the moving starts to vectors (their
     * kinds apart, each block of one kind), the rest one by one */
    OnceRate rate = {NAN, NAN, {NAN, NAN}, 0};
    const int t0_ok = isfinite(t0);
    int expect_rotation = 0;   /* once_moving_avx's guess for the next block */
    for (size_t start = 0; start < n; start += ONCE_CHUNK) {
        const size_t end = n - start < ONCE_CHUNK ? n : start + ONCE_CHUNK;
        OnceSorted by;
        once_sort(start, end, theta0, omega0, g, L, t0_ok, &rate, &by);
        refused += once_blocks(0, by.n_rest, by.rest, by.w0_rest, theta0, omega0, g, L, t0, t, theta, omega, NULL);
        if (by.n_moving > 0) {
            refused += once_moving_blocks(&by, theta0, omega0, g, L, t0, t, theta, omega, &expect_rotation);
        }
        for (int i = 0; i < by.n_other; ++i) {
            const size_t j = by.other[i];
            refused += once_scalar(theta0[j], omega0[j], g[j], L[j], t0, t[j], &theta[j], &omega[j]);
        }
    }
#else
    for (size_t j = 0; j < n; ++j) {
        refused += once_scalar(theta0[j], omega0[j], g[j], L[j], t0, t[j], &theta[j], &omega[j]);
    }
#endif
    return refused;
}

const char *pendulum_exact_qualitative_miss(const PendulumExact *ex, double theta, double omega)
{
    /* the libration (and the separatrix motion) is centred on the bottom 2 pi j nearest theta0 */
    const DoubleDouble centre = dd_two_prod(2.0 * ex->theta_turns, PI_HI);
    const double offset = (theta - centre.hi) - (centre.lo + 2.0 * ex->theta_turns * PI_LO);
    /* past the top by more than half a radian: fallen down the other side, not a rounding-level
     * excursion of a state released at the top itself (pi as a double lies 1.2e-16 below it) */
    const double over = PI_HI + 0.5;
    switch (ex->regime) {
    case PENDULUM_LIBRATION:
        return fabs(offset) > over ? "carried the libration over the top" : NULL;
    case PENDULUM_ROTATION:
        return ex->direction * omega < 0.0 ? "reversed the rotation" : NULL;
    default:
        if (ex->direction == 0.0) {
            return NULL;   /* at rest on the top: any motion is a rounding-level departure */
        }
        if (ex->direction * offset > over) {
            return "went over the top past the separatrix";
        }
        return ex->direction * omega < 0.0 ? "fell back from the separatrix" : NULL;
    }
}

double pendulum_exact_period(const PendulumExact *ex)
{
    return ex->period;   /* computed in init: 4K/w0, 2K/(sqrt(m) w0), or +inf */
}

void pendulum_exact_sin_cos(const PendulumExact *ex, double t, double *sin_theta, double *cos_theta)
{
#ifdef EXACT_HANDS_ON_TO_FMA
    if (EXACT_FMA_HERE()) {
        pendulum_exact_sin_cos_fma(ex, t, sin_theta, cos_theta);
        return;
    }
#endif
    double y, x;   /* sin and cos of the half angle (up to a common sign), or of am v (rotation) */
    double sign = 1.0;

    if (t == ex->t0 || (ex->regime == PENDULUM_SEPARATRIX && ex->direction == 0.0)) {
        *sin_theta = sin(ex->theta0);   /* the initial state as given (libm reduces it exactly) */
        *cos_theta = cos(ex->theta0);
        return;
    }
    if (!pendulum_exact_resolvable(ex, t)) {
        *sin_theta = *cos_theta = NAN;
        return;
    }
    if (ex->regime == PENDULUM_SEPARATRIX) {
        /* theta = 2 pi j + 2 d gd(u): sin(gd u) = tanh u, cos(gd u) = sech u */
        const DoubleDouble tau = dd_two_sum(t, -ex->t0);
        const double u = ex->scale * tau.hi + ((ex->scale * tau.lo + ex->scale_lo * tau.hi) + ex->u0);
        y = tanh(u);
        x = 1.0 / cosh(u);
        sign = ex->direction;
    } else {
        DoubleDouble n;
        double S, C, E, D, f;
        const int quarter = phase_at(ex, t, &f, &n);   /* resolvable: checked above */
        elliptic_sncndn_homogeneous(&ex->ell, f * ex->K_hi, &S, &C, &E, &D);   /* sn r = S/D, ... */
        const double turn = 1.0 - (double)(quarter & 2);   /* -1 for n = 2, 3 mod 4 */
        if (ex->regime == PENDULUM_LIBRATION) {
            /* sin(theta/2) = k sn u, cos(theta/2) = dn u with sn(K + r) = cd r, dn(K + r) = k'/dn r */
            y = (quarter & 1) ? turn * ex->k * (C / E) : turn * ex->k * (S / D);
            x = (quarter & 1) ? ex->kc * (D / E) : E / D;
        } else {
            /* theta = 2 pi j + 2 d am v: sin(am v) = sn v, cos(am v) = cn v, cn(K + r) = -k' sd r */
            y = (quarter & 1) ? turn * (C / E) : turn * (S / D);
            x = (quarter & 1) ? -turn * ex->kc * (S / E) : turn * (C / D);
            sign = ex->direction;
        }
    }
    /* sin theta = 2 sin cos, cos theta = cos^2 - sin^2 of the half angle, the pair scaled to
     * unit length first (a rounding common to both, e.g. of the denominator, drops out): both
     * keep the relative accuracy of the elliptic functions where theta nears a multiple of pi */
    const double h = hypot(x, y);
    x /= h;
    y /= h;
    *sin_theta = sign * (2.0 * y * x);
    *cos_theta = (x - y) * (x + y);
}
