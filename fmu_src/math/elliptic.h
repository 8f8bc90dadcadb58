/* elliptic.h: the complete elliptic integral K, Carlson's R_F and the Jacobi elliptic
 * functions sn, cn, dn for real argument and parameter 0 <= m <= 1, as the exact solution
 * (exact.c) uses them; the double-double arithmetic they are set up with is dd.h.
 *
 * Notation of Abramowitz & Stegun (A&S) ch. 16-17 and DLMF ch. 19, 22: m is the parameter,
 * m1 = 1 - m the complementary parameter, k = sqrt(m) the modulus, k' = sqrt(m1).
 * Every function takes m1 as given by the caller and never forms it as 1 - m: near m = 1
 * the caller's m1 (for the pendulum: a product of cosines) carries digits that 1 - m has lost.
 *
 * Method (why it is accurate for m1 -> 0):
 *  - K by the arithmetic-geometric mean from k' (A&S 17.6.1-2, DLMF 19.8.5) in double-double,
 *    formed with the parameter set (elliptic_param_init): read off the same descending Landen
 *    levels the evaluation uses (the AGM normalised), each level's exact k'_n carried as the
 *    chain's double plus a first-order tail, K = K(m_N) / prod (1 + k'_n)/2 (elliptic.c).
 *  - sn, cn, dn by the descending Landen (Gauss) transformation A&S 16.12.2-4 in its
 *    algebraic form, i.e. the AGM sequence of moduli k_{n+1} = (1 - k_n')/(1 + k_n') of
 *    A&S 17.5 / 16.4, bottomed out with the small-parameter expansions A&S 16.13.1-3.
 *    The caller reduces the argument to u = n K + v, |v| <= K/2 (exact.c: its phase in
 *    quarter periods), and applies the quarter-period identities A&S 16.8.1-3
 *    (sn(v+K) = cd v, cn(v+K) = -k' sd v, dn(v+K) = k'/dn v) by n mod 4 (elliptic_quarter_of).
 *    On |v| <= K/2 every quantity of every Landen level is positive and is formed from
 *    products and sums of positive numbers only (1 - k s^2 is written (1 - k) + k c^2), so
 *    sn, cn and dn all keep their relative accuracy, including dn(K/2) = sqrt(k'), and the
 *    quarter-period identities turn them into products and quotients, never differences.
 *    The levels run in homogeneous coordinates (sn = S/D, cn = C/D, dn = E/D), so a level
 *    costs a few multiplications and no division.
 *    The bottom level's sin and cos are a short Maclaurin series (trig_sincos_small, trig.h;
 *    |z| <= pi/4 there).
 *  - R_F by Carlson's duplication algorithm (DLMF 19.36.1; Carlson, Numer. Algorithms 10
 *    (1995) 13-26): the incomplete integral F(phi | m) of an initial phase is
 *    sin phi R_F(cos^2 phi, 1 - m sin^2 phi, 1) (DLMF 19.25.5), formed by the caller.
 *
 * The evaluation kernels (Landen levels, the bottom series, an atan for the amplitude) are
 * static inline below, so that a caller's evaluation compiles into one function without
 * link-time optimisation; everything that runs once per parameter is in elliptic.c.
 * All functions are pure (no global state, no allocation); EllipticParam is plain data. */
#ifndef PENDULUM_ELLIPTIC_H
#define PENDULUM_ELLIPTIC_H

#include <math.h>

#include "dd.h"
#include "trig.h"

/* ---------------------------------------------------------------------------------------
 * Carlson's R_F (the complete integral K is part of EllipticParam).
 * --------------------------------------------------------------------------------------- */

/* Carlson's symmetric integral R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z))
 * for x, y, z >= 0, at most one of them 0 (DLMF 19.16.1), by the duplication theorem
 * (DLMF 19.26.18) until the spread is below 0.004, then the series DLMF 19.36.1 to degree 7.
 * Returns +INFINITY if two arguments are 0, NaN for a negative or NaN argument. */
/* elliptic_RF's closing series (DLMF 19.36.1) in E2 = XY - Z^2 and E3 = XYZ, for doubles and
 * for once_avx.h's vectors of four (the same operations) */
#define ELLIPTIC_RF_SERIES(E2, E3)                                                              \
    (1.0 - (E2) / 10.0 + (E3) / 14.0 + (E2) * (E2) / 24.0 - 3.0 * (E2) * (E3) / 44.0           \
     - 5.0 * (E2) * (E2) * (E2) / 208.0 + 3.0 * (E3) * (E3) / 104.0 + (E2) * (E2) * (E3) / 16.0)

double elliptic_RF(double x, double y, double z);

/* ---------------------------------------------------------------------------------------
 * Jacobi elliptic functions. EllipticParam holds everything that depends on m only:
 * computed once, then each evaluation is a reduction and one pass up the Landen levels.
 * --------------------------------------------------------------------------------------- */
#define ELLIPTIC_MAX_LEVELS 16

typedef struct {
    double m, m1;           /* parameter and complementary parameter (m1 as given) */
    double k, kc;           /* modulus sqrt(m) and complementary modulus sqrt(m1) */
    double K_hi, K_lo;      /* K(m) in double-double; K_hi = +INFINITY when m1 == 0 */
    /* For a reduction of an argument by K (tests/c/test_elliptic.c); exact.c reduces its phase
     * in quarter periods from its own rates instead. Part of the solution's bytes (FMU states). */
    double inv_K;           /* 1 / K_hi, the quotient estimate */
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

/* 1 when elliptic_param_init and elliptic_param_init_root accept the parameter: m and m1 in
 * [0, 1], m1_lo finite and m + m1 equal to 1 within 1e-12 (a caller can check before it
 * writes anything). */
static inline int elliptic_param_acceptable(double m, double m1_hi, double m1_lo)
{
    return m >= 0.0 && m <= 1.0 && m1_hi >= 0.0 && m1_hi <= 1.0 && isfinite(m1_lo)
           && fabs(m + m1_hi - 1.0) <= 1e-12;
}

/* Prepares the parameter set for m in [0, 1] and m1 = 1 - m given separately, m1 in
 * double-double (m1_lo may be 0); K is computed in double-double from it.
 * Returns 0, or -1 (p untouched) if m or m1 is outside [0, 1] or NaN, or m + m1 is not
 * 1 to within 1e-12. m1 == 0 (m = 1) is allowed: sn = tanh, cn = dn = sech, K = +inf. */
int elliptic_param_init(EllipticParam *p, double m, double m1_hi, double m1_lo);

/* The same with k' = sqrt(m1) given in double-double by the caller (root == NULL: formed
 * from m1), for a caller that has it without a square root (the pendulum from rest:
 * k' = cos(theta0/2)); *inv_K receives 1/K in double-double (0 for m = 1), for callers that
 * divide by K. Written in place: every byte of *p must be zero on entry (the caller cleared
 * it, padding included, as the FMU checksums its states bytewise); on failure p is untouched. */
int elliptic_param_init_root(EllipticParam *p, double m, double m1_hi, double m1_lo, const DoubleDouble *root,
                             DoubleDouble *inv_K);

/* The set-up of elliptic_param_init_root in two steps, for a caller that knows k' as a double
 * before its low part (the pendulum from rest: the leading double of cos(theta0/2) comes
 * first): elliptic_param_begin runs the Landen chain of the double k' (every field the
 * evaluation reads but K, 1/K and the bottom scale), elliptic_param_finish forms K and 1/K in
 * double-double from the chain and k' = kc + kc_lo. Together, on a parameter set whose bytes
 * are zero, they write what elliptic_param_init_root writes for 0 <= m <= 1, 0 < m1 <= 1
 * (checked by the caller: elliptic_param_acceptable) and k' = sqrt(m1) > 0. */
typedef struct {
    double kc[ELLIPTIC_MAX_LEVELS + 1];     /* k'_n of the double chain, n = 0..levels */
    double root[ELLIPTIC_MAX_LEVELS];       /* sqrt(k'_n), rounded */
    double one_plus[ELLIPTIC_MAX_LEVELS];   /* 1 + k'_n, rounded */
} EllipticChain;

void elliptic_param_begin(EllipticParam *p, double m, double kc, EllipticChain *chain);
void elliptic_param_finish(EllipticParam *p, const EllipticChain *chain, double m1, double kc_lo,
                           DoubleDouble *inv_K);


/* Above this |z| the bottom level calls libm's sin and cos, below it trig_sincos_small
 * (trig.h: their Maclaurin series to z^17 and z^16, no range reduction). */
#define ELLIPTIC_SERIES_Z_MAX 0.8

/* Renormalise the homogeneous coordinates when D exceeds this (only for m1 < ~1e-30). */
#define ELLIPTIC_HOMOGENEOUS_RESCALE 0x1p200

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
static inline double elliptic_landen_up_S(const EllipticParam *p, int index, EllipticHomogeneous h)
{
    return p->landen_1pk[index] * h.S * h.D;
}

static inline double elliptic_landen_up_C(EllipticHomogeneous h)
{
    return h.C * h.E;
}

static inline double elliptic_landen_up_E(const EllipticParam *p, int index, EllipticHomogeneous h)
{
    return p->landen_1mk[index] * (h.D * h.D) + p->landen_k[index] * h.C * h.C;
}

static inline double elliptic_landen_up_D(const EllipticParam *p, int index, EllipticHomogeneous h)
{
    return h.D * h.D + p->landen_k[index] * h.S * h.S;
}

/* The four coordinates together (the coordinates alone above: a caller that needs two of
 * them forms only those, with the same operations). */
static inline EllipticHomogeneous elliptic_landen_step_plain(const EllipticParam *p, int index,
                                                             EllipticHomogeneous h)
{
    EllipticHomogeneous up;
    up.S = elliptic_landen_up_S(p, index, h);
    up.C = elliptic_landen_up_C(h);
    up.E = elliptic_landen_up_E(p, index, h);
    up.D = elliptic_landen_up_D(p, index, h);
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

/* sn, cn, dn at the bottom level N of the chain, from z = |v| / prod(1 + k_n) (z = |v|
 * bottom_scale), sin z and cos z, for the small m_N (A&S 16.13.1-3):
 *   sn = sin z - m/4 (z - sin z cos z) cos z,  cn = cos z + m/4 (z - sin z cos z) sin z,
 *   dn = 1 - m/2 sin^2 z   (D = 1). */
static inline EllipticHomogeneous elliptic_landen_bottom(const EllipticParam *p, double z, double sz,
                                                         double cz)
{
    EllipticHomogeneous h;
    const double w = 0.25 * p->bottom_m * (z - sz * cz);
    h.S = sz - w * cz;
    h.C = cz + w * sz;
    h.E = 1.0 - 0.5 * p->bottom_m * sz * sz;
    h.D = 1.0;
    return h;
}

/* sn, cn, dn of |v| at Landen level `level` (0 = the parameter m itself), from the bottom
 * level N (elliptic_landen_bottom) up. For m1 == 0 (no levels): tanh and sech
 * (A&S 16.6.1-3). */
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
        trig_sincos_small(z, &sz, &cz);               /* always so for a reduced argument */
    } else {
        sz = sin(z);
        cz = cos(z);
    }
    h = elliptic_landen_bottom(p, z, sz, cz);
    for (int i = p->levels - 1; i >= level; --i) {
        h = elliptic_landen_step(p, i, h);
    }
    return h;
}

/* sn, cn, dn of a reduced argument v (|v| <= K/2 for full relative accuracy; accurate to a
 * few ulps of v up to |v| <= K; a larger |v| is reduced by K first) in homogeneous
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

/* n mod 4 in 0..3 for an integer-valued double n (0 for a non-finite n): the quarter of a
 * period that a reduction quotient n lands in. */
int elliptic_quarter_of(double n);

/* tan(pi/8), tan(3 pi/8) and pi/4 in two parts (from mpmath). */
#define ELLIPTIC_TAN_PI_8     0x1.a827999fcef32p-2
#define ELLIPTIC_TAN_3PI_8    0x1.3504f333f9de6p+1
#define ELLIPTIC_QUARTER_PI_HI 0x1.921fb54442d18p-1
#define ELLIPTIC_QUARTER_PI_LO 0x1.1a62633145c07p-55

/* g(s) = (atan(sqrt s)/sqrt s - 1)/s on [0, tan^2(pi/8)]: Chebyshev fit of degree 11,
 * generated with mpmath.chebyfit at 50 digits (max fit error 1.2e-18); coefficients
 * g_0..g_11, evaluated by Estrin's scheme. atan(t) = t + t s g(s) with s = t^2. */
/* The body for s of type T: double here, four doubles in once_avx.h (the same operations). */
#define ELLIPTIC_ATAN_SERIES_BODY(T, s)                                              \
    const T s2 = (s) * (s), s4 = s2 * s2, s8 = s4 * s4;                              \
    const T g01 = -0x1.5555555555555p-2 + (s) * 0x1.9999999999953p-3;               \
    const T g23 = -0x1.249249248d7eep-3 + (s) * 0x1.c71c71c304b68p-4;               \
    const T g45 = -0x1.745d165df3f95p-4 + (s) * 0x1.3b1392d9e785cp-4;               \
    const T g67 = -0x1.110e880a7a521p-4 + (s) * 0x1.e19a13b9fc6dfp-5;               \
    const T g89 = -0x1.ac7a938b69c93p-5 + (s) * 0x1.74ddd408bb4c1p-5;               \
    const T g1011 = -0x1.1b33b923aa954p-5 + (s) * 0x1.0ad36a455cafbp-6;             \
    return ((g01 + s2 * g23) + s4 * (g45 + s2 * g67)) + s8 * (g89 + s2 * g1011)

static inline double elliptic_atan_series(double s)
{
    ELLIPTIC_ATAN_SERIES_BODY(double, s);
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

#endif
