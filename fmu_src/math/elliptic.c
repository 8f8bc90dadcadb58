/* elliptic.c: K, F, sn, cn, dn, am (see elliptic.h for the method and the references). */
#include "elliptic.h"

#include <stddef.h>
#include <string.h>
#include <math.h>

/* pi/2 in three parts: exact halves of ELLIPTIC_PI_*. */
#define HALF_PI_HI   (0.5 * ELLIPTIC_PI_HI)
#define HALF_PI_LO   (0.5 * ELLIPTIC_PI_LO)
#define HALF_PI_LOLO (0.5 * ELLIPTIC_PI_LOLO)

/* The bottom of the Landen descent: once m_N <= BOTTOM_M, A&S 16.13.1-3 is used. Its error
 * is O(m_N^2): measured with mpmath (m = 1e-4, |z| <= pi/4), the relative error of sn, cn, dn
 * is below 0.0045 m^2, so below 1.2e-17 here. */
#define BOTTOM_M 5e-8

/* ------------------------------------------------------------------------------------- */
/* double-double                                                                          */
/* ------------------------------------------------------------------------------------- */

/* The double-double arithmetic is static inline in elliptic.h (so that the set-up's chains
 * of double-double operations compile without calls); Dekker's Fast2Sum by its local name: */
#define fast_two_sum elliptic_fast_two_sum

/* Coefficients of the Maclaurin series of sin and cos (A&S 4.3.65-66) in double-double,
 * generated with mpmath at 300 bits: SIN_COEF[j - 1] = (-1)^j / (2j + 1)!,
 * COS_COEF[j - 1] = (-1)^j / (2j)!, j = 1..14. */
static const EllipticDD SIN_COEF[14] = {
    {-0x1.5555555555555p-3, -0x1.5555555555555p-57}, {0x1.1111111111111p-7, 0x1.1111111111111p-63},
    {-0x1.a01a01a01a01ap-13, -0x1.a01a01a01a01ap-73}, {0x1.71de3a556c734p-19, -0x1.c154f8ddc6c00p-73},
    {-0x1.ae64567f544e4p-26, 0x1.c062e06d1f209p-80}, {0x1.6124613a86d09p-33, 0x1.f28e0cc748ebep-87},
    {-0x1.ae7f3e733b81fp-41, -0x1.1d8656b0ee8cbp-97}, {0x1.952c77030ad4ap-49, 0x1.ac981465ddc6cp-103},
    {-0x1.2f49b46814157p-57, -0x1.2650f61dbdcb4p-112}, {0x1.71b8ef6dcf572p-66, -0x1.d043ae40c4647p-120},
    {-0x1.761b41316381ap-75, 0x1.3423c7d91404fp-130}, {0x1.3f3ccdd165fa9p-84, -0x1.58ddadf344487p-139},
    {-0x1.d1ab1c2dccea3p-94, -0x1.054d0c78aea14p-149}, {0x1.259f98b4358adp-103, 0x1.eaf8c39dd9bc5p-157},
};
static const EllipticDD COS_COEF[14] = {
    {-0x1.0000000000000p-1, 0x0.0p+0}, {0x1.5555555555555p-5, 0x1.5555555555555p-59},
    {-0x1.6c16c16c16c17p-10, 0x1.f49f49f49f49fp-65}, {0x1.a01a01a01a01ap-16, 0x1.a01a01a01a01ap-76},
    {-0x1.27e4fb7789f5cp-22, -0x1.cbbc05b4fa99ap-76}, {0x1.1eed8eff8d898p-29, -0x1.2aec959e14c06p-83},
    {-0x1.93974a8c07c9dp-37, -0x1.05d6f8a2efd1fp-92}, {0x1.ae7f3e733b81fp-45, 0x1.1d8656b0ee8cbp-101},
    {-0x1.6827863b97d97p-53, -0x1.eec01221a8b0bp-107}, {0x1.e542ba4020225p-62, 0x1.ea72b4afe3c2fp-120},
    {-0x1.0ce396db7f853p-70, 0x1.aebcdbd20331cp-124}, {0x1.f2cf01972f578p-80, -0x1.9ada5fcc1ab14p-135},
    {-0x1.88e85fc6a4e5ap-89, 0x1.71c37ebd16540p-143}, {0x1.0a18a2635085dp-98, 0x1.b9e2e28e1aa54p-153},
};

/* c + x y for double-doubles, with the sloppy sum (one renormalisation): Horner's step when
 * |x y| is well below |c| (here |x y| <= 0.31 |c|), relative error a few 2^-104. */
static EllipticDD dd_mul_add(EllipticDD c, EllipticDD x, EllipticDD y)
{
    EllipticDD p = elliptic_two_prod(x.hi, y.hi);
    p.lo += x.hi * y.lo + x.lo * y.hi;
    EllipticDD s = elliptic_two_sum(c.hi, p.hi);
    s.lo += c.lo + p.lo;
    return fast_two_sum(s.hi, s.lo);
}

#define WANT_SIN 1
#define WANT_COS 2

/* x = n pi/2 + y, |y| <= pi/4 (about): y = x - n (pi/2)_hi - n (pi/2)_lo - n (pi/2)_lolo, the
 * products n (pi/2)_hi and n (pi/2)_lo exact (two-product), n small. Returns y, *n = n. */
static EllipticDD reduce_half_pi(EllipticDD x, double *quadrants)
{
    const double n = nearbyint(x.hi / HALF_PI_HI);
    *quadrants = n;
    if (n == 0.0) {
        return x;
    }
    EllipticDD y = elliptic_dd_add(x, elliptic_dd_neg(elliptic_two_prod(n, HALF_PI_HI)));
    y = elliptic_dd_add(y, elliptic_dd_neg(elliptic_two_prod(n, HALF_PI_LO)));
    return elliptic_dd_add(y, elliptic_dd(-n * HALF_PI_LOLO));
}

/* sum_{j < n} coef[j] z^j + z^n tail for a double-double z (z2 = z^2), by Horner's scheme
 * split into two chains in z^2 that the processor runs side by side (the even and the odd
 * powers, A(z^2) + z B(z^2)), half the depth of one chain: every step adds a term far below
 * the partial sum (|coef[j + 2] z^2| <= 0.02 |coef[j]|), as dd_mul_add needs. */
static EllipticDD horner_two_chains(const EllipticDD *coef, int n, double tail, EllipticDD z, EllipticDD z2)
{
    /* the tail belongs to the chain of power n: even (A) or odd (B) */
    EllipticDD even = elliptic_dd((n % 2 == 0) ? tail : 0.0);
    EllipticDD odd = elliptic_dd((n % 2 == 1) ? tail : 0.0);
    for (int j = n - 1; j >= 0; --j) {
        if (j % 2 == 0) {
            even = dd_mul_add(coef[j], z2, even);
        } else {
            odd = dd_mul_add(coef[j], z2, odd);
        }
    }
    return elliptic_dd_add(even, elliptic_dd_mul(z, odd));
}

/* sin y and cos y for |y| <= pi/4 (about): those flagged in `want` (WANT_SIN, WANT_COS) in
 * double-double, the others as a double (lo = 0) within an ulp or so.
 * sin y = y + y y2 P(y2), cos y = 1 + y2 Q(y2), y2 = y^2 <= 0.62, P(y2) = sum_j
 * SIN_COEF[j - 1] y2^(j - 1), Q likewise, j = 1..14 (the first omitted terms, y2^14 / 31!
 * and / 30!, are below 1e-35 relative). By Horner, the terms from j = J on in double, the
 * J - 1 leading ones in double-double. J is the least with |c_J| y2^J <= 1e-16 for the
 * series wanted: the double tail (relative error ~2 eps) then moves sin y by at most
 * 1.2 y2 2 eps |c_J| y2^(J - 1) <= 2^-104 relative, and cos y (>= 0.707) likewise. At
 * |y| = pi/4, J = 9; at |y| = 0.087 (th = 10 or 170 degrees), J = 5; for |y| <= 1e-8, J = 1. */
static void sincos_reduced(EllipticDD y, int want, EllipticDD *sin_y, EllipticDD *cos_y)
{
    const EllipticDD y2 = elliptic_dd_mul(y, y);
    const double z = y2.hi;
    const double sin_bound = (want & WANT_SIN) ? 1.0 : 0.0, cos_bound = (want & WANT_COS) ? 1.0 : 0.0;
    int J = 1;
    for (double power = z; J < 14 && !(sin_bound * fabs(SIN_COEF[J - 1].hi) * power <= 1e-16
                                        && cos_bound * fabs(COS_COEF[J - 1].hi) * power <= 1e-16); ++J) {
        power *= z;
    }
    double tail_s = SIN_COEF[13].hi, tail_c = COS_COEF[13].hi;
    for (int j = 12; j >= J - 1; --j) {
        tail_s = SIN_COEF[j].hi + z * tail_s;
        tail_c = COS_COEF[j].hi + z * tail_c;
    }
    const EllipticDD y4 = elliptic_dd_mul(y2, y2);
    if (want & WANT_SIN) {
        const EllipticDD p = horner_two_chains(SIN_COEF, J - 1, tail_s, y2, y4);
        *sin_y = elliptic_dd_add(y, elliptic_dd_mul(elliptic_dd_mul(y, y2), p));
    } else {
        for (int j = J - 2; j >= 0; --j) {
            tail_s = SIN_COEF[j].hi + z * tail_s;
        }
        *sin_y = elliptic_dd(y.hi + y.hi * z * tail_s);
    }
    if (want & WANT_COS) {
        const EllipticDD q = horner_two_chains(COS_COEF, J - 1, tail_c, y2, y4);
        *cos_y = elliptic_dd_add(elliptic_dd(1.0), elliptic_dd_mul(y2, q));
    } else {
        for (int j = J - 2; j >= 0; --j) {
            tail_c = COS_COEF[j].hi + z * tail_c;
        }
        *cos_y = elliptic_dd(1.0 + z * tail_c);
    }
}

/* n mod 4 for an integer-valued double n, without integer overflow. */
static int quadrant_of(double n)
{
    return (int)(n - 4.0 * floor(0.25 * n));
}

void elliptic_dd_sincos(EllipticDD x, EllipticDD *sin_x, EllipticDD *cos_x)
{
    if (!isfinite(x.hi)) {
        *sin_x = *cos_x = elliptic_dd(NAN);
        return;
    }
    double n;
    EllipticDD sin_y, cos_y;
    sincos_reduced(reduce_half_pi(x, &n), WANT_SIN | WANT_COS, &sin_y, &cos_y);
    /* sin(y + n pi/2), cos(y + n pi/2) by the quadrant n mod 4. */
    switch (quadrant_of(n)) {
    case 0: *sin_x = sin_y;         *cos_x = cos_y;         break;
    case 1: *sin_x = cos_y;         *cos_x = elliptic_dd_neg(sin_y); break;
    case 2: *sin_x = elliptic_dd_neg(sin_y); *cos_x = elliptic_dd_neg(cos_y); break;
    default: *sin_x = elliptic_dd_neg(cos_y); *cos_x = sin_y;        break;
    }
}

void elliptic_dd_cos_sin(EllipticDD x, EllipticDD *cos_x, double *sin_x)
{
    if (!isfinite(x.hi)) {
        *cos_x = elliptic_dd(NAN);
        *sin_x = NAN;
        return;
    }
    double n;
    const EllipticDD y = reduce_half_pi(x, &n);
    const int quadrant = quadrant_of(n);
    EllipticDD sin_y, cos_y;
    /* cos x is +-cos y for even n, -+sin y for odd n: only that one in double-double */
    sincos_reduced(y, (quadrant & 1) ? WANT_SIN : WANT_COS, &sin_y, &cos_y);
    switch (quadrant) {
    case 0: *sin_x = sin_y.hi;  *cos_x = cos_y;                   break;
    case 1: *sin_x = cos_y.hi;  *cos_x = elliptic_dd_neg(sin_y);  break;
    case 2: *sin_x = -sin_y.hi; *cos_x = elliptic_dd_neg(cos_y);  break;
    default: *sin_x = -cos_y.hi; *cos_x = sin_y;                  break;
    }
}

/* ------------------------------------------------------------------------------------- */
/* Complete and incomplete integrals                                                      */
/* ------------------------------------------------------------------------------------- */

double elliptic_K(double m1)
{
    if (!(m1 >= 0.0)) {
        return NAN;
    }
    if (m1 == 0.0) {
        return INFINITY;
    }
    if (isinf(m1)) {
        return 0.0;
    }
    /* AGM: a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n), a_0 = 1, b_0 = k' (A&S 17.6.1).
     * When |a - b| <= 2^-26 a, the next mean (a + b)/2 is within (a-b)^2/(16 a) < 2^-56 a
     * of the limit. */
    double a = 1.0, b = sqrt(m1);
    for (int i = 0; i < 64 && fabs(a - b) > 0x1p-26 * a; ++i) {
        double a_next = 0.5 * (a + b);
        b = sqrt(a * b);
        a = a_next;
    }
    /* K = pi / (2 AGM(1, k'))  (A&S 17.6.2), AGM = (a + b)/2. */
    return ELLIPTIC_PI_HI / (a + b);
}

/* K from k' = sqrt(m1) in double-double (k' > 0): K = (pi/2) / AGM(1, k').
 * The AGM runs in double-double until x = (a - b)/(a + b) <= 2^-15. For that close pair,
 * with c = (a + b)/2, AGM(a, b) = c AGM(1 + x, 1 - x) = c / 2F1(1/2, 1/2; 1; x^2)
 * (DLMF 19.8.5 with 19.5.1), so
 *   K = (pi/2) / AGM = (pi / (a + b)) (1 + x^2/4 + 9 x^4/64 + 25 x^6/256 + 1225 x^8/16384 + ...),
 * the series of 2F1 (coefficients ((1/2)_n / n!)^2); the omitted terms are below
 * 0.061 x^10 < 2^-154. x is formed in double-double from a - b (a.hi - b.hi exact by
 * Sterbenz, a.lo - b.lo within 2^-106) and x^2/4 (below 2^-32) in double-double; the higher
 * terms (below 2^-62) need a double only. The quotient pi / (a + b) does not wait for x:
 * the two divisions run side by side. This saves one to two square-root steps over running
 * the means to |a - b| ~ 1e-17. */
static EllipticDD K_dd_of_root(EllipticDD kc)
{
    EllipticDD a = elliptic_dd(1.0), b = kc;
    for (int i = 0; i < 64; ++i) {
        const EllipticDD sum = elliptic_dd_add(a, b);
        const double diff_hi = a.hi - b.hi;
        if (fabs(diff_hi) <= 0x1p-15 * sum.hi) {
            const EllipticDD base = elliptic_dd_div(fast_two_sum(ELLIPTIC_PI_HI, ELLIPTIC_PI_LO), sum);
            const EllipticDD diff = elliptic_two_sum(diff_hi, a.lo - b.lo);
            const EllipticDD x = elliptic_dd_div(diff, sum);
            const EllipticDD x2 = elliptic_dd_mul(x, x);
            const double t = x2.hi;
            const double higher = t * t * (9.0 / 64.0 + t * (25.0 / 256.0 + t * (1225.0 / 16384.0)));
            const EllipticDD series = elliptic_dd_add((EllipticDD){0.25 * x2.hi, 0.25 * x2.lo},
                                                      elliptic_dd(higher));   /* 2F1 - 1 */
            return elliptic_dd_add(base, elliptic_dd_mul(base, series));
        }
        const EllipticDD a_next = {0.5 * sum.hi, 0.5 * sum.lo};
        b = elliptic_dd_sqrt(elliptic_dd_mul(a, b));
        a = a_next;
    }
    return elliptic_dd(NAN);
}

EllipticDD elliptic_K_dd(EllipticDD m1)
{
    if (!(m1.hi >= 0.0)) {
        return elliptic_dd(NAN);
    }
    if (m1.hi == 0.0) {
        return elliptic_dd(INFINITY);
    }
    return K_dd_of_root(elliptic_dd_sqrt(m1));
}

double elliptic_RF(double x, double y, double z)
{
    if (!(x >= 0.0 && y >= 0.0 && z >= 0.0)) {
        return NAN;
    }
    if ((x == 0.0) + (y == 0.0) + (z == 0.0) >= 2) {
        return INFINITY;
    }
    if (isinf(x) || isinf(y) || isinf(z)) {
        return 0.0;
    }
    /* Duplication theorem (DLMF 19.26.18): R_F(x,y,z) = R_F((x+l)/4, (y+l)/4, (z+l)/4) with
     * l = sqrt(x)sqrt(y) + sqrt(y)sqrt(z) + sqrt(z)sqrt(x). A_n - x_n = 4^-n (A_0 - x_0)
     * exactly, which gives X, Y without cancellation (Carlson 1995, algorithm for R_F). */
    const double x0 = x, y0 = y;
    const double mean0 = (x + y + z) / 3.0;
    const double spread0 = fmax(fabs(mean0 - x), fmax(fabs(mean0 - y), fabs(mean0 - z)));
    double mean = mean0, pow4 = 1.0; /* pow4 = 4^-n */
    for (int i = 0; i < 200 && pow4 * spread0 >= 0.004 * mean; ++i) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double lambda = sx * sy + sy * sz + sz * sx;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        mean = 0.25 * (mean + lambda);
        pow4 *= 0.25;
    }
    /* DLMF 19.36.1: X = 1 - x_n/A_n etc. (X + Y + Z = 0), E2 = XY - Z^2, E3 = XYZ,
     * R_F = A^-1/2 (1 - E2/10 + E3/14 + E2^2/24 - 3 E2 E3/44 - 5 E2^3/208 + 3 E3^2/104
     *               + E2^2 E3/16); with |X|,|Y|,|Z| < 0.004 the remainder is < 1e-20. */
    double X = (mean0 - x0) * pow4 / mean;
    double Y = (mean0 - y0) * pow4 / mean;
    double Z = -(X + Y);
    double E2 = X * Y - Z * Z;
    double E3 = X * Y * Z;
    double series = 1.0 - E2 / 10.0 + E3 / 14.0 + E2 * E2 / 24.0 - 3.0 * E2 * E3 / 44.0
                    - 5.0 * E2 * E2 * E2 / 208.0 + 3.0 * E3 * E3 / 104.0
                    + E2 * E2 * E3 / 16.0;
    return series / sqrt(mean);
}

double elliptic_F(double phi, double m, double m1)
{
    if (isnan(phi) || !(m >= 0.0 && m <= 1.0) || !(m1 >= 0.0 && m1 <= 1.0)) {
        return NAN;
    }
    if (m1 == 0.0) {
        /* m = 1: F(phi | 1) = asinh(tan phi) = atanh(sin phi) for |phi| < pi/2 (A&S 17.4.21);
         * infinite from pi/2 on. */
        if (fabs(phi) >= HALF_PI_HI) {
            return copysign(INFINITY, phi);
        }
        return asinh(tan(phi));
    }
    /* phi = n pi + psi, |psi| <= pi/2, psi with pi in two parts (fma: one rounding). */
    double n = nearbyint(phi / ELLIPTIC_PI_HI);
    double psi = fma(-n, ELLIPTIC_PI_HI, phi);
    psi = fma(-n, ELLIPTIC_PI_LO, psi);
    double s = sin(psi), c = cos(psi);
    /* F(psi | m) = sin psi R_F(cos^2 psi, 1 - m sin^2 psi, 1), 1 - m sin^2 = cos^2 + m1 sin^2. */
    double f = s * elliptic_RF(c * c, c * c + m1 * s * s, 1.0);
    if (n != 0.0) {
        /* F(psi + n pi) = F(psi) + 2 n K  (A&S 17.4.3). */
        EllipticDD K = elliptic_K_dd(elliptic_dd(m1));
        f = fma(2.0 * n, K.hi, fma(2.0 * n, K.lo, f));
    }
    return f;
}

/* ------------------------------------------------------------------------------------- */
/* Jacobi elliptic functions                                                              */
/* ------------------------------------------------------------------------------------- */

int elliptic_param_init(EllipticParam *p, double m, double m1_hi, double m1_lo)
{
    return elliptic_param_init_root(p, m, m1_hi, m1_lo, NULL);
}

int elliptic_param_init_root(EllipticParam *p, double m, double m1_hi, double m1_lo, const EllipticDD *root)
{
    if (p == NULL || !(m >= 0.0 && m <= 1.0) || !(m1_hi >= 0.0 && m1_hi <= 1.0)
        || !isfinite(m1_lo) || !(fabs(m + m1_hi - 1.0) <= 1e-12)) {
        return -1;
    }
    /* written in place once the inputs are accepted (no copy) */
    EllipticParam *q = p;
    memset(q, 0, sizeof *q); /* padding too: the FMU checksums its states bytewise */
    EllipticDD m1 = elliptic_two_sum(m1_hi, m1_lo);
    q->m = m;
    q->m1 = m1.hi;
    q->k = sqrt(m);
    const EllipticDD kc = root != NULL ? *root : elliptic_dd_sqrt(m1);
    q->kc = kc.hi;
    q->levels = 0;
    for (int i = 0; i < ELLIPTIC_MAX_LEVELS; ++i) {
        q->landen_k[i] = 0.0;
        q->landen_1pk[i] = 1.0;
        q->landen_1mk[i] = 1.0;
    }
    if (m1.hi == 0.0) {
        /* m = 1: no Landen chain; sn = tanh, cn = dn = sech. */
        q->K_hi = INFINITY;
        q->K_lo = 0.0;
        q->inv_K = 0.0;
        q->K_head = INFINITY;
        q->K_tail = 0.0;
        q->bottom_scale = 1.0;
        q->bottom_m = 1.0;
        q->sqrt_k1 = 1.0;
        return 0;
    }
    EllipticDD K = K_dd_of_root(kc);   /* elliptic_K_dd(m1), sharing the root */
    q->K_hi = K.hi;
    q->K_lo = K.lo;
    q->inv_K = 1.0 / K.hi;
    q->K_head = elliptic_head26(K.hi);   /* top 26 bits of K_hi; K_tail = the rest, exact */
    q->K_tail = K.hi - q->K_head;

    /* Descending Landen sequence (A&S 16.12.1, DLMF 22.7.1; the AGM of A&S 16.4 normalised,
     * k_n = c_n / a_n, k'_n = b_n / a_n):
     *   k_{n+1} = (1 - k'_n) / (1 + k'_n) = m_n / (1 + k'_n)^2,
     *   1 - k_{n+1} = 2 k'_n / (1 + k'_n),   k'_{n+1} = 2 sqrt(k'_n) / (1 + k'_n),
     * each in the form that does not cancel. */
    double kc_n = q->kc, m_n = m;
    int n = 0;
    while ((m_n > BOTTOM_M || n == 0) && n < ELLIPTIC_MAX_LEVELS) {   /* at least one level */
        double one_plus_kc = 1.0 + kc_n;
        double k_next = kc_n < 0.5 ? (1.0 - kc_n) / one_plus_kc
                                   : m_n / (one_plus_kc * one_plus_kc);
        q->landen_k[n] = k_next;
        q->landen_1pk[n] = 1.0 + k_next;
        q->landen_1mk[n] = 2.0 * kc_n / one_plus_kc;
        kc_n = 2.0 * sqrt(kc_n) / one_plus_kc;
        m_n = k_next * k_next;
        ++n;
    }
    q->levels = n;
    q->sqrt_k1 = q->k / (1.0 + q->kc);   /* sqrt(k_1) = sqrt((1 - k')/(1 + k')) = k / (1 + k') */
    q->bottom_m = m_n;
    /* prod(1 + k_n) = K(m) / K(m_N) (descending Landen K(k) = (1 + k_1) K(k_1), DLMF
     * 19.8(ii), A&S 17.5), and
     * K(m_N) = pi/2 (1 + m_N/4 + 9 m_N^2/64 + ...)  (A&S 17.3.11): one division by K in
     * double-double instead of N rounded factors. */
    EllipticDD K_bottom = elliptic_dd_mul(fast_two_sum(HALF_PI_HI, HALF_PI_LO),
                                          elliptic_dd(1.0 + m_n * (0.25 + m_n * (9.0 / 64.0))));
    q->bottom_scale = elliptic_dd_div(K_bottom, K).hi;
    return 0;
}

double elliptic_reduce(const EllipticParam *p, double u_hi, double u_lo, double *quarters)
{
    double n = elliptic_nearest_integer((u_hi + u_lo) * p->inv_K);
    if (n == 0.0 || !(p->K_hi < INFINITY)) {
        *quarters = 0.0;
        return u_hi + u_lo;
    }
    *quarters = n;
    if (fabs(n) < 0x1p26) {
        /* Cody-Waite: n K_head and n K_tail are exact; u_hi - n K_head is exact once n is
         * more than a few (Sterbenz), otherwise all terms are small. */
        return ((u_hi - n * p->K_head) - n * p->K_tail) + (u_lo - n * p->K_lo);
    }
    if (fabs(n) < 0x1p52) {
        /* Large n: n K_hi = prod.hi + prod.lo exactly by a two-product. */
        EllipticDD prod = elliptic_two_prod(n, p->K_hi);
        return ((u_hi - prod.hi) - prod.lo) + (u_lo - n * p->K_lo);
    }
    /* Beyond 2^52 quarter periods doubles cannot resolve the phase; the exact remainder
     * modulo K_hi (C99 remquo, which also gives n mod 8) keeps the result finite. */
    int quotient_bits = 0;
    double r = remquo(u_hi, p->K_hi, &quotient_bits);
    *quarters = isnan(r) ? 0.0 : (double)(quotient_bits % 8);
    return r;
}

void elliptic_sncndn_reduced(const EllipticParam *p, double v, double *sn, double *cn, double *dn)
{
    double S, C, E, D;
    elliptic_sncndn_homogeneous(p, v, &S, &C, &E, &D);
    double inv = 1.0 / D;
    *sn = S * inv;
    *cn = C * inv;
    *dn = E * inv;
}

int elliptic_quarter_of(double n)
{
    if (fabs(n) < 0x1p62) {
        return (int)((long long)n & 3);
    }
    if (!isfinite(n)) {
        return 0;
    }
    double r = fmod(n, 4.0);
    return (int)(r < 0.0 ? r + 4.0 : r);
}

void elliptic_sncndn(const EllipticParam *p, double u, double *sn, double *cn, double *dn)
{
    double n, S, C, E, D;
    double r = elliptic_reduce(p, u, 0.0, &n);
    elliptic_sncndn_homogeneous(p, r, &S, &C, &E, &D);
    switch (elliptic_quarter_of(n)) {
    case 0: /* u = r */
        *sn = S / D;
        *cn = C / D;
        *dn = E / D;
        break;
    case 1: /* u = K + r: cd r, -k' sd r, k' nd r  (A&S 16.8.1-3) */
        *sn = C / E;
        *cn = -p->kc * S / E;
        *dn = p->kc * D / E;
        break;
    case 2: /* u = 2K + r: -sn r, -cn r, dn r */
        *sn = -S / D;
        *cn = -C / D;
        *dn = E / D;
        break;
    default: /* u = 3K + r = -K + r: -cd r, k' sd r, k' nd r */
        *sn = -C / E;
        *cn = p->kc * S / E;
        *dn = p->kc * D / E;
        break;
    }
}

double elliptic_am(const EllipticParam *p, double u)
{
    double n, S, C, E, D;
    double r = elliptic_reduce(p, u, 0.0, &n);
    elliptic_sncndn_homogeneous(p, r, &S, &C, &E, &D);
    /* am(nK + r) = n pi/2 + delta: delta = am r for even n; for odd n, sin and cos of
     * am(nK + r) - n pi/2 are proportional to k' sn r and cn r (table in elliptic.h). */
    double delta = elliptic_atan_ratio((elliptic_quarter_of(n) & 1) ? p->kc * S : S, C);   /* C > 0 */
    return fma(n, HALF_PI_HI, fma(n, HALF_PI_LO, delta));
}
