/* dd.c: sin and cos of a double-double argument (see dd.h). */
#include "dd.h"

#include <math.h>

/* pi/2 in three parts: exact halves of DD_PI_*. */
#define HALF_PI_HI   (0.5 * DD_PI_HI)
#define HALF_PI_LO   (0.5 * DD_PI_LO)
#define HALF_PI_LOLO (0.5 * DD_PI_LOLO)

/* Coefficients of the Maclaurin series of sin and cos (A&S 4.3.65-66) in double-double,
 * generated with mpmath at 300 bits: SIN_COEF[j - 1] = (-1)^j / (2j + 1)!,
 * COS_COEF[j - 1] = (-1)^j / (2j)!, j = 1..14. */
static const DoubleDouble SIN_COEF[14] = {
    {-0x1.5555555555555p-3, -0x1.5555555555555p-57}, {0x1.1111111111111p-7, 0x1.1111111111111p-63},
    {-0x1.a01a01a01a01ap-13, -0x1.a01a01a01a01ap-73}, {0x1.71de3a556c734p-19, -0x1.c154f8ddc6c00p-73},
    {-0x1.ae64567f544e4p-26, 0x1.c062e06d1f209p-80}, {0x1.6124613a86d09p-33, 0x1.f28e0cc748ebep-87},
    {-0x1.ae7f3e733b81fp-41, -0x1.1d8656b0ee8cbp-97}, {0x1.952c77030ad4ap-49, 0x1.ac981465ddc6cp-103},
    {-0x1.2f49b46814157p-57, -0x1.2650f61dbdcb4p-112}, {0x1.71b8ef6dcf572p-66, -0x1.d043ae40c4647p-120},
    {-0x1.761b41316381ap-75, 0x1.3423c7d91404fp-130}, {0x1.3f3ccdd165fa9p-84, -0x1.58ddadf344487p-139},
    {-0x1.d1ab1c2dccea3p-94, -0x1.054d0c78aea14p-149}, {0x1.259f98b4358adp-103, 0x1.eaf8c39dd9bc5p-157},
};
static const DoubleDouble COS_COEF[14] = {
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
static DoubleDouble dd_mul_add(DoubleDouble c, DoubleDouble x, DoubleDouble y)
{
    DoubleDouble p = dd_two_prod(x.hi, y.hi);
    p.lo += x.hi * y.lo + x.lo * y.hi;
    DoubleDouble s = dd_two_sum(c.hi, p.hi);
    s.lo += c.lo + p.lo;
    return dd_fast_two_sum(s.hi, s.lo);
}

#define WANT_SIN 1
#define WANT_COS 2

/* x = n pi/2 + y, |y| <= pi/4 (about): y = x - n (pi/2)_hi - n (pi/2)_lo - n (pi/2)_lolo, the
 * products n (pi/2)_hi and n (pi/2)_lo exact (two-product), n small. Returns y, *n = n. */
static DoubleDouble reduce_half_pi(DoubleDouble x, double *quadrants)
{
    const double n = nearbyint(x.hi / HALF_PI_HI);
    *quadrants = n;
    if (n == 0.0) {
        return x;
    }
    DoubleDouble y = dd_add(x, dd_neg(dd_two_prod(n, HALF_PI_HI)));
    y = dd_add(y, dd_neg(dd_two_prod(n, HALF_PI_LO)));
    return dd_add(y, dd_of(-n * HALF_PI_LOLO));
}

/* sum_{j < n} coef[j] z^j + z^n tail for a double-double z (z2 = z^2), by Horner's scheme
 * split into two chains in z^2 that the processor runs side by side (the even and the odd
 * powers, A(z^2) + z B(z^2)), half the depth of one chain: every step adds a term far below
 * the partial sum (|coef[j + 2] z^2| <= 0.02 |coef[j]|), as dd_mul_add needs. */
static DoubleDouble horner_two_chains(const DoubleDouble *coef, int n, double tail, DoubleDouble z, DoubleDouble z2)
{
    /* the tail belongs to the chain of power n: even (A) or odd (B) */
    DoubleDouble even = dd_of((n % 2 == 0) ? tail : 0.0);
    DoubleDouble odd = dd_of((n % 2 == 1) ? tail : 0.0);
    for (int j = n - 1; j >= 0; --j) {
        if (j % 2 == 0) {
            even = dd_mul_add(coef[j], z2, even);
        } else {
            odd = dd_mul_add(coef[j], z2, odd);
        }
    }
    return dd_add(even, dd_mul(z, odd));
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
static void sincos_reduced(DoubleDouble y, int want, DoubleDouble *sin_y, DoubleDouble *cos_y)
{
    const DoubleDouble y2 = dd_mul(y, y);
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
    const DoubleDouble y4 = dd_mul(y2, y2);
    if (want & WANT_SIN) {
        const DoubleDouble p = horner_two_chains(SIN_COEF, J - 1, tail_s, y2, y4);
        *sin_y = dd_add(y, dd_mul(dd_mul(y, y2), p));
    } else {
        for (int j = J - 2; j >= 0; --j) {
            tail_s = SIN_COEF[j].hi + z * tail_s;
        }
        *sin_y = dd_of(y.hi + y.hi * z * tail_s);
    }
    if (want & WANT_COS) {
        const DoubleDouble q = horner_two_chains(COS_COEF, J - 1, tail_c, y2, y4);
        *cos_y = dd_add(dd_of(1.0), dd_mul(y2, q));
    } else {
        for (int j = J - 2; j >= 0; --j) {
            tail_c = COS_COEF[j].hi + z * tail_c;
        }
        *cos_y = dd_of(1.0 + z * tail_c);
    }
}

/* n mod 4 for an integer-valued double n, without integer overflow. */
static int quadrant_of(double n)
{
    return (int)(n - 4.0 * floor(0.25 * n));
}

void dd_sincos(DoubleDouble x, DoubleDouble *sin_x, DoubleDouble *cos_x)
{
    if (!isfinite(x.hi)) {
        *sin_x = *cos_x = dd_of(NAN);
        return;
    }
    double n;
    DoubleDouble sin_y, cos_y;
    sincos_reduced(reduce_half_pi(x, &n), WANT_SIN | WANT_COS, &sin_y, &cos_y);
    /* sin(y + n pi/2), cos(y + n pi/2) by the quadrant n mod 4. */
    switch (quadrant_of(n)) {
    case 0: *sin_x = sin_y;         *cos_x = cos_y;         break;
    case 1: *sin_x = cos_y;         *cos_x = dd_neg(sin_y); break;
    case 2: *sin_x = dd_neg(sin_y); *cos_x = dd_neg(cos_y); break;
    default: *sin_x = dd_neg(cos_y); *cos_x = sin_y;        break;
    }
}

void dd_cos_sin(DoubleDouble x, DoubleDouble *cos_x, double *sin_x)
{
    if (!isfinite(x.hi)) {
        *cos_x = dd_of(NAN);
        *sin_x = NAN;
        return;
    }
    double n;
    const DoubleDouble y = reduce_half_pi(x, &n);
    const int quadrant = quadrant_of(n);
    DoubleDouble sin_y, cos_y;
    /* cos x is +-cos y for even n, -+sin y for odd n: only that one in double-double */
    sincos_reduced(y, (quadrant & 1) ? WANT_SIN : WANT_COS, &sin_y, &cos_y);
    switch (quadrant) {
    case 0: *sin_x = sin_y.hi;  *cos_x = cos_y;                   break;
    case 1: *sin_x = cos_y.hi;  *cos_x = dd_neg(sin_y);  break;
    case 2: *sin_x = -sin_y.hi; *cos_x = dd_neg(cos_y);  break;
    default: *sin_x = -cos_y.hi; *cos_x = sin_y;                  break;
    }
}
