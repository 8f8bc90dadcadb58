/* dd.h: double-double arithmetic. A value is hi + lo with |lo| <= ulp(hi)/2 (Dekker, Numer.
 * Math. 18 (1971) 224-242; Knuth, TAOCP vol. 2, 4.2.2), about 106 significant bits.
 *
 * The exact port uses it where a double is not enough: K and the phase rate over long
 * horizons, the parameter next to the separatrix (elliptic.c, exact.c), and the solvers'
 * energy reference (integrator_core.c). Beside the arithmetic it holds the exact bit-level
 * helpers those set-ups need (power-of-two scaling, the 26-bit head of a double, the nearest
 * integer) and, in dd.c, sin and cos of a double-double argument.
 *
 * The operations are static inline: the set-ups run long chains of them, which then compile
 * without calls. They need IEEE double arithmetic without extended precision (SSE2 or
 * better) and no contraction of a*b+c into an fma (the project builds with
 * -ffp-contract=off). All functions are pure. */
#ifndef PENDULUM_DD_H
#define PENDULUM_DD_H

#include <math.h>
#include <stdint.h>
#include <string.h>

typedef struct {
    double hi, lo;
} DoubleDouble;

/* pi in three parts (pi = DD_PI_HI + DD_PI_LO + DD_PI_LOLO to ~1e-48), generated with mpmath. */
#define DD_PI_HI   0x1.921fb54442d18p+1
#define DD_PI_LO   0x1.1a62633145c07p-53
#define DD_PI_LOLO (-0x1.f1976b7ed8fbcp-109)

/* The double-double x + 0. */
static inline DoubleDouble dd_of(double x)
{
    DoubleDouble r;
    r.hi = x;
    r.lo = 0.0;
    return r;
}

/* -x, exactly. */
static inline DoubleDouble dd_neg(DoubleDouble x)
{
    x.hi = -x.hi;
    x.lo = -x.lo;
    return x;
}

/* s + err = a + b exactly, s = fl(a + b) (Knuth's TwoSum, TAOCP 4.2.2 Theorem B). */
static inline DoubleDouble dd_two_sum(double a, double b)
{
    DoubleDouble r;
    double b_virtual;
    r.hi = a + b;
    b_virtual = r.hi - a;
    r.lo = (a - (r.hi - b_virtual)) + (b - b_virtual);
    return r;
}

/* s + err = a + b exactly, valid when |a| >= |b| or a == 0 (Dekker's Fast2Sum). */
static inline DoubleDouble dd_fast_two_sum(double a, double b)
{
    DoubleDouble r;
    r.hi = a + b;
    r.lo = b - (r.hi - a);
    return r;
}

/* p + err = a * b exactly, p = fl(a b). With a hardware fma (FP_FAST_FMA, C11 7.12, or
 * PENDULUM_DD_FMA: the fma build of exact_fma.c):
 * err = fma(a, b, -p), exact by the single rounding. Otherwise Dekker's product (Dekker 1971,
 * mul12): Veltkamp's split of a and b into 26-bit halves, whose partial products are exact
 * (valid for |a|, |b| < 2^995). */
static inline DoubleDouble dd_two_prod(double a, double b)
{
    DoubleDouble r;
    r.hi = a * b;
#if defined(FP_FAST_FMA) || defined(PENDULUM_DD_FMA)
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

/* x + y in double-double (relative error a few 2^-104): the sum of the high parts and of the
 * low parts, each error-free, then two renormalisations (the "accurate" double-double
 * addition of Hida, Li and Bailey's QD library). */
static inline DoubleDouble dd_add(DoubleDouble x, DoubleDouble y)
{
    DoubleDouble s = dd_two_sum(x.hi, y.hi);
    DoubleDouble t = dd_two_sum(x.lo, y.lo);
    s.lo += t.hi;
    s = dd_fast_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return dd_fast_two_sum(s.hi, s.lo);
}

/* x - y, as x + (-y). */
static inline DoubleDouble dd_sub(DoubleDouble x, DoubleDouble y)
{
    return dd_add(x, dd_neg(y));
}

/* x y: (xh + xl)(yh + yl) = xh yh (exact two-product) + xh yl + xl yh + O(2^-106). */
static inline DoubleDouble dd_mul(DoubleDouble x, DoubleDouble y)
{
    DoubleDouble p = dd_two_prod(x.hi, y.hi);
    p.lo += x.hi * y.lo + x.lo * y.hi;
    return dd_fast_two_sum(p.hi, p.lo);
}

/* x / y by Dekker's div2: q1 = x.hi / y.hi, the remainder x - q1 y with q1 y.hi exact
 * (two-product; x.hi - p.hi is exact by Sterbenz), then q2 = remainder / y.hi. Relative error
 * a few 2^-104 (Dekker 1971, section 8). */
static inline DoubleDouble dd_div(DoubleDouble x, DoubleDouble y)
{
    const double q1 = x.hi / y.hi;
    const DoubleDouble p = dd_two_prod(q1, y.hi);
    const double remainder = (((x.hi - p.hi) - p.lo) + x.lo) - q1 * y.lo;
    return dd_fast_two_sum(q1, remainder / y.hi);
}

/* sqrt(x) for x >= 0 (NaN below): one Newton step from the double root s,
 * sqrt(x) = s + (x - s^2) / (2 s), with s^2 formed exactly by a two-product. */
static inline DoubleDouble dd_sqrt(DoubleDouble x)
{
    if (!(x.hi > 0.0)) {
        return dd_of(x.hi == 0.0 ? 0.0 : NAN);
    }
    if (isinf(x.hi)) {
        return dd_of(x.hi);
    }
    if (x.hi < 0x1p-900) {
        /* keep the error terms of the two-product out of the subnormal range: scale by an
         * even power of two (exact) */
        DoubleDouble scaled = {x.hi * 0x1p1000, x.lo * 0x1p1000};
        DoubleDouble root = dd_sqrt(scaled);
        root.hi *= 0x1p-500;
        root.lo *= 0x1p-500;
        return root;
    }
    double s = sqrt(x.hi);
    DoubleDouble sq = dd_two_prod(s, s);
    double correction = (((x.hi - sq.hi) - sq.lo) + x.lo) / (2.0 * s);
    return dd_fast_two_sum(s, correction);
}

/* Biased exponent field of x (0 for zero and subnormals, 0x7ff for inf and NaN). */
static inline int dd_biased_exponent(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return (int)((bits >> 52) & 0x7ff);
}

/* x 2^e, the value of ldexp(x, e) (scalbn: the radix is 2): a multiplication by the power of
 * two built from its bits (exact, or one rounding for a subnormal result, as ldexp) when 2^e
 * is a normal double, else ldexp itself. Avoids a libm call in the set-ups. */
static inline double dd_scalbn(double x, int e)
{
    if (e >= -1022 && e <= 1023) {
        const uint64_t bits = (uint64_t)(e + 1023) << 52;
        double power;
        memcpy(&power, &bits, sizeof power);
        return x * power;
    }
    return ldexp(x, e);
}

/* x 2^exponent for a double-double (exact unless it overflows or underflows). */
static inline DoubleDouble dd_ldexp(DoubleDouble x, int exponent)
{
    x.hi = dd_scalbn(x.hi, exponent);
    x.lo = dd_scalbn(x.lo, exponent);
    return x;
}

/* The exponent frexp would give (x = f 2^e, 1/2 <= |f| < 1), from the bits for a normal x. */
static inline int dd_frexp_exponent(double x)
{
    const int biased = dd_biased_exponent(x);
    if (biased != 0 && biased != 0x7ff) {
        return biased - 1022;
    }
    int exponent = 0;
    (void)frexp(x, &exponent);
    return exponent;
}

/* The leading 26 significant bits of x (truncated), so that head * n is exact for |n| < 2^27
 * and x - head is exact with at most 27 significant bits (Cody-Waite splitting). For a normal
 * x the low 27 bits of the significand are cleared; otherwise formed with frexp/ldexp/trunc.
 * Both are exact, so no floating-point contraction can spoil it (unlike Veltkamp's split). */
static inline double dd_head26(double x)
{
    const int biased = dd_biased_exponent(x);
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
static inline double dd_nearest_integer(double x)
{
    if (fabs(x) < 0x1p51) {
        const double shift = 0x1.8p52;
        return (x + shift) - shift;
    }
    return nearbyint(x);
}

/* sin x and cos x for a double-double argument |x| <= 2 pi (relative accuracy ~1e-31, also
 * near the zeros): x = n pi/2 + y with pi/2 in three parts, |y| <= pi/4, Maclaurin series
 * of sin y and cos y (A&S 4.3.65-66) summed in double-double, then the quadrant (dd.c). */
void dd_sincos(DoubleDouble x, DoubleDouble *sin_x, DoubleDouble *cos_x);

/* cos x in double-double and sin x as a double (within an ulp or so) for |x| <= 2 pi, for the
 * exact port's set-up: x = n pi/2 + y as above, and the one of cos y, sin y that gives cos x
 * by a table of cos and sin at multiples of 1/64 and the series of sin and 1 - cos of the
 * remainder |r| <= 1/128 (~2^-104 relative; a fifth of dd_sincos's work), the other as the
 * Maclaurin series in double that dd_sincos has always used for its double result (so sin x
 * has the same bits as before). */
void dd_cos_sin(DoubleDouble x, DoubleDouble *cos_x, double *sin_x);

/* dd_cos_sin in two steps, for a caller that can start on the leading double of cos x before
 * its low part is known (the exact port's set-up from rest): dd_cos_sin_begin reduces x, forms
 * sin x (the double of dd_cos_sin) and the leading double of cos x by a shorter sum, with
 * cos_lead_certain = 1 when that double is certainly cos x rounded to nearest (all but about
 * one argument in 10^4); dd_cos_sin_end gives cos x in double-double, whose leading double is
 * then cos_lead. */
typedef struct {
    double sign;           /* y = sign |y| */
    DoubleDouble r;        /* |y| - a, a = i/64 the table point nearest |y| */
    DoubleDouble C, S;     /* cos a, sin a */
} DdTablePoint;

typedef struct {
    DoubleDouble y;        /* x - n pi/2, |y| <= pi/4 */
    DdTablePoint point;    /* |y|'s place in the table */
    int quadrant;          /* n mod 4 */
    double sin_x;          /* sin x, the double of dd_cos_sin */
    double cos_lead;       /* the leading double of cos x when cos_lead_certain */
    int cos_lead_certain;
} DdCosSin;

void dd_cos_sin_begin(DoubleDouble x, DdCosSin *t);
DoubleDouble dd_cos_sin_end(const DdCosSin *t);

/* sin x in double-double for |x| <= 2 pi by the table of dd_cos_sin (~2^-104 relative). */
DoubleDouble dd_sin(DoubleDouble x);

#endif
