/* dd_avx.h: double-double operations on four lanes at once, GCC's vector of four doubles
 * (AVX), for the fma build's lock-step set-ups (exact_fma.c: GCC on x86-64, AVX and FMA
 * enabled by its target pragma): elliptic_avx.h and dd.c's dd_cos_sin_begin_many and _end_many.
 *
 * Every operation is the scalar one of dd.h lane by lane (+, -, *, / and the square root
 * elementwise, each IEEE-rounded as the scalar operation; the two-product by the fma, as dd.h's
 * in the fma build), so a lane's bits are the scalar code's when it runs the same operations in
 * the same order. Where scalar code branches, a lane computes both sides and keeps its own
 * (v4_pick). */
#ifndef PENDULUM_DD_AVX_H
#define PENDULUM_DD_AVX_H

#include "dd.h"

#include <immintrin.h>
#include <string.h>

typedef double V4 __attribute__((vector_size(32)));
typedef long long V4Mask __attribute__((vector_size(32)));

/* lanes to a vector */
#define AVX_LANES 4

static inline V4 v4_all(double x)
{
    const V4 v = {x, x, x, x};
    return v;
}

/* where[l] ? yes[l] : no[l] */
static inline V4 v4_pick(V4Mask where, V4 yes, V4 no)
{
    return (V4)_mm256_blendv_pd((__m256d)no, (__m256d)yes, (__m256d)where);
}

/* 1 in bit l for every lane l of the mask */
static inline int v4_bits(V4Mask mask)
{
    return _mm256_movemask_pd((__m256d)mask);
}

typedef struct {
    V4 hi, lo;
} V4Dd;

static inline V4Dd v4_two_prod(V4 a, V4 b)
{
    V4Dd r;
    r.hi = a * b;
    r.lo = (V4)_mm256_fmadd_pd((__m256d)a, (__m256d)b, (__m256d)(-r.hi));
    return r;
}

static inline V4Dd v4_two_sum(V4 a, V4 b)
{
    V4Dd r;
    r.hi = a + b;
    const V4 b_virtual = r.hi - a;
    r.lo = (a - (r.hi - b_virtual)) + (b - b_virtual);
    return r;
}

static inline V4Dd v4_fast_two_sum(V4 a, V4 b)
{
    V4Dd r;
    r.hi = a + b;
    r.lo = b - (r.hi - a);
    return r;
}

static inline V4Dd v4_dd_mul(V4Dd x, V4Dd y)
{
    V4Dd p = v4_two_prod(x.hi, y.hi);
    p.lo += x.hi * y.lo + x.lo * y.hi;
    return v4_fast_two_sum(p.hi, p.lo);
}

static inline V4Dd v4_dd_div(V4Dd x, V4Dd y)
{
    const V4 q1 = x.hi / y.hi;
    const V4Dd p = v4_two_prod(q1, y.hi);
    const V4 remainder = (((x.hi - p.hi) - p.lo) + x.lo) - q1 * y.lo;
    return v4_fast_two_sum(q1, remainder / y.hi);
}

static inline V4 v4_load(const double *x)
{
    V4 v;
    memcpy(&v, x, sizeof v);
    return v;
}

static inline void v4_store(double *x, V4 v)
{
    memcpy(x, &v, sizeof v);
}

static inline V4Dd v4_pick_dd(V4Mask where, V4Dd yes, V4Dd no)
{
    V4Dd r;
    r.hi = v4_pick(where, yes.hi, no.hi);
    r.lo = v4_pick(where, yes.lo, no.lo);
    return r;
}

/* dd_add_smaller of dd.c */
static inline V4Dd v4_add_smaller(V4Dd x, V4Dd y)
{
    V4Dd s = v4_fast_two_sum(x.hi, y.hi);
    s.lo += x.lo + y.lo;
    return v4_fast_two_sum(s.hi, s.lo);
}

static inline V4Dd v4_dd_neg(V4Dd x)
{
    x.hi = -x.hi;
    x.lo = -x.lo;
    return x;
}

static inline V4 v4_abs(V4 x)
{
    return (V4)_mm256_andnot_pd(_mm256_set1_pd(-0.0), (__m256d)x);
}

/* What dd.c's cos_sin_begin_v4 knows of four arguments x (dd_cos_sin_begin's DdCosSin,
 * lane by lane): y = x - n pi/2, n in {-1, 0, 1}, the double sin x, the table point
 * (sign, r, C, S) and the leading double of cos x with its certificate. */
typedef struct {
    V4Dd y;
    V4 n;
    V4 sin_x;
    V4 sign;
    V4Dd r, C, S;
    V4 cos_lead;
    V4Mask certain;
} CosSinV4;

#endif
