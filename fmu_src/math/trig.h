/* trig.h: sine and cosine of a double, inline: the bottom level of the Landen chain
 * (trig_sincos_small, elliptic.h), rkn's stages (trig_sin_moved) and the outputs x and y (one
 * trig_sincos for both).
 *
 * The project's other sine and cosine, dd_sincos (dd.h, dd.c), takes a double-double to
 * ~1e-31 for the once-per-state set-ups and sums its series in double-double; these are the
 * 1-ulp double ones of the evaluation and step loops, inline and without a libm call on the
 * usual path. The two share no arithmetic, so each stays with its precision.
 *
 * rkn evaluates sin(theta) at 16 stages a step, 15 of them one after another on the step's
 * chain of dependent operations, where libm's sin is a call with branches on the argument's
 * range and a range reduction. trig_sin_moved needs no reduction (the stages lie near the
 * step's start, whose sine and cosine are known). trig_sincos, for |x| < 2^19:
 *   x = k pi/2 + r, k the integer nearest to x 2/pi, |r| <= pi/4 (plus a rounding);
 *   r = ((x - k P1) - k P2) - k P3 (Cody and Waite), with pi/2 = P1 + P2 + P3 + 1e-37:
 *     P1 and P2 hold 33 bits each, so k P1 and k P2 are exact for |k| < 2^20, and
 *     x - k P1 is exact (Sterbenz: x and k P1 lie within a factor 2 of each other); the
 *     last two subtractions keep their rounding errors in r_lo;
 *   sin r = r + r^3 (-1/3! + r^2/5! - ... + r^14/17!),
 *   cos r = 1 + r^2 (-1/2! + r^2/4! - ... + r^14/16!), Taylor series: the first omitted terms
 *     are below 1e-19 at |r| = pi/4, so the error is the rounding of the sums: 1 ulp;
 *   by the quadrant q = k mod 4: sin x = (s, c, -s, -c)[q], cos x = (c, -s, -c, s)[q].
 * Both series are evaluated and the quadrant selects between them (conditional moves, not
 * branches). The same bits on every platform (no libm, contraction off). Beyond 2^19
 * (rotations past 80,000 turns), and for infinities and NaN, libm; below 2^-27, sin x = x
 * and cos x = 1.
 * tests/c/test_trig.c compares both with libm (1 ulp) over every quadrant and scale. */
#ifndef PENDULUM_TRIG_H
#define PENDULUM_TRIG_H

#include <math.h>

#define TRIG_REDUCE_LIMIT 524288.0   /* 2^19: |k| < 2^19 (2/pi) < 2^20 */
#define TRIG_TINY 7.450580596923828e-09   /* 2^-27: x^2/2 < 2^-55, below half an ulp of 1 */

/* (-1)^floor(n/2) / n!, correctly rounded: the Taylor coefficients of sin and cos */
#define TRIG_TERMS 18
static const double TRIG_SIGNED_INVERSE_FACTORIAL[TRIG_TERMS] = {
    1.0, 1.0, -0.5, -0.16666666666666666, 0.041666666666666664, 0.008333333333333333,
    -0.001388888888888889, -0.0001984126984126984, 2.48015873015873e-05, 2.7557319223985893e-06,
    -2.755731922398589e-07, -2.505210838544172e-08, 2.08767569878681e-09, 1.6059043836821613e-10,
    -1.1470745597729725e-11, -7.647163731819816e-13, 4.779477332387385e-14, 2.8114572543455206e-15};

/* The series' tails in z = r^2 for |r| <= pi/4 (plus a rounding): sin r = r + r z ps,
 * cos r = 1 + z pc, ps = sum_k c_{2k+3} z^k and pc = sum_k c_{2k+2} z^k with c the table above.
 * Estrin's scheme: half the dependent steps of Horner's. */
static inline void trig_series(double z, double *ps, double *pc)
{
    const double *c = TRIG_SIGNED_INVERSE_FACTORIAL;
    const double z2 = z * z, z4 = z2 * z2;
    *ps = ((c[3] + z * c[5]) + z2 * (c[7] + z * c[9]))
          + z4 * ((c[11] + z * c[13]) + z2 * (c[15] + z * c[17]));
    *pc = ((c[2] + z * c[4]) + z2 * (c[6] + z * c[8]))
          + z4 * ((c[10] + z * c[12]) + z2 * (c[14] + z * c[16]));
}

/* sin r and cos r for a double |r| <= 0.8 without a low part: sin r = r + r z ps,
 * cos r = 1 + z pc, z = r^2. The first omitted terms, r^19/19! and r^18/18!, stay below 2e-19
 * and 3e-18 relative up to |r| = 0.8, so the error is the rounding of the sums: 1 ulp. The
 * bottom level of the Landen chain (elliptic.h) takes its sine and cosine here. */
static inline void trig_sincos_small(double r, double *sin_r, double *cos_r)
{
    const double z = r * r;
    double ps, pc;
    trig_series(z, &ps, &pc);
    *sin_r = r + (r * z) * ps;
    *cos_r = 1.0 + z * pc;
}

/* sin and cos of r + r_lo for |r| <= pi/4 (plus a rounding), |r_lo| <= ulp(r) */
static inline void trig_kernel(double r, double r_lo, double *s, double *c)
{
    const double z = r * r;
    double ps, pc;
    trig_series(z, &ps, &pc);
    /* sin(r + r_lo) = sin r + r_lo cos r, cos(r + r_lo) = cos r - r_lo sin r, to first order */
    *s = r + ((r * z) * ps + r_lo);
    *c = 1.0 + (z * pc - r * r_lo);
}

/* sin x and cos x, both */
static inline void trig_sincos(double x, double *sin_x, double *cos_x)
{
    if (!(fabs(x) < TRIG_REDUCE_LIMIT)) {
        *sin_x = sin(x);
        *cos_x = cos(x);
        return;
    }
    if (fabs(x) < TRIG_TINY) {   /* sin x = x and cos x = 1 correctly rounded; keeps the sign of -0 */
        *sin_x = x;
        *cos_x = 1.0;
        return;
    }
    const double round_magic = 6755399441055744.0;   /* 1.5 * 2^52: adding it rounds to an integer */
    const double k = (x * 0.6366197723675814 + round_magic) - round_magic;   /* nearest to x 2/pi */
    /* r = r_hi + r_lo: the subtractions' rounding errors kept (Fast2Sum), so that a result
     * smaller than r (sin r below 1/2 while r is above it) is not one ulp of r off */
    const double t1 = x - k * 1.5707963267341256, w2 = k * 6.077100506303966e-11, w3 = k * 2.0222662487959506e-21;
    const double r1 = t1 - w2, e1 = (t1 - r1) - w2;
    const double r = r1 - w3, r_lo = ((r1 - r) - w3) + e1;
    double s, c;
    trig_kernel(r, r_lo, &s, &c);
    const int q = (int)k & 3;   /* two's complement: k mod 4 for negative k too */
    const double sin_mag = (q & 1) ? c : s, cos_mag = (q & 1) ? s : c;   /* selections (cmov) */
    *sin_x = (q & 2) ? -sin_mag : sin_mag;
    *cos_x = ((q + 1) & 2) ? -cos_mag : cos_mag;
}

static inline double trig_sin(double x)
{
    double s, c;
    trig_sincos(x, &s, &c);
    return s;
}

/* sin(x0 + d) for the moves d of one step from x0, as the Taylor polynomial in d:
 * sin(x0 + d) = sum_n a_n d^n, a_n = sin^(n)(x0) / n! = (sin x0, cos x0, -sin x0, -cos x0, ...)_n / n!,
 * its coefficients formed once a step (trig_moved_coefficients) from sin x0 and cos x0. For
 * |d| <= pi/4 the first omitted term, (pi/4)^18 / 18!, is 2e-18: no range reduction.
 * trig_sin_moved returns the sine in two parts, lead = a_0 + a_1 d and *rest = the terms from
 * d^2 on (Estrin's scheme in d, d^2, d^4 and d^10: 8 dependent operations from d), so that a
 * caller that multiplies the sine can take the product of the lead while the rest is still
 * being summed. lead + *rest is within 3 ulps of |sin x0| + |d|, what the rounding of x0 + d
 * alone would cost (tests/c/test_trig.c). Larger moves (and NaN) return trig_sin(x0 + d) as
 * the lead, with a rest of 0. */
static inline void trig_moved_coefficients(double sin_x0, double cos_x0, double a[TRIG_TERMS])
{
    for (int n = 0; n < TRIG_TERMS; n++)
        a[n] = ((n & 1) ? cos_x0 : sin_x0) * TRIG_SIGNED_INVERSE_FACTORIAL[n];
}

static inline double trig_sin_moved(double x0, const double a[TRIG_TERMS], double d, double *rest)
{
    if (!(fabs(d) <= 0.7853981633974483)) {
        *rest = 0.0;
        return trig_sin(x0 + d);
    }
    const double d2 = d * d, d4 = d2 * d2, d10 = (d4 * d4) * d2;
    const double low = ((a[2] + a[3] * d) + d2 * (a[4] + a[5] * d))
                       + d4 * ((a[6] + a[7] * d) + d2 * (a[8] + a[9] * d));
    const double high = ((a[10] + a[11] * d) + d2 * (a[12] + a[13] * d))
                        + d4 * ((a[14] + a[15] * d) + d2 * (a[16] + a[17] * d));
    *rest = d2 * low + d10 * high;
    return a[0] + a[1] * d;
}

#endif
