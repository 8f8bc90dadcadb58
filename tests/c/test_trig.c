/* test_trig.c: the inline sine and cosine of trig.h against libm (glibc: errors below
 * 1 ulp), over every quadrant and scale: random arguments in |x| <= a for a from 1e-8 to
 * 2^19, both sides of each quadrant's edge (x near odd multiples of pi/4), near the zeros
 * (multiples of pi/2), at the switch-overs to libm (2^19) and to sin x = x (2^-27), and
 * the special values (+-0 with its sign, subnormals, infinities, NaN). Each result within
 * 1 ulp of libm's; prints the largest distance in ulps at each scale and one summary line.
 * trig_sin_moved (sin(x0 + d), the Taylor polynomial in d about x0, its two parts summed)
 * against libm's sin of the sum, where the sum is exact: within 3 ulps of |sin x0| + |d|
 * (half an ulp each: the two inputs, the leading product, the two last sums, the reference),
 * for moves up to pi/4 and beyond (where it takes trig_sin of the sum). trig_sincos_small
 * (no reduction) within 1 ulp of libm on |r| <= 0.8. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "trig.h"

/* distance in units in the last place between two finite doubles (0 for equal zeros) */
static double ulps_apart(double a, double b)
{
    if (a == b)
        return 0.0;
    int64_t ia, ib;
    memcpy(&ia, &a, sizeof ia);
    memcpy(&ib, &b, sizeof ib);
    if (ia < 0)
        ia = INT64_MIN - ia;   /* the doubles in one monotone integer order */
    if (ib < 0)
        ib = INT64_MIN - ib;
    if ((ia < 0) != (ib < 0))
        return INFINITY;   /* opposite signs (no result here is that close to zero) */
    return (double)(ia > ib ? ia - ib : ib - ia);   /* the difference is exact; converted, it is small */
}

static uint64_t rng_state = 0x9e3779b97f4a7c15u;

static double uniform(double a)   /* in [-a, a) */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return a * (2.0 * (double)(rng_state >> 11) * 0x1p-53 - 1.0);
}

/* one argument: sin and cos within 1 ulp of libm; returns the larger distance */
static double compare(double x)
{
    double s, c;
    trig_sincos(x, &s, &c);
    const double ds = ulps_apart(s, sin(x)), dc = ulps_apart(c, cos(x));
    check(ds <= 1.0 && dc <= 1.0, "x = %a: sin %a (libm %a, %.0f ulp), cos %a (libm %a, %.0f ulp)", x, s, sin(x),
          ds, c, cos(x), dc);
    check(trig_sin(x) == s, "x = %a: trig_sin differs from trig_sincos", x);
    return fmax(ds, dc);
}

int main(void)
{
    const double scales[] = {1e-8, 1e-3, 0.5, 0.78, 1.6, 3.2, 7.0, 100.0, 1e4, 5e5};
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        double worst = 0.0;
        for (int n = 0; n < 200000; n++)
            worst = fmax(worst, compare(uniform(scales[i])));
        printf("|x| <= %-6g: largest distance from libm %.0f ulp\n", scales[i], worst);
    }
    /* both sides of every quadrant edge (k pi/4, k odd) and every zero (k pi/2) up to 2^19 */
    double worst = 0.0;
    for (double k = 1.0; k * 0.7853981633974483 < 524288.0; k = k < 64.0 ? k + 1.0 : floor(k * 1.37)) {
        const double edge = k * 0.7853981633974483;
        double x = edge;
        for (int j = 0; j < 4; j++, x = nextafter(x, 0.0))
            worst = fmax(worst, fmax(compare(x), compare(-x)));
        x = nextafter(edge, INFINITY);
        for (int j = 0; j < 3; j++, x = nextafter(x, INFINITY))
            worst = fmax(worst, fmax(compare(x), compare(-x)));
    }
    printf("quadrant edges and zeros: largest distance from libm %.0f ulp\n", worst);
    /* the switch-overs: libm from 2^19 on, sin x = x below 2^-27 */
    const double limits[] = {TRIG_REDUCE_LIMIT, TRIG_TINY};
    for (int i = 0; i < 2; i++) {
        double x = limits[i];
        for (int j = 0; j < 3; j++)
            x = nextafter(x, 0.0);
        for (int j = 0; j < 7; j++, x = nextafter(x, INFINITY)) {
            compare(x);
            compare(-x);
        }
    }
    /* trig_sin_moved: random starts and moves of every size up to 2 (beyond pi/4: the
     * fallback), on a grid of 2^-48 with |x0| < 16, so that x0 + d is exact and libm's sin of
     * it is the reference (within half an ulp) */
    double worst_moved = 0.0;
    for (int n = 0; n < 400000; n++) {
        const double x0 = round(uniform(10.0) * 0x1p20) * 0x1p-20;
        const double size = n % 4 == 0 ? 2.0 : n % 4 == 1 ? 0.7853981633974483 : n % 4 == 2 ? 1e-3 : 1e-9;
        const double d = round(uniform(size) * 0x1p48) * 0x1p-48;
        double taylor_sin[TRIG_TERMS];
        trig_moved_coefficients(sin(x0), cos(x0), taylor_sin);
        double rest;
        const double moved = trig_sin_moved(x0, taylor_sin, d, &rest) + rest, exact = sin(x0 + d);
        const double scale = (fabs(sin(x0)) + fabs(d)) * DBL_EPSILON, off = fabs(moved - exact);
        worst_moved = fmax(worst_moved, off / scale);
        check(off <= 3.0 * scale, "trig_sin_moved(%a, %a): %a, sin of the sum %a (%.2f ulps of |sin x0| + |d|)", x0, d,
              moved, exact, off / scale);
    }
    printf("trig_sin_moved: largest error %.2f ulps of |sin x0| + |d|\n", worst_moved);
    /* trig_sincos_small (the Landen chain's bottom level) on |r| <= 0.8, beyond pi/4 too:
     * random arguments and a grid of 0.001, each within 1 ulp of libm */
    double worst_small = 0.0;
    for (int n = 0; n < 200000 + 1601; n++) {
        const double r = n < 200000 ? uniform(0.8) : 0.001 * (n - 200000 - 800);
        double sin_r, cos_r;
        trig_sincos_small(r, &sin_r, &cos_r);
        const double off = fmax(ulps_apart(sin_r, sin(r)), ulps_apart(cos_r, cos(r)));
        worst_small = fmax(worst_small, off);
        check(off <= 1.0, "trig_sincos_small(%a): %a %a, libm %a %a", r, sin_r, cos_r, sin(r), cos(r));
    }
    printf("trig_sincos_small, |r| <= 0.8: largest distance from libm %.0f ulp\n", worst_small);
    /* special values */
    double s, c;
    trig_sincos(-0.0, &s, &c);
    check(s == 0.0 && signbit(s) && c == 1.0, "sincos(-0): %a %a", s, c);
    trig_sincos(0.0, &s, &c);
    check(s == 0.0 && !signbit(s) && c == 1.0, "sincos(+0): %a %a", s, c);
    compare(DBL_TRUE_MIN);
    compare(-DBL_MIN);
    compare(DBL_MAX);
    const double not_finite[] = {INFINITY, -INFINITY, NAN};
    for (int i = 0; i < 3; i++) {
        trig_sincos(not_finite[i], &s, &c);
        check(isnan(s) && isnan(c), "sincos(%g): %g %g, not NaN", not_finite[i], s, c);
    }
    return check_summary("test_trig");
}
