/* elliptic.h: complete and incomplete elliptic integrals of the first kind and the Jacobi
 * elliptic functions sn, cn, dn, am for real argument and parameter 0 <= m <= 1.
 *
 * Notation of Abramowitz & Stegun (A&S) ch. 16-17 and DLMF ch. 19, 22: m is the parameter,
 * m1 = 1 - m the complementary parameter, k = sqrt(m) the modulus, k' = sqrt(m1).
 * Every function takes m1 as given by the caller and never forms it as 1 - m: near m = 1
 * the caller's m1 (for the pendulum: a product of cosines) carries digits that 1 - m has lost.
 *
 * Method (why it is accurate for m1 -> 0):
 *  - K by the arithmetic-geometric mean from k' (A&S 17.6.1-2, DLMF 19.8.5), in double and
 *    in double-double.
 *  - sn, cn, dn by the descending Landen (Gauss) transformation A&S 16.12.2-4 in its
 *    algebraic form, i.e. the AGM sequence of moduli k_{n+1} = (1 - k_n')/(1 + k_n') of
 *    A&S 17.5 / 16.4, bottomed out with the small-parameter expansions A&S 16.13.1-3.
 *    The argument is first reduced modulo 4K and then to |v| <= K/2 with the quarter-period
 *    identities A&S 16.8.1-3 (sn(v+K) = cd v, cn(v+K) = -k' sd v, dn(v+K) = k'/dn v).
 *    On |v| <= K/2 every quantity of every Landen level is positive and is formed from
 *    products and sums of positive numbers only (1 - k s^2 is written (1 - k) + k c^2), so
 *    sn, cn and dn all keep their relative accuracy, including dn(K/2) = sqrt(k'), and the
 *    quarter-period identities turn them into products and quotients, never differences.
 *    The levels run in homogeneous coordinates (sn = S/D, cn = C/D, dn = E/D), so a level
 *    costs a few multiplications and no division.
 *    The bottom level's sin and cos are a short Maclaurin series (|z| <= pi/4 there).
 *  - F(phi | m) by Carlson's R_F (DLMF 19.25.5, duplication algorithm DLMF 19.36.1 /
 *    Carlson, Numer. Algorithms 10 (1995) 13-26), continued by F(phi + n pi) = F(phi) + 2nK
 *    (A&S 17.4.3).
 *
 * The evaluation kernels (Landen levels, the bottom series, an atan for the amplitude) are
 * static inline below, so that a caller's evaluation compiles into one function without
 * link-time optimisation; everything that runs once per parameter is in elliptic.c.
 * All functions are pure (no global state, no allocation); EllipticParam is plain data. */
#ifndef PENDULUM_ELLIPTIC_H
#define PENDULUM_ELLIPTIC_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* ---------------------------------------------------------------------------------------
 * Double-double arithmetic: a value is hi + lo with |lo| <= ulp(hi)/2 (Dekker, Numer. Math.
 * 18 (1971) 224-242; Knuth, TAOCP vol. 2, 4.2.2). Used for K and the phase over long
 * horizons. The two error-free transformations are inline because the evaluation path
 * uses them; they need IEEE double arithmetic without extended precision (SSE2 or better).
 * --------------------------------------------------------------------------------------- */
typedef struct {
    double hi, lo;
} EllipticDD;

/* The double-double x + 0. */
static inline EllipticDD elliptic_dd(double x)
{
    EllipticDD r;
    r.hi = x;
    r.lo = 0.0;
    return r;
}

/* -x, exactly. */
static inline EllipticDD elliptic_dd_neg(EllipticDD x)
{
    x.hi = -x.hi;
    x.lo = -x.lo;
    return x;
}

/* s + err = a + b exactly, s = fl(a + b) (Knuth's TwoSum, TAOCP 4.2.2 Theorem B). */
static inline EllipticDD elliptic_two_sum(double a, double b)
{
    EllipticDD r;
    double b_virtual;
    r.hi = a + b;
    b_virtual = r.hi - a;
    r.lo = (a - (r.hi - b_virtual)) + (b - b_virtual);
    return r;
}

/* p + err = a * b exactly, p = fl(a b). With a hardware fma (FP_FAST_FMA, C11 7.12):
 * err = fma(a, b, -p), exact by the single rounding. Otherwise Dekker's product (Dekker 1971,
 * mul12): Veltkamp's split of a and b into 26-bit halves, whose partial products are exact
 * (valid for |a|, |b| < 2^995). */
static inline EllipticDD elliptic_two_prod(double a, double b)
{
    EllipticDD r;
    r.hi = a * b;
#ifdef FP_FAST_FMA
    r.lo = fma(a, b, -r.hi);
#else
    const double splitter = 134217729.0;          /* 2^27 + 1 */
    double a_big = splitter * a, b_big = splitter * b;
    double a_hi = a_big - (a_big - a), b_hi = b_big - (b_big - b);
    double a_lo = a - a_hi, b_lo = b - b_hi;
    r.lo = ((a_hi * b_hi - r.hi) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
#endif
    return r;
}

/* Biased exponent field of x (0 for zero and subnormals, 0x7ff for inf and NaN). */
static inline int elliptic_biased_exponent(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return (int)((bits >> 52) & 0x7ff);
}

/* x 2^e, the value of ldexp(x, e): a multiplication by the power of two built from its bits
 * (exact, or one rounding for a subnormal result, as ldexp) when 2^e is a normal double,
 * else ldexp itself. Avoids a libm call in the set-up. */
static inline double elliptic_ldexp(double x, int e)
{
    if (e >= -1022 && e <= 1023) {
        const uint64_t bits = (uint64_t)(e + 1023) << 52;
        double power;
        memcpy(&power, &bits, sizeof power);
        return x * power;
    }
    return ldexp(x, e);
}

/* The exponent frexp would give (x = f 2^e, 1/2 <= |f| < 1), from the bits for a normal x. */
static inline int elliptic_frexp_exponent(double x)
{
    const int biased = elliptic_biased_exponent(x);
    if (biased != 0 && biased != 0x7ff) {
        return biased - 1022;
    }
    int exponent = 0;
    (void)frexp(x, &exponent);
    return exponent;
}

/* The leading 26 significant bits of x (truncated), so that head * n is exact for |n| < 2^27
 * and x - head is exact with at most 27 significant bits. For a normal x the low 27 bits of
 * the significand are cleared; otherwise formed with frexp/ldexp/trunc. Both are exact, so
 * no floating-point contraction can spoil it (unlike Veltkamp's split). */
static inline double elliptic_head26(double x)
{
    const int biased = elliptic_biased_exponent(x);
    if (biased != 0 && biased != 0x7ff) {
        uint64_t bits;
        memcpy(&bits, &x, sizeof bits);
        bits &= ~(((uint64_t)1 << 27) - 1);
        double head;
        memcpy(&head, &bits, sizeof head);
        return head;
    }
    int exponent;
    const double fraction = frexp(x, &exponent);
    return ldexp(trunc(ldexp(fraction, 26)), exponent - 26);
}

/* Nearest integer to x (ties to even), by the 1.5 * 2^52 shift for |x| < 2^51 (exact in
 * round-to-nearest double arithmetic), else nearbyint. */
static inline double elliptic_nearest_integer(double x)
{
    if (fabs(x) < 0x1p51) {
        const double shift = 0x1.8p52;
        return (x + shift) - shift;
    }
    return nearbyint(x);
}

/* x + y, x * y, x / y, sqrt(x) in double-double (relative error a few 2^-104; sqrt for
 * x >= 0), static inline: the set-up runs long chains of them. */
/* s + err = a + b exactly, valid when |a| >= |b| or a == 0 (Dekker's Fast2Sum). */
static inline EllipticDD elliptic_fast_two_sum(double a, double b)
{
    EllipticDD r;
    r.hi = a + b;
    r.lo = b - (r.hi - a);
    return r;
}

static inline EllipticDD elliptic_dd_add(EllipticDD x, EllipticDD y)
{
    /* Sum of the high parts and of the low parts, each error-free, then two renormalisations
     * (the "accurate" double-double addition of Hida, Li and Bailey's QD library). */
    EllipticDD s = elliptic_two_sum(x.hi, y.hi);
    EllipticDD t = elliptic_two_sum(x.lo, y.lo);
    s.lo += t.hi;
    s = elliptic_fast_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return elliptic_fast_two_sum(s.hi, s.lo);
}

static inline EllipticDD elliptic_dd_mul(EllipticDD x, EllipticDD y)
{
    /* (xh + xl)(yh + yl) = xh yh (exact two-product) + xh yl + xl yh + O(2^-106). */
    EllipticDD p = elliptic_two_prod(x.hi, y.hi);
    p.lo += x.hi * y.lo + x.lo * y.hi;
    return elliptic_fast_two_sum(p.hi, p.lo);
}

static inline EllipticDD elliptic_dd_div(EllipticDD x, EllipticDD y)
{
    /* Dekker's div2: q1 = x.hi / y.hi, the remainder x - q1 y with q1 y.hi exact (two-product;
     * x.hi - p.hi is exact by Sterbenz), then q2 = remainder / y.hi. Relative error a few
     * 2^-104 (Dekker 1971, section 8). */
    const double q1 = x.hi / y.hi;
    const EllipticDD p = elliptic_two_prod(q1, y.hi);
    const double remainder = (((x.hi - p.hi) - p.lo) + x.lo) - q1 * y.lo;
    return elliptic_fast_two_sum(q1, remainder / y.hi);
}

static inline EllipticDD elliptic_dd_sqrt(EllipticDD x)
{
    /* One Newton step from the double root s: sqrt(x) = s + (x - s^2) / (2 s), with s^2
     * formed exactly by a two-product. */
    if (!(x.hi > 0.0)) {
        return elliptic_dd(x.hi == 0.0 ? 0.0 : NAN);
    }
    if (isinf(x.hi)) {
        return elliptic_dd(x.hi);
    }
    if (x.hi < 0x1p-900) {
        /* keep the error terms of the two-product out of the subnormal range: scale by an
         * even power of two (exact) */
        EllipticDD scaled = {x.hi * 0x1p1000, x.lo * 0x1p1000};
        EllipticDD root = elliptic_dd_sqrt(scaled);
        root.hi *= 0x1p-500;
        root.lo *= 0x1p-500;
        return root;
    }
    double s = sqrt(x.hi);
    EllipticDD sq = elliptic_two_prod(s, s);
    double correction = (((x.hi - sq.hi) - sq.lo) + x.lo) / (2.0 * s);
    return elliptic_fast_two_sum(s, correction);
}


/* sin x and cos x for a double-double argument |x| <= 2 pi (relative accuracy ~1e-31, also
 * near the zeros): x = n pi/2 + y with pi/2 in three parts, |y| <= pi/4, Maclaurin series
 * of sin y and cos y (A&S 4.3.65-66) summed in double-double, then the quadrant. */
void elliptic_dd_sincos(EllipticDD x, EllipticDD *sin_x, EllipticDD *cos_x);

/* The same with only cos x in double-double and sin x as a double (within an ulp or so):
 * about half the work, for callers that need the digits of one of the two only. */
void elliptic_dd_cos_sin(EllipticDD x, EllipticDD *cos_x, double *sin_x);

/* pi in three parts (pi = PI_HI + PI_LO + PI_LOLO to ~1e-48), generated with mpmath. */
#define ELLIPTIC_PI_HI   0x1.921fb54442d18p+1
#define ELLIPTIC_PI_LO   0x1.1a62633145c07p-53
#define ELLIPTIC_PI_LOLO (-0x1.f1976b7ed8fbcp-109)

/* ---------------------------------------------------------------------------------------
 * Complete and incomplete integrals of the first kind.
 * --------------------------------------------------------------------------------------- */

/* K(m) from m1 = 1 - m >= 0 (m1 may exceed 1, i.e. m < 0):
 * K = pi / (2 AGM(1, sqrt(m1)))   (A&S 17.6.1-2, DLMF 19.8.5).
 * Returns +INFINITY for m1 == 0 and NaN for m1 < 0 or NaN. About 1 ulp. */
double elliptic_K(double m1);

/* The same in double-double, from m1 in double-double (m1 >= 0): the AGM in double-double
 * until the pair is within 2^-15 of each other, then the series of 2F1 (elliptic.c). */
EllipticDD elliptic_K_dd(EllipticDD m1);

/* Carlson's symmetric integral R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z))
 * for x, y, z >= 0, at most one of them 0 (DLMF 19.16.1), by the duplication theorem
 * (DLMF 19.26.18) until the spread is below 0.004, then the series DLMF 19.36.1 to degree 7.
 * Returns +INFINITY if two arguments are 0, NaN for a negative or NaN argument. */
double elliptic_RF(double x, double y, double z);

/* Incomplete integral of the first kind F(phi | m), any real phi, 0 <= m <= 1:
 * F(psi | m) = sin psi R_F(cos^2 psi, cos^2 psi + m1 sin^2 psi, 1) for |psi| <= pi/2
 * (DLMF 19.25.5, with 1 - m sin^2 psi written as a sum of positive terms), continued by
 * F(psi + n pi | m) = F(psi | m) + 2 n K(m)  (A&S 17.4.3). F(phi | 1) = asinh(tan phi)
 * for |phi| < pi/2 (A&S 17.4.21). */
double elliptic_F(double phi, double m, double m1);

/* ---------------------------------------------------------------------------------------
 * Jacobi elliptic functions. EllipticParam holds everything that depends on m only:
 * computed once, then each evaluation is a reduction and one pass up the Landen levels.
 * --------------------------------------------------------------------------------------- */
#define ELLIPTIC_MAX_LEVELS 16

typedef struct {
    double m, m1;           /* parameter and complementary parameter (m1 as given) */
    double k, kc;           /* modulus sqrt(m) and complementary modulus sqrt(m1) */
    double K_hi, K_lo;      /* K(m) in double-double; K_hi = +INFINITY when m1 == 0 */
    double inv_K;           /* 1 / K_hi, for the quotient estimate of the reduction */
    double K_head, K_tail;  /* K_hi = K_head + K_tail, each with at most 27 significant bits,
                               so n K_head and n K_tail are exact for |n| < 2^26 (Cody-Waite) */
    double bottom_scale;    /* z_N = v * bottom_scale = v / prod(1 + k_n), n = 1..N */
    double bottom_m;        /* m_N = k_N^2, small enough for A&S 16.13 to be exact in double */
    int levels;             /* N, the number of descending Landen steps (>= 1 when m1 > 0) */
    double sqrt_k1;         /* sqrt(k_1), k_1 = landen_k[0]: see elliptic_sncndn_homogeneous_pair */
    double landen_k[ELLIPTIC_MAX_LEVELS];   /* k_n, n = 1..N (index n - 1) */
    double landen_1pk[ELLIPTIC_MAX_LEVELS]; /* 1 + k_n */
    double landen_1mk[ELLIPTIC_MAX_LEVELS]; /* 1 - k_n = 2 k'_{n-1} / (1 + k'_{n-1}) */
} EllipticParam;

/* Prepares the parameter set for m in [0, 1] and m1 = 1 - m given separately, m1 in
 * double-double (m1_lo may be 0); K is computed in double-double from it.
 * Returns 0, or -1 (p untouched) if m or m1 is outside [0, 1] or NaN, or m + m1 is not
 * 1 to within 1e-12. m1 == 0 (m = 1) is allowed: sn = tanh, cn = dn = sech, K = +inf. */
int elliptic_param_init(EllipticParam *p, double m, double m1_hi, double m1_lo);

/* The same with k' = sqrt(m1) given in double-double by the caller (root == NULL: formed
 * from m1), for a caller that has it without a square root (the pendulum from rest:
 * k' = cos(theta0/2)). */
int elliptic_param_init_root(EllipticParam *p, double m, double m1_hi, double m1_lo, const EllipticDD *root);

/* Reduces u = u_hi + u_lo to u = n K + r with n = nearest integer to u / K, so |r| <= K/2
 * (up to rounding of the quotient). Returns r; *quarters = n (an integer-valued double).
 * u_lo need not be small (it may hold a phase offset of a few K). K is used in double-double
 * and n K is formed exactly (Cody-Waite: n K_head + n K_tail for |n| < 2^26, a two-product
 * up to 2^52), so r keeps the absolute accuracy of u even for n in the millions. Beyond
 * 2^52 quarter periods (no phase resolvable) r = remquo(u_hi, K_hi) and n is only right
 * mod 8. When K is infinite, returns u_hi + u_lo, n = 0. */
double elliptic_reduce(const EllipticParam *p, double u_hi, double u_lo, double *quarters);

/* Above this |z| the bottom level calls libm's sin and cos instead of the series below. */
#define ELLIPTIC_SERIES_Z_MAX 0.8

/* Renormalise the homogeneous coordinates when D exceeds this (only for m1 < ~1e-30). */
#define ELLIPTIC_HOMOGENEOUS_RESCALE 0x1p200

/* sin z and cos z for 0 <= z <= ELLIPTIC_SERIES_Z_MAX by their Maclaurin series
 * (A&S 4.3.65-66) to z^17 and z^16: the first omitted terms are below 1.2e-19 and 2.8e-18
 * relative there.
 * sin z = z + z s P(s), cos z = 1 + s Q(s), s = z^2, P and Q of degree 7 in s, evaluated by
 * Estrin's scheme (pairs, then powers s^2, s^4) for a short dependency chain. */
static inline void elliptic_sincos_series(double z, double *sin_z, double *cos_z)
{
    const double s = z * z, s2 = s * s, s4 = s2 * s2;
    /* P(s) = -1/3! + s/5! - s^2/7! + ... - s^7/17! */
    const double p01 = -1.0 / 6.0 + s * (1.0 / 120.0);
    const double p23 = -1.0 / 5040.0 + s * (1.0 / 362880.0);
    const double p45 = -1.0 / 39916800.0 + s * (1.0 / 6227020800.0);
    const double p67 = -1.0 / 1307674368000.0 + s * (1.0 / 355687428096000.0);
    const double p = (p01 + s2 * p23) + s4 * (p45 + s2 * p67);
    /* Q(s) = -1/2! + s/4! - s^2/6! + ... + s^7/16! */
    const double q01 = -0.5 + s * (1.0 / 24.0);
    const double q23 = -1.0 / 720.0 + s * (1.0 / 40320.0);
    const double q45 = -1.0 / 3628800.0 + s * (1.0 / 479001600.0);
    const double q67 = -1.0 / 87178291200.0 + s * (1.0 / 20922789888000.0);
    const double q = (q01 + s2 * q23) + s4 * (q45 + s2 * q67);
    *sin_z = z + z * s * p;
    *cos_z = 1.0 + s * q;
}

/* Homogeneous coordinates of (sn, cn, dn): sn = S/D, cn = C/D, dn = E/D, D > 0. */
typedef struct {
    double S, C, E, D;
} EllipticHomogeneous;

/* One ascending step from Landen level n to level n - 1 with kk = k_n = landen_k[n - 1]
 * (A&S 16.12.2-4, DLMF 22.7.2-4): sn = (1 + kk) s / (1 + kk s^2), cn = c d / (1 + kk s^2),
 * dn = (1 - kk s^2) / (1 + kk s^2) = ((1 - kk) + kk c^2) / (1 + kk s^2), in homogeneous form
 *   S' = (1 + kk) S D,  C' = C E,  E' = (1 - kk) D^2 + kk C^2,  D' = D^2 + kk S^2,
 * products and sums of positive numbers only (for 0 <= v <= K/2). Renormalised when D
 * grows past ELLIPTIC_HOMOGENEOUS_RESCALE. */
static inline EllipticHomogeneous elliptic_landen_step_plain(const EllipticParam *p, int index,
                                                             EllipticHomogeneous h)
{
    const double kk = p->landen_k[index];
    const double d2 = h.D * h.D;
    EllipticHomogeneous up;
    up.S = p->landen_1pk[index] * h.S * h.D;
    up.C = h.C * h.E;
    up.E = p->landen_1mk[index] * d2 + kk * h.C * h.C;
    up.D = d2 + kk * h.S * h.S;
    return up;
}

/* The largest number of levels for which no step can need the renormalisation: from the
 * bottom (D = 1, |S| <= D) each step gives D' = D^2 + k S^2 <= 2.01 D^2, so after n steps
 * D <= 2.01^(2^n - 1) < 2^130 < ELLIPTIC_HOMOGENEOUS_RESCALE for n <= 7: elliptic_landen_step
 * then skips its test, and the lock-step evaluation of several points takes the plain steps. */
#define ELLIPTIC_LEVELS_WITHOUT_RESCALE 7

static inline EllipticHomogeneous elliptic_landen_step(const EllipticParam *p, int index,
                                                       EllipticHomogeneous h)
{
    EllipticHomogeneous up = elliptic_landen_step_plain(p, index, h);
    if (p->levels > ELLIPTIC_LEVELS_WITHOUT_RESCALE && up.D > ELLIPTIC_HOMOGENEOUS_RESCALE) {
        const double inv = 1.0 / up.D;
        up.S *= inv;
        up.C *= inv;
        up.E *= inv;
        up.D = 1.0;
    }
    return up;
}

/* sn, cn, dn of |v| at Landen level `level` (0 = the parameter m itself), from the bottom
 * level N up. Bottom, z = |v| / prod(1 + k_n), small m_N (A&S 16.13.1-3):
 *   sn = sin z - m/4 (z - sin z cos z) cos z,  cn = cos z + m/4 (z - sin z cos z) sin z,
 *   dn = 1 - m/2 sin^2 z. For m1 == 0 (no levels): tanh and sech (A&S 16.6.1-3). */
static inline EllipticHomogeneous elliptic_landen_ascend(const EllipticParam *p, double av,
                                                         int level)
{
    EllipticHomogeneous h;
    if (p->m1 == 0.0) {
        /* sn = tanh v, cn = dn = sech v as ((1 - x^2), 2x, 2x) / (1 + x^2), x = exp(-|v|). */
        const double x = exp(-av);
        h.S = (1.0 - x) * (1.0 + x);
        h.C = 2.0 * x;
        h.E = h.C;
        h.D = 1.0 + x * x;
        return h;
    }
    const double z = av * p->bottom_scale;
    double sz, cz;
    if (z <= ELLIPTIC_SERIES_Z_MAX) {
        elliptic_sincos_series(z, &sz, &cz);          /* always so for a reduced argument */
    } else {
        sz = sin(z);
        cz = cos(z);
    }
    const double w = 0.25 * p->bottom_m * (z - sz * cz);
    h.S = sz - w * cz;
    h.C = cz + w * sz;
    h.E = 1.0 - 0.5 * p->bottom_m * sz * sz;
    h.D = 1.0;
    for (int i = p->levels - 1; i >= level; --i) {
        h = elliptic_landen_step(p, i, h);
    }
    return h;
}

/* sn, cn, dn of a reduced argument v (|v| <= K/2 for full relative accuracy; accurate to a
 * few ulps of v up to |v| <= K; not for larger |v|, use elliptic_sncndn) in homogeneous
 * form: sn = *S / *D, cn = *C / *D, dn = *E / *D with *D > 0, by the descending Landen
 * scheme above. */
static inline void elliptic_sncndn_homogeneous(const EllipticParam *p, double v,
                                               double *S, double *C, double *E, double *D)
{
    const EllipticHomogeneous h = elliptic_landen_ascend(p, fabs(v), 0);
    *S = v < 0.0 ? -h.S : h.S;   /* sn is odd, cn and dn are even */
    *C = h.C;
    *E = h.E;
    *D = h.D;
}

/* The same at level 0 and at level 1 of the chain (parameter m_1 = k_1^2, k_1 = landen_k[0],
 * argument v / (1 + k_1)); needs m1 > 0 (elliptic_param_init then keeps levels >= 1).
 * Level 1 gives the pendulum angle without the last step: with k = 2 sqrt(k_1) / (1 + k_1),
 * A&S 16.12.2 and 16.12.4 read k sn(v|m) = 2 t / (1 + t^2), dn(v|m) = (1 - t^2) / (1 + t^2)
 * with t = sqrt(k_1) sn(v/(1+k_1) | m_1), i.e. atan2(k sn, dn) = 2 atan(t). */
static inline void elliptic_sncndn_homogeneous_pair(const EllipticParam *p, double v,
                                                    EllipticHomogeneous *level0,
                                                    EllipticHomogeneous *level1)
{
    EllipticHomogeneous h1 = elliptic_landen_ascend(p, fabs(v), 1);
    EllipticHomogeneous h0 = elliptic_landen_step(p, 0, h1);
    if (v < 0.0) {
        h1.S = -h1.S;
        h0.S = -h0.S;
    }
    *level0 = h0;
    *level1 = h1;
}

/* sn, cn, dn of a reduced argument v, |v| <= K/2 (the homogeneous form divided out). */
void elliptic_sncndn_reduced(const EllipticParam *p, double v, double *sn, double *cn, double *dn);

/* n mod 4 in 0..3 for an integer-valued double n (0 for a non-finite n): the quarter of a
 * period that a reduction quotient n lands in. */
int elliptic_quarter_of(double n);

/* sn(u|m), cn(u|m), dn(u|m) for any real u: reduction to u = n K + r, then by n mod 4
 * (A&S 16.8.1-3 and the table of A&S 16.8 for shifts by K, 2K, 3K):
 *   n = 0: ( sn r,          cn r,              dn r      )
 *   n = 1: ( cn r / dn r,  -k' sn r / dn r,    k' / dn r )
 *   n = 2: (-sn r,         -cn r,              dn r      )
 *   n = 3: (-cn r / dn r,   k' sn r / dn r,    k' / dn r ) */
void elliptic_sncndn(const EllipticParam *p, double u, double *sn, double *cn, double *dn);

/* tan(pi/8), tan(3 pi/8) and pi/4 in two parts (from mpmath). */
#define ELLIPTIC_TAN_PI_8     0x1.a827999fcef32p-2
#define ELLIPTIC_TAN_3PI_8    0x1.3504f333f9de6p+1
#define ELLIPTIC_QUARTER_PI_HI 0x1.921fb54442d18p-1
#define ELLIPTIC_QUARTER_PI_LO 0x1.1a62633145c07p-55

/* g(s) = (atan(sqrt s)/sqrt s - 1)/s on [0, tan^2(pi/8)]: Chebyshev fit of degree 11,
 * generated with mpmath.chebyfit at 50 digits (max fit error 1.2e-18); coefficients
 * g_0..g_11, evaluated by Estrin's scheme. atan(t) = t + t s g(s) with s = t^2. */
static inline double elliptic_atan_series(double s)
{
    const double s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
    const double g01 = -0x1.5555555555555p-2 + s * 0x1.9999999999953p-3;
    const double g23 = -0x1.249249248d7eep-3 + s * 0x1.c71c71c304b68p-4;
    const double g45 = -0x1.745d165df3f95p-4 + s * 0x1.3b1392d9e785cp-4;
    const double g67 = -0x1.110e880a7a521p-4 + s * 0x1.e19a13b9fc6dfp-5;
    const double g89 = -0x1.ac7a938b69c93p-5 + s * 0x1.74ddd408bb4c1p-5;
    const double g1011 = -0x1.1b33b923aa954p-5 + s * 0x1.0ad36a455cafbp-6;
    return ((g01 + s2 * g23) + s4 * (g45 + s2 * g67)) + s8 * (g89 + s2 * g1011);
}

/* atan(y / x) for x > 0 and finite y (that is atan2(y, x) on the right half-plane), within
 * about 1 ulp:
 * t = |y|/x is mapped into |t| <= tan(pi/8) by atan(a/b) = pi/4 + atan((a - b)/(a + b)) and
 * atan(a/b) = pi/2 - atan(b/a) (A&S 4.4.34, 4.4.42), one division in all, then
 * atan t = t + t^3 g(t^2) with g a degree-11 Chebyshev fit of (atan(sqrt s)/sqrt s - 1)/s on
 * [0, tan^2(pi/8)] (mpmath chebyfit, fit error 1.2e-18). About 3x faster than libm's atan2. */
static inline double elliptic_atan_ratio(double y, double x)
{
    const double a = fabs(y), b = x;
    /* a/b <= tan(pi/8): t = a/b;  up to tan(3pi/8): t = (a - b)/(a + b), atan(a/b) = pi/4 + atan t;
     * beyond: t = -b/a, atan(a/b) = pi/2 + atan t. */
    /* The sector is picked by exact 0/1 weights (x * 0 + y * 1 == y exactly for finite x, y):
     * no data-dependent branch. */
    const double w3 = (double)(a > ELLIPTIC_TAN_3PI_8 * b);
    const double w1 = (double)(a > ELLIPTIC_TAN_PI_8 * b) - w3;
    const double w0 = 1.0 - w1 - w3;
    const double num = w0 * a + w1 * (a - b) - w3 * b;
    const double den = w0 * b + w1 * (a + b) + w3 * a;
    const double base_hi = w1 * ELLIPTIC_QUARTER_PI_HI + w3 * (2.0 * ELLIPTIC_QUARTER_PI_HI);
    const double base_lo = w1 * ELLIPTIC_QUARTER_PI_LO + w3 * (2.0 * ELLIPTIC_QUARTER_PI_LO);
    const double t = num / den;
    const double s = t * t;
    const double g = elliptic_atan_series(s);
    const double angle = base_hi + (base_lo + (t + t * s * g));
    return copysign(angle, y);
}

/* atan(y / x) for |y| <= x (x > 0): the first two sectors of elliptic_atan_ratio only. */
static inline double elliptic_atan_unit(double y, double x)
{
    const double a = fabs(y), b = x;
    const double w1 = a > ELLIPTIC_TAN_PI_8 * b ? 1.0 : 0.0, w0 = 1.0 - w1;  /* exact 0/1 */
    const double t = (w0 * a + w1 * (a - b)) / (w0 * b + w1 * (a + b));
    const double s = t * t;
    const double g = elliptic_atan_series(s);
    const double angle =
        w1 * ELLIPTIC_QUARTER_PI_HI + (w1 * ELLIPTIC_QUARTER_PI_LO + (t + t * s * g));
    return copysign(angle, y);
}

/* The amplitude am(u|m), continuous and increasing in u (am(u + 2K) = am(u) + pi, A&S 16.1.5):
 * am(n K + r) = n pi/2 + atan2(sn r, cn r)       for n even,
 *             = n pi/2 + atan2(k' sn r, cn r)    for n odd (from the table above). */
double elliptic_am(const EllipticParam *p, double u);

#endif
