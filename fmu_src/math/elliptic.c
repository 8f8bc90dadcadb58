/* elliptic.c: K, F, sn, cn, dn, am (see elliptic.h for the method and the references). */
#include "elliptic.h"

#include <stddef.h>
#include <string.h>
#include <math.h>

/* pi/2 in three parts: exact halves of DD_PI_*. */
#define HALF_PI_HI   (0.5 * DD_PI_HI)
#define HALF_PI_LO   (0.5 * DD_PI_LO)
#define HALF_PI_LOLO (0.5 * DD_PI_LOLO)

/* The bottom of the Landen descent: once m_N <= BOTTOM_M, A&S 16.13.1-3 is used. Its error
 * is O(m_N^2): measured with mpmath (m = 1e-4, |z| <= pi/4), the relative error of sn, cn, dn
 * is below 0.0045 m^2, so below 1.2e-17 here. */
#define BOTTOM_M 5e-8

/* ------------------------------------------------------------------------------------- */
/* K and Carlson's R_F                                                                     */
/* ------------------------------------------------------------------------------------- */

/* 1/pi in two parts (mpmath, 300 bits). */
#define INV_PI_HI 0x1.45f306dc9c883p-2
#define INV_PI_LO (-0x1.6b01ec5417056p-56)

/* *mean (f_hi + f_lo) for |f_lo| of the order of ulp(f_hi), with what the double-double
 * product rounds off carried in *error (the compensated product: the three leading partial
 * products are two-products, the low part their exact sum but for two TwoSum errors, which go
 * to *error with the products below 2^-106): the mean of the Landen levels then keeps about
 * 2^-106 relative over its N factors, where N plain products would lose N times that. */
static void mean_times(DoubleDouble *mean, double *error, double f_hi, double f_lo)
{
    const DoubleDouble p = dd_two_prod(mean->hi, f_hi), a = dd_two_prod(mean->hi, f_lo);
    const DoubleDouble b = dd_two_prod(mean->lo, f_hi);
    const DoubleDouble s1 = dd_two_sum(p.lo, a.hi), s2 = dd_two_sum(s1.hi, b.hi);
    *error = *error * f_hi + (((s1.lo + s2.lo) + (a.lo + b.lo)) + mean->lo * f_lo);
    *mean = dd_fast_two_sum(p.hi, s2.hi);
}

/* K and 1/K in double-double from the bottom of the Landen chain: mean = prod_{n < N}
 * (1 + kappa_n)/2, the AGM's a_N for a_0 = 1 (A&S 17.6), and the exact complementary
 * modulus kappa_N = kc_N + tail of the last level, m_N = 1 - kappa_N^2 <= BOTTOM_M (the mean
 * given as mean + mean_error, mean_times). With
 * AGM(1, k') = a_N AGM(1, kappa_N) and K = (pi/2) / AGM (DLMF 19.8.5), d = 1 - kappa_N
 * (exact: 1 - kc_N by Sterbenz, then TwoSum),
 *   K   = ((pi/2) / mean) (1 + S),  1 + S = 2F1(1/2, 1/2; 1; 2d - d^2),
 *   1/K = ((2/pi) mean) (1 - T),    1 - T = AGM(1, 1 - d),
 *   S = d/2 + 5 d^2/16 + 7 d^3/32 + 169 d^4/1024,  T = d/2 + d^2/16 + d^3/32 + 21 d^4/1024,
 * the Maclaurin series in d of 2F1 (A&S 17.3.11 with m = 2d - d^2) and of its reciprocal
 * (mpmath.taylor; d < 2^-25, so the next terms are below 2^-125). (pi/2)/mean and
 * (2/pi) mean are formed while the last level is still being computed; S and T are below
 * 2^-26, so K and 1/K are each the leading part plus a small product (the terms of d^2 by
 * two-products, the rest in double, each within 2^-107 of K). */
static DoubleDouble landen_K(DoubleDouble mean, double mean_error, double kc_N, double tail, DoubleDouble *inv_K)
{
    DoubleDouble A = dd_div(dd_fast_two_sum(HALF_PI_HI, HALF_PI_LO), mean);
    DoubleDouble B = dd_mul(mean, dd_fast_two_sum(2.0 * INV_PI_HI, 2.0 * INV_PI_LO));
    /* the mean's rounding error: (pi/2)/(mean + e) = A - A^2 (2/pi) e, (2/pi)(mean + e) = B + (2/pi) e */
    A.lo -= A.hi * (A.hi * (mean_error * (2.0 * INV_PI_HI)));
    B.lo += mean_error * (2.0 * INV_PI_HI);
    const DoubleDouble d = dd_two_sum(1.0 - kc_N, -tail);
    DoubleDouble d2 = dd_two_prod(d.hi, d.hi);
    d2.lo += 2.0 * d.hi * d.lo;
    const double cube = d.hi * d2.hi;
    const DoubleDouble s2 = dd_two_prod(0.3125, d2.hi);                  /* 5/16 d^2 */
    DoubleDouble S = dd_fast_two_sum(0.5 * d.hi, s2.hi);
    S.lo += (s2.lo + 0.3125 * d2.lo + 0.5 * d.lo) + cube * (7.0 / 32.0 + d.hi * (169.0 / 1024.0));
    DoubleDouble T = dd_fast_two_sum(0.5 * d.hi, 0.0625 * d2.hi);        /* 1/16 d^2: exact */
    T.lo += (0.0625 * d2.lo + 0.5 * d.lo) + cube * (1.0 / 32.0 + d.hi * (21.0 / 1024.0));
    const DoubleDouble AS = dd_two_prod(A.hi, S.hi), BT = dd_two_prod(B.hi, T.hi);
    DoubleDouble K = dd_fast_two_sum(A.hi, AS.hi);
    K.lo += A.lo + (AS.lo + (A.hi * S.lo + A.lo * S.hi));
    DoubleDouble inverse = dd_fast_two_sum(B.hi, -BT.hi);
    inverse.lo += B.lo - (BT.lo + (B.hi * T.lo + B.lo * T.hi));
    *inv_K = dd_fast_two_sum(inverse.hi, inverse.lo);
    return dd_fast_two_sum(K.hi, K.lo);
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
    double series = ELLIPTIC_RF_SERIES(E2, E3);
    return series / sqrt(mean);
}

/* ------------------------------------------------------------------------------------- */
/* Jacobi elliptic functions                                                              */
/* ------------------------------------------------------------------------------------- */

int elliptic_param_init(EllipticParam *p, double m, double m1_hi, double m1_lo)
{
    EllipticParam fresh;
    memset(&fresh, 0, sizeof fresh);   /* padding too: the FMU checksums its states bytewise */
    DoubleDouble inv_K;
    if (p == NULL || elliptic_param_init_root(&fresh, m, m1_hi, m1_lo, NULL, &inv_K) != 0) {
        return -1;
    }
    memcpy(p, &fresh, sizeof fresh);
    return 0;
}

int elliptic_param_init_root(EllipticParam *p, double m, double m1_hi, double m1_lo, const DoubleDouble *root,
                             DoubleDouble *inv_K)
{
    if (p == NULL || !elliptic_param_acceptable(m, m1_hi, m1_lo)) {
        return -1;
    }
    /* written in place once the inputs are accepted (no copy); the caller cleared its bytes */
    const DoubleDouble m1 = dd_two_sum(m1_hi, m1_lo);
    const DoubleDouble kc = root != NULL ? *root : dd_sqrt(m1);
    if (m1.hi == 0.0) {
        /* m = 1: no Landen chain; sn = tanh, cn = dn = sech. */
        p->m = m;
        p->k = sqrt(m);
        p->kc = kc.hi;
        for (int i = 0; i < ELLIPTIC_MAX_LEVELS; ++i) {
            p->landen_1pk[i] = 1.0;
            p->landen_1mk[i] = 1.0;
        }
        p->K_hi = INFINITY;
        p->K_lo = 0.0;
        p->inv_K = 0.0;
        p->K_head = INFINITY;
        p->K_tail = 0.0;
        p->bottom_scale = 1.0;
        p->bottom_m = 1.0;
        p->sqrt_k1 = 1.0;
        *inv_K = dd_of(0.0);
        return 0;
    }
    EllipticChain chain;
    elliptic_param_begin(p, m, kc.hi, &chain);
    elliptic_param_finish(p, &chain, m1.hi, kc.lo, inv_K);
    return 0;
}

void elliptic_param_begin(EllipticParam *p, double m, double kc, EllipticChain *chain)
{
    p->m = m;
    p->k = sqrt(m);
    p->kc = kc;
    for (int i = 0; i < ELLIPTIC_MAX_LEVELS; ++i) {   /* landen_k and levels: zero on entry */
        p->landen_1pk[i] = 1.0;
        p->landen_1mk[i] = 1.0;
    }
    /* Descending Landen sequence (A&S 16.12.1, DLMF 22.7.1; the AGM of A&S 16.4 normalised,
     * k_n = c_n / a_n, k'_n = b_n / a_n):
     *   k_{n+1} = (1 - k'_n) / (1 + k'_n) = m_n / (1 + k'_n)^2,
     *   1 - k_{n+1} = 2 k'_n / (1 + k'_n),   k'_{n+1} = 2 sqrt(k'_n) / (1 + k'_n),
     * each in the form that does not cancel, all from the double k' (the halves (1 + k'_n)/2
     * are exact, so k'_n / ((1 + k'_n)/2) is the rounded 2 k'_n / (1 + k'_n) itself). Not
     * rounded from a more accurate chain: its moduli would be the correctly rounded ones, but
     * each level is then not the Landen transform of the rounded level above it, and the
     * evaluation, which passes through the levels in turn, loses more (measured: theta's mean
     * error at 170 deg from rest 3.2e-16 rad against 2.2e-16 with this chain). Every m_1 >= the
     * smallest subnormal reaches m_N <= BOTTOM_M within 11 levels. */
    double kc_n = kc, m_n = m;
    int n = 0;
    while ((m_n > BOTTOM_M || n == 0) && n < ELLIPTIC_MAX_LEVELS) {   /* at least one level */
        const double one_plus_kc = 1.0 + kc_n, half = 0.5 * one_plus_kc;   /* half: exact */
        const double root_kc = sqrt(kc_n);
        const double kc_next = root_kc / half;   /* 2 sqrt(k'_n) / (1 + k'_n) */
        const double k_next = kc_n < 0.5 ? (1.0 - kc_n) / one_plus_kc
                                         : m_n / (one_plus_kc * one_plus_kc);
        p->landen_k[n] = k_next;
        p->landen_1pk[n] = 1.0 + k_next;
        p->landen_1mk[n] = kc_n / half;
        chain->kc[n] = kc_n;
        chain->root[n] = root_kc;
        chain->one_plus[n] = one_plus_kc;
        kc_n = kc_next;
        m_n = k_next * k_next;
        ++n;
    }
    chain->kc[n] = kc_n;
    p->levels = n;
    p->sqrt_k1 = p->k / (1.0 + kc);   /* sqrt(k_1) = sqrt((1 - k')/(1 + k')) = k / (1 + k') */
    p->bottom_m = m_n;
}

void elliptic_param_finish(EllipticParam *p, const EllipticChain *chain, double m1, double kc_lo,
                           DoubleDouble *inv_K)
{
    p->m1 = m1;
    /* K in double-double from the same levels (landen_K): the exact complementary modulus of
     * level n is kappa_n = kc_n + tail_n, the tail carried to first order beside the double
     * chain, and K = K(m_N) / prod_{n < N} (1 + kappa_n)/2. kappa_{n+1} = 2 sqrt(kappa_n) /
     * (1 + kappa_n) to first order in the tails and in the rounding errors of level n, each
     * exact: e_h = (1 + kc_n) - one_plus (Fast2Sum), e_s = kc_n - root^2 and
     * e_q = 2 root - kc_{n+1} one_plus (the residuals of a correctly rounded root and quotient
     * are doubles; two-products, Sterbenz):
     *   tail_{n+1} = (root e_q + (e_s + tail_n) - root kc_{n+1} (e_h + tail_n)) / (root one_plus),
     * what is left out of the order of tail^2 / kc_n, ~2^-106 relative. */
    double tail = kc_lo;
    DoubleDouble mean = dd_of(1.0);   /* prod_{i < n} (1 + kappa_i)/2: the AGM's a_n for a_0 = 1 */
    double mean_error = 0.0;          /* ... less mean: what its double-double has rounded off */
    for (int n = 0; n < p->levels; ++n) {
        const double kc_n = chain->kc[n], root = chain->root[n], one_plus = chain->one_plus[n];
        const double kc_next = chain->kc[n + 1];
        const double e_h = kc_n - (one_plus - 1.0);
        const DoubleDouble root_sq = dd_two_prod(root, root);
        const double e_s = (kc_n - root_sq.hi) - root_sq.lo;
        const DoubleDouble product = dd_two_prod(kc_next, one_plus);
        const double e_q = (2.0 * root - product.hi) - product.lo;
        const double tail_h = e_h + tail;   /* 1 + kappa_n = one_plus + tail_h */
        mean_times(&mean, &mean_error, 0.5 * one_plus, 0.5 * tail_h);
        tail = ((root * e_q + (e_s + tail)) - root * kc_next * tail_h) / (root * one_plus);
    }
    const DoubleDouble K = landen_K(mean, mean_error, chain->kc[p->levels], tail, inv_K);
    p->K_hi = K.hi;
    p->K_lo = K.lo;
    p->inv_K = 1.0 / K.hi;   /* as before: the correctly rounded 1/K.hi */
    p->K_head = dd_head26(K.hi);   /* top 26 bits of K_hi; K_tail = the rest, exact */
    p->K_tail = K.hi - p->K_head;
    /* prod(1 + k_n) = K(m) / K(m_N) (descending Landen K(k) = (1 + k_1) K(k_1), DLMF
     * 19.8(ii), A&S 17.5), and
     * K(m_N) = pi/2 (1 + m_N/4 + 9 m_N^2/64 + ...)  (A&S 17.3.11): one division by K in
     * double-double instead of N rounded factors. */
    const double m_n = p->bottom_m;
    const DoubleDouble K_bottom = dd_mul(dd_fast_two_sum(HALF_PI_HI, HALF_PI_LO),
                                         dd_of(1.0 + m_n * (0.25 + m_n * (9.0 / 64.0))));
    p->bottom_scale = dd_mul(K_bottom, *inv_K).hi;
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
