/* once_avx.h: new states set up and evaluated once, a vector of them at a time, for
 * pendulum_exact_once_gl_many: four lanes in the fma build (exact_fma.c: GCC or clang on x86-64
 * Linux, AVX and FMA enabled by its target pragma), eight in the AVX-512 build (avx512_copy.c,
 * the same sources with AVX-512F enabled, for processors that have it). Included at the end of exact.c
 * in those builds alone: each compiles dd.c, elliptic.c and exact.c as one translation unit,
 * and this code reads their tables and constants (dd.c's TABLE_64 and series, elliptic.c's
 * BOTTOM_M and pi's parts).
 *
 * Each lane runs the scalar code's operations in their order, on the compiler's vector of doubles:
 * +, -, *, / elementwise, each IEEE-rounded as the scalar operation, the correctly rounded
 * vector square root, and the two-products by the fma as the fma build's scalar ones. So a lane
 * has the scalar bits: dd_cos_sin_begin and _end (the cosine of theta0/2 and the double sine),
 * elliptic_param_begin and _finish (the Landen chain, K and 1/K), the fields of
 * init_from_rest (once_avx) or, for a moving libration or rotation, of exact_init_dd's
 * general path (once_moving_block: the scaled rates, q, m1 or dd_sin, mu1, mu, dd_sqrt,
 * elliptic_RF, the initial phase; glibc's hypot called lane by lane), and eval_any's
 * libration (phase_near, the Landen pair, libration_angle_omega, add_half_turns: the
 * roundings of pendulum_exact_eval, whose inline common case reaches them in fewer steps)
 * with its whole turns, or its rotation (elliptic_atan_ratio, dn, the winding). Where the scalar
 * code branches on a value, each lane computes what it needs of both sides and keeps its own
 * (vec_pick, a blend); the table's rows are read lane by lane; a lane whose Landen chain has
 * ended is carried along with its values frozen. test_exact_batch compares every output with
 * the scalar set-up and evaluation. */
#ifndef PENDULUM_ONCE_AVX_H
#define PENDULUM_ONCE_AVX_H

#include <float.h>
#include <immintrin.h>

/* a stage inlined where it is used: left to GCC, the stages both kinds of block share and the
 * block of releases from rest went out of line, and a release from rest took 10-20 % longer
 * (bench_exact's once kind) */
#define ONCE_STAGE static inline __attribute__((always_inline))

/* --- a vector of ONCE_LANES doubles; what each instruction set does in its own words ------ */

/* four lanes (AVX: exact_fma.c) or eight (AVX-512F: avx512_copy.c); the same operations lane
 * by lane either way */
#ifndef PENDULUM_ONCE_LANES
#define PENDULUM_ONCE_LANES 4
#endif
#define ONCE_LANES PENDULUM_ONCE_LANES
#if ONCE_LANES != 4 && ONCE_LANES != 8
#error "once_avx.h: a vector of four or eight doubles"
#endif

typedef double Vec __attribute__((vector_size(8 * ONCE_LANES)));
typedef long long VecMask __attribute__((vector_size(8 * ONCE_LANES)));

/* the mask of every lane, and its bits (vec_bits) */
#define VEC_EVERY ((VecMask){0} - 1)
#define VEC_ALL_BITS ((1 << ONCE_LANES) - 1)

static inline Vec vec_all(double x)
{
#if ONCE_LANES == 8
    const Vec v = {x, x, x, x, x, x, x, x};
#else
    const Vec v = {x, x, x, x};
#endif
    return v;
}

/* The vector type of the intrinsics, and their names for this width */
#if ONCE_LANES == 8
typedef __m512d VecNative;
#define VEC_PD(op) _mm512_##op##_pd
#define VEC_ROUND(x, mode) _mm512_roundscale_pd(x, mode)
#else
typedef __m256d VecNative;
#define VEC_PD(op) _mm256_##op##_pd
#define VEC_ROUND(x, mode) _mm256_round_pd(x, mode)
#endif

#if ONCE_LANES == 8
/* the mask register of a lane mask */
static inline __mmask8 vec_k(VecMask mask)
{
    return _mm512_test_epi64_mask((__m512i)mask, (__m512i)mask);
}

/* where[l] ? yes[l] : no[l] */
static inline Vec vec_pick(VecMask where, Vec yes, Vec no)
{
    return (Vec)_mm512_mask_blend_pd(vec_k(where), (__m512d)no, (__m512d)yes);
}

/* 1 in bit l for every lane l of the mask */
static inline int vec_bits(VecMask mask)
{
    return (int)vec_k(mask);
}

static inline Vec vec_abs(Vec x)
{
    return (Vec)_mm512_abs_pd((__m512d)x);
}

/* the magnitude of x with the sign of y */
static inline Vec vec_copysign(Vec x, Vec y)
{
    const VecMask sign_bit = (VecMask)vec_all(-0.0);
    return (Vec)(((VecMask)x & ~sign_bit) | ((VecMask)y & sign_bit));
}
#else
/* where[l] ? yes[l] : no[l] */
static inline Vec vec_pick(VecMask where, Vec yes, Vec no)
{
    return (Vec)_mm256_blendv_pd((__m256d)no, (__m256d)yes, (__m256d)where);
}

/* 1 in bit l for every lane l of the mask */
static inline int vec_bits(VecMask mask)
{
    return _mm256_movemask_pd((__m256d)mask);
}

static inline Vec vec_abs(Vec x)
{
    return (Vec)_mm256_andnot_pd(_mm256_set1_pd(-0.0), (__m256d)x);
}

/* the magnitude of x with the sign of y */
static inline Vec vec_copysign(Vec x, Vec y)
{
    const __m256d sign_bit = _mm256_set1_pd(-0.0);
    return (Vec)_mm256_or_pd(_mm256_andnot_pd(sign_bit, (__m256d)x), _mm256_and_pd(sign_bit, (__m256d)y));
}
#endif

/* a b + c, rounded once */
static inline Vec vec_fmadd(Vec a, Vec b, Vec c)
{
    return (Vec)VEC_PD(fmadd)((VecNative)a, (VecNative)b, (VecNative)c);
}

/* the larger of a and b, neither NaN (fmax) */
static inline Vec vec_max(Vec a, Vec b)
{
    return (Vec)VEC_PD(max)((VecNative)a, (VecNative)b);
}

static inline Vec vec_sqrt(Vec x)
{
    return (Vec)VEC_PD(sqrt)((VecNative)x);
}

/* x rounded toward zero to a whole number */
static inline Vec vec_trunc(Vec x)
{
    return (Vec)VEC_ROUND((VecNative)x, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
}

/* x rounded to the nearest whole number, ties to even (nearbyint in the default mode) */
static inline Vec vec_nearest(Vec x)
{
    return (Vec)VEC_ROUND((VecNative)x, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}

/* --- double-double operations lane by lane ------------------------------------------------ */

typedef struct {
    Vec hi, lo;
} VecDd;

static inline VecDd vec_two_prod(Vec a, Vec b)
{
    VecDd r;
    r.hi = a * b;
    r.lo = vec_fmadd(a, b, -r.hi);
    return r;
}

static inline VecDd vec_two_sum(Vec a, Vec b)
{
    VecDd r;
    r.hi = a + b;
    const Vec b_virtual = r.hi - a;
    r.lo = (a - (r.hi - b_virtual)) + (b - b_virtual);
    return r;
}

static inline VecDd vec_fast_two_sum(Vec a, Vec b)
{
    VecDd r;
    r.hi = a + b;
    r.lo = b - (r.hi - a);
    return r;
}

/* dd_add of dd.h: the sums of the high and of the low parts, each error-free, two
 * renormalisations */
static inline VecDd vec_dd_add(VecDd x, VecDd y)
{
    VecDd s = vec_two_sum(x.hi, y.hi);
    const VecDd t = vec_two_sum(x.lo, y.lo);
    s.lo += t.hi;
    s = vec_fast_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return vec_fast_two_sum(s.hi, s.lo);
}

static inline VecDd vec_dd_mul(VecDd x, VecDd y)
{
    VecDd p = vec_two_prod(x.hi, y.hi);
    p.lo += x.hi * y.lo + x.lo * y.hi;
    return vec_fast_two_sum(p.hi, p.lo);
}

static inline VecDd vec_dd_div(VecDd x, VecDd y)
{
    const Vec q1 = x.hi / y.hi;
    const VecDd p = vec_two_prod(q1, y.hi);
    const Vec remainder = (((x.hi - p.hi) - p.lo) + x.lo) - q1 * y.lo;
    return vec_fast_two_sum(q1, remainder / y.hi);
}

static inline VecDd vec_pick_dd(VecMask where, VecDd yes, VecDd no)
{
    VecDd r;
    r.hi = vec_pick(where, yes.hi, no.hi);
    r.lo = vec_pick(where, yes.lo, no.lo);
    return r;
}

/* dd_add_smaller of dd.c */
static inline VecDd vec_add_smaller(VecDd x, VecDd y)
{
    VecDd s = vec_fast_two_sum(x.hi, y.hi);
    s.lo += x.lo + y.lo;
    return vec_fast_two_sum(s.hi, s.lo);
}

static inline VecDd vec_dd_neg(VecDd x)
{
    x.hi = -x.hi;
    x.lo = -x.lo;
    return x;
}

/* dd_sqrt of dd.h for x.hi in [2^-900, inf): s = sqrt(x.hi), sqrt(x) = s + (x - s^2) / (2 s) */
static inline VecDd vec_dd_sqrt(VecDd x)
{
    const Vec s = vec_sqrt(x.hi);
    const VecDd sq = vec_two_prod(s, s);
    return vec_fast_two_sum(s, (((x.hi - sq.hi) - sq.lo) + x.lo) / (2.0 * s));
}

/* --- dd_cos_sin_begin and _end lane by lane (dd.c) -------------------------------------- */

/* table_point's DdTablePoint lane by lane: y = sign (a + r), a the table point, C, S = cos a, sin a */
typedef struct {
    Vec sign;
    VecDd r, C, S;
} TablePointVec;

/* What cos_sin_begin_vec knows of a vector of arguments x (dd_cos_sin_begin's DdCosSin, lane by
 * lane): y = x - n pi/2, n in {-1, 0, 1}, the double sin x, the table point and the leading
 * double of cos x with its certificate. */
typedef struct {
    VecDd y;
    Vec n;
    Vec sin_x;
    TablePointVec point;
    Vec cos_lead;
    VecMask certain;
} CosSinVec;

/* horner_double lane by lane */
static inline Vec vec_horner_double(const DoubleDouble *coef, Vec z)
{
    Vec tail = vec_all(coef[13].hi);
    for (int j = 12; j >= 0; --j) {
        tail = coef[j].hi + z * tail;
    }
    return tail;
}

/* sin_versine_small lane by lane */
static inline void vec_sin_versine_small(VecDd r, VecDd *w, VecDd *v)
{
    VecDd r2 = vec_two_prod(r.hi, r.hi);
    r2.lo += 2.0 * r.hi * r.lo;
    const Vec z = r2.hi;
    const Vec p_rest = SMALL_P_REST(z);
    const Vec q_rest = SMALL_Q_REST(z);
    const VecDd p2 = vec_dd_mul(r2, (VecDd){vec_all(INV_5F_HI), vec_all(INV_5F_LO)});
    const VecDd q2 = vec_dd_mul(r2, (VecDd){vec_all(-INV_6F_HI), vec_all(-INV_6F_LO)});
    VecDd P = vec_fast_two_sum(vec_all(-INV_3F_HI), p2.hi), Q = vec_fast_two_sum(vec_all(INV_4F_HI), q2.hi);
    P.lo += (-INV_3F_LO + p2.lo) + p_rest;
    Q.lo += (INV_4F_LO + q2.lo) + q_rest;
    *w = vec_add_smaller(r, vec_dd_mul(vec_dd_mul(r, r2), P));
    *v = vec_add_smaller((VecDd){0.5 * r2.hi, 0.5 * r2.lo}, vec_dd_neg(vec_dd_mul(vec_dd_mul(r2, r2), Q)));
}

/* reduce_quadrant's first branch on a vector of arguments x, |x.hi| < 2: n in {-1, 0, 1},
 * y = x - n pi/2 (y = x for n = 0) */
ONCE_STAGE VecDd reduce_quadrant_vec(VecDd x, Vec *quadrants)
{
    const Vec n = vec_pick((VecMask)(x.hi > 0.5 * HALF_PI_HI), vec_all(1.0), vec_all(0.0))
                 - vec_pick((VecMask)(x.hi < -0.5 * HALF_PI_HI), vec_all(1.0), vec_all(0.0));
    const Vec head = x.hi - n * HALF_PI_HI;
    const VecDd rest = vec_two_sum(x.lo, -n * HALF_PI_LO);
    VecDd y = vec_two_sum(head, rest.hi);
    y.lo += rest.lo - n * HALF_PI_LOLO;
    y = vec_fast_two_sum(y.hi, y.lo);
    *quadrants = n;
    return vec_pick_dd((VecMask)(n == 0.0), x, y);
}

/* The table's rows {cos hi, cos lo, sin hi, sin lo} at index[first .. first + 3], each loaded
 * whole, as four columns of four lanes each (transposed) */
typedef struct {
    __m256d cos_hi, cos_lo, sin_hi, sin_lo;
} TableRows4;

static inline TableRows4 table_rows4(Vec index, int first)
{
    const __m256d r0 = _mm256_loadu_pd(TABLE_64[(int)index[first]]);
    const __m256d r1 = _mm256_loadu_pd(TABLE_64[(int)index[first + 1]]);
    const __m256d r2 = _mm256_loadu_pd(TABLE_64[(int)index[first + 2]]);
    const __m256d r3 = _mm256_loadu_pd(TABLE_64[(int)index[first + 3]]);
    const __m256d even01 = _mm256_unpacklo_pd(r0, r1), odd01 = _mm256_unpackhi_pd(r0, r1);
    const __m256d even23 = _mm256_unpacklo_pd(r2, r3), odd23 = _mm256_unpackhi_pd(r2, r3);
    TableRows4 rows;
    rows.cos_hi = _mm256_permute2f128_pd(even01, even23, 0x20);
    rows.cos_lo = _mm256_permute2f128_pd(odd01, odd23, 0x20);
    rows.sin_hi = _mm256_permute2f128_pd(even01, even23, 0x31);
    rows.sin_lo = _mm256_permute2f128_pd(odd01, odd23, 0x31);
    return rows;
}

#if ONCE_LANES == 8
/* lanes 0-3 from low, 4-7 from high */
static inline Vec vec_join(__m256d low, __m256d high)
{
    return (Vec)_mm512_insertf64x4(_mm512_castpd256_pd512(low), high, 1);
}
#endif

/* table_point of a vector of y, |y| <= pi/4 + small: i = nearest(64 |y|), ties up, its row read
 * lane by lane, r = |y| - i/64 */
ONCE_STAGE TablePointVec table_point_vec(VecDd y)
{
    TablePointVec t;
    t.sign = vec_pick((VecMask)(y.hi < 0.0), vec_all(-1.0), vec_all(1.0));
    const VecDd u = {t.sign * y.hi, t.sign * y.lo};
    const Vec scaled = u.hi * 64.0;
    const Vec whole = vec_trunc(scaled);
    const Vec index = whole + vec_pick((VecMask)(scaled - whole >= 0.5), vec_all(1.0), vec_all(0.0));
#if ONCE_LANES == 8
    const TableRows4 low = table_rows4(index, 0), high = table_rows4(index, 4);
    t.C.hi = vec_join(low.cos_hi, high.cos_hi);
    t.C.lo = vec_join(low.cos_lo, high.cos_lo);
    t.S.hi = vec_join(low.sin_hi, high.sin_hi);
    t.S.lo = vec_join(low.sin_lo, high.sin_lo);
#else
    const TableRows4 rows = table_rows4(index, 0);
    t.C.hi = (Vec)rows.cos_hi;
    t.C.lo = (Vec)rows.cos_lo;
    t.S.hi = (Vec)rows.sin_hi;
    t.S.lo = (Vec)rows.sin_lo;
#endif
    t.r = vec_two_sum(u.hi - index * 0.015625, u.lo);
    return t;
}

/* sincos_at lane by lane: cos y where `cosine` is set, sin y elsewhere, by the addition
 * theorems cos(a + r) = C - (S w + C v), sin(a + r) = S + (C w - S v) */
ONCE_STAGE VecDd table_sincos_vec(const TablePointVec *t, VecMask cosine)
{
    VecDd w, v;
    vec_sin_versine_small(t->r, &w, &v);
    const VecDd C = t->C, S = t->S;
    VecDd cos_y = {vec_all(0.0), vec_all(0.0)}, sin_y = cos_y;
    if (vec_bits(cosine) != 0) {   /* the sums a lane needs; both where the lanes differ */
        cos_y = vec_add_smaller(C, vec_dd_neg(vec_add_smaller(vec_dd_mul(S, w), vec_dd_mul(C, v))));
    }
    if (vec_bits(cosine) != VEC_ALL_BITS) {
        const VecDd sin_abs = vec_add_smaller(S, vec_add_smaller(vec_dd_mul(C, w), vec_dd_neg(vec_dd_mul(S, v))));
        sin_y.hi = t->sign * sin_abs.hi;
        sin_y.lo = t->sign * sin_abs.lo;
    }
    return vec_pick_dd(cosine, cos_y, sin_y);
}

/* subtract_turns(x, j): x - j (2 pi), 2 pi in three parts, the two leading products exact */
static inline VecDd vec_subtract_turns(VecDd x, Vec j)
{
    x = vec_dd_add(x, vec_dd_neg(vec_two_prod(j, vec_all(2.0 * PI_HI))));
    x = vec_dd_add(x, vec_dd_neg(vec_two_prod(j, vec_all(2.0 * PI_LO))));
    return vec_dd_add(x, (VecDd){-j * 2.0 * PI_LOLO, vec_all(0.0)});
}

/* reduce_initial_angle's turns for |theta0| < 2^50: where |theta0| > 3.2, th = theta0 - 2 pi j
 * with j = nearbyint(theta0 / (2 pi)) (*turns), else th = theta0; *reduced marks the lanes
 * whose th is within 3.2 after that one subtraction (the scalar code's rounds stop there too;
 * the others, and |theta0| >= 2^50, are left to it) */
ONCE_STAGE VecDd reduce_turns_vec(Vec theta0, Vec *turns, VecMask *reduced)
{
    const VecDd whole = {theta0, vec_all(0.0)};
    const VecMask wound = (VecMask)(vec_abs(theta0) > 3.2);
    if (vec_bits(wound) == 0) {
        *turns = vec_all(0.0);
        *reduced = VEC_EVERY;
        return whole;
    }
    const Vec j = vec_pick(wound, vec_nearest(theta0 / (2.0 * PI_HI)), vec_all(0.0));
    const VecDd th = vec_pick_dd(wound, vec_subtract_turns(whole, j), whole);
    *turns = j;
    *reduced = (VecMask)(vec_abs(th.hi) <= 3.2) & (VecMask)(vec_abs(theta0) < 0x1p50);
    return th;
}

/* dd_cos_sin_begin on a vector of arguments x, |x.hi| < 2 (reduce_quadrant's first branch), into
 * a CosSinVec */
ONCE_STAGE void cos_sin_begin_vec(VecDd x, CosSinVec *out)
{
    Vec n;
    const VecDd y = reduce_quadrant_vec(x, &n);
    /* quadrant_of(n): 0, 1, or 3 for n = -1; odd for n != 0; flip = -1 for quadrant 1 */
    const VecMask odd = (VecMask)(n != 0.0), flip_minus = (VecMask)(n > 0.0);
    /* the double sin x: the series in double of sincos_reduced */
    const Vec z = vec_dd_mul(y, y).hi;
    Vec other;
    if (vec_bits(odd) == 0) {   /* the series a lane needs; both where the lanes differ */
        other = y.hi + y.hi * z * vec_horner_double(SIN_COEF, z);
    } else if (vec_bits(odd) == VEC_ALL_BITS) {
        other = 1.0 + z * vec_horner_double(COS_COEF, z);
    } else {
        other = vec_pick(odd, 1.0 + z * vec_horner_double(COS_COEF, z),
                         y.hi + y.hi * z * vec_horner_double(SIN_COEF, z));
    }
    const Vec sin_x = vec_pick((VecMask)(n < 0.0), -other, other);
    const TablePointVec point = table_point_vec(y);
    const Vec sign = point.sign;
    const VecDd r = point.r, C = point.C, S = point.S;
    /* table_leading */
    const VecDd R2 = vec_two_prod(r.hi, r.hi);
    const Vec zr = R2.hi;
    const Vec w_rest = TABLE_SIN_REST(r.hi, r.lo, zr);
    const Vec v_rest = TABLE_VERSINE_REST(r.hi, r.lo, R2.lo, zr);
    const VecDd first = vec_two_prod(vec_pick(odd, C.hi, -S.hi), r.hi);
    const Vec base = vec_pick(odd, S.hi, C.hi), other_hi = vec_pick(odd, C.hi, -S.hi);
    const Vec base_lo = vec_pick(odd, S.lo, C.lo), other_lo = vec_pick(odd, C.lo, -S.lo);
    const VecDd second = vec_two_prod(-base, 0.5 * zr);
    const VecDd A = vec_two_sum(base, first.hi), B = vec_two_sum(A.hi, second.hi);
    const Vec rest_sum = ((A.lo + B.lo) + (first.lo + second.lo))
                        + ((base_lo - base_lo * (0.5 * zr) - base * v_rest) + (other_hi * w_rest + other_lo * r.hi));
    const VecDd sum = vec_two_sum(B.hi, rest_sum);
    const Vec bound = 0x1p-66 * vec_abs(sum.hi);
    const Vec flip = vec_pick(flip_minus, vec_all(-1.0), vec_all(1.0));
    out->y = y;
    out->n = n;
    out->sin_x = sin_x;
    out->point = point;
    out->cos_lead = flip * vec_pick(odd, sign * sum.hi, sum.hi);
    out->certain = (VecMask)(sum.hi + (sum.lo + bound) == sum.hi) & (VecMask)(sum.hi + (sum.lo - bound) == sum.hi);
}

/* dd_cos_sin_end of cos_sin_begin_vec's lanes: cos x in double-double */
ONCE_STAGE VecDd cos_sin_end_vec(const CosSinVec *in)
{
    const VecMask odd = (VecMask)(in->n != 0.0);
    const Vec flip = vec_pick((VecMask)(in->n > 0.0), vec_all(-1.0), vec_all(1.0));
    /* sincos_at: cos for even quadrants, sin for odd */
    const VecDd value = table_sincos_vec(&in->point, ~odd);
    /* the certain leading double, or the value itself */
    const Vec lead = in->cos_lead;
    const VecDd known = {lead, flip * ((value.hi - flip * lead) + value.lo)};
    return vec_pick_dd(in->certain, known, (VecDd){flip * value.hi, flip * value.lo});
}

/* dd_sin's value from the table point of y = x - n pi/2: sin y, cos y (n = 1) or -cos y
 * (n = -1) */
ONCE_STAGE VecDd sin_at_point_vec(const TablePointVec *point, Vec n)
{
    const VecDd value = table_sincos_vec(point, (VecMask)(n != 0.0));
    return vec_pick_dd((VecMask)(n < 0.0), vec_dd_neg(value), value);
}

/* dd_sin of a vector of x, |x.hi| < 2 */
ONCE_STAGE VecDd dd_sin_vec(VecDd x)
{
    Vec n;
    const TablePointVec point = table_point_vec(reduce_quadrant_vec(x, &n));
    return sin_at_point_vec(&point, n);
}

/* --- elliptic_param_begin and _finish lane by lane (elliptic.c) ------------------------- */

/* The Landen chains of the lanes, as the evaluation reads them: each level's factors (a
 * lane's own up to its N, frozen values past it), N and m_N. */
typedef struct {
    Vec landen_k[ELLIPTIC_MAX_LEVELS], landen_1pk[ELLIPTIC_MAX_LEVELS], landen_1mk[ELLIPTIC_MAX_LEVELS];
    Vec levels;    /* N as doubles */
    int most;     /* the largest N */
    Vec bottom_m;  /* m_N */
} ChainsVec;

/* elliptic_param_finish's running values lane by lane: the tail, the mean and its error */
typedef struct {
    Vec tail;
    VecDd mean;
    Vec mean_error;
} TailsVec;

static inline TailsVec tails_start_vec(Vec kc_lo)
{
    const TailsVec t = {kc_lo, {vec_all(1.0), vec_all(0.0)}, vec_all(0.0)};
    return t;
}

/* elliptic_param_finish's level n, with mean_times(&mean, &mean_error, one_plus / 2,
 * tail_h / 2), on the lanes whose chain has that level (active); the others keep their values */
static inline void tails_level_vec(TailsVec *t, VecMask active, Vec kc_n, Vec root_n, Vec one_plus_n, Vec kc_next)
{
    const Vec tail = t->tail;
    const VecDd mean = t->mean;
    const Vec e_h = kc_n - (one_plus_n - 1.0);
    const VecDd root_sq = vec_two_prod(root_n, root_n);
    const Vec e_s = (kc_n - root_sq.hi) - root_sq.lo;
    const VecDd product = vec_two_prod(kc_next, one_plus_n);
    const Vec e_q = (2.0 * root_n - product.hi) - product.lo;
    const Vec tail_h = e_h + tail;
    const Vec f_hi = 0.5 * one_plus_n, f_lo = 0.5 * tail_h;
    const VecDd pr = vec_two_prod(mean.hi, f_hi), a = vec_two_prod(mean.hi, f_lo);
    const VecDd b = vec_two_prod(mean.lo, f_hi);
    const VecDd s1 = vec_two_sum(pr.lo, a.hi), s2 = vec_two_sum(s1.hi, b.hi);
    const Vec error = t->mean_error * f_hi + (((s1.lo + s2.lo) + (a.lo + b.lo)) + mean.lo * f_lo);
    const VecDd next_mean = vec_fast_two_sum(pr.hi, s2.hi);
    const Vec next_tail = ((root_n * e_q + (e_s + tail)) - root_n * kc_next * tail_h) / (root_n * one_plus_n);
    if (vec_bits(active) == VEC_ALL_BITS) {   /* every lane: no blends */
        t->mean_error = error;
        t->mean = next_mean;
        t->tail = next_tail;
        return;
    }
    t->mean_error = vec_pick(active, error, t->mean_error);
    t->mean.hi = vec_pick(active, next_mean.hi, mean.hi);
    t->mean.lo = vec_pick(active, next_mean.lo, mean.lo);
    t->tail = vec_pick(active, next_tail, tail);
}

/* landen_K from the tails at the bottom (k'_N = kc_bottom), and elliptic_param_finish's
 * bottom scale */
static inline void tails_finish_vec(const TailsVec *t, Vec kc_bottom, Vec bottom_m, VecDd *K_out, VecDd *inv_K,
                                   Vec *bottom_scale)
{
    const VecDd mean = t->mean;
    const Vec mean_error = t->mean_error;
    VecDd A = vec_dd_div(vec_fast_two_sum(vec_all(HALF_PI_HI), vec_all(HALF_PI_LO)), mean);
    VecDd B = vec_dd_mul(mean, vec_fast_two_sum(vec_all(2.0 * INV_PI_HI), vec_all(2.0 * INV_PI_LO)));
    A.lo -= A.hi * (A.hi * (mean_error * (2.0 * INV_PI_HI)));
    B.lo += mean_error * (2.0 * INV_PI_HI);
    const VecDd d = vec_two_sum(1.0 - kc_bottom, -t->tail);
    VecDd d2 = vec_two_prod(d.hi, d.hi);
    d2.lo += 2.0 * d.hi * d.lo;
    const Vec cube = d.hi * d2.hi;
    const VecDd s2 = vec_two_prod(vec_all(0.3125), d2.hi);
    VecDd S = vec_fast_two_sum(0.5 * d.hi, s2.hi);
    S.lo += (s2.lo + 0.3125 * d2.lo + 0.5 * d.lo) + cube * (7.0 / 32.0 + d.hi * (169.0 / 1024.0));
    VecDd T = vec_fast_two_sum(0.5 * d.hi, 0.0625 * d2.hi);
    T.lo += (0.0625 * d2.lo + 0.5 * d.lo) + cube * (1.0 / 32.0 + d.hi * (21.0 / 1024.0));
    const VecDd AS = vec_two_prod(A.hi, S.hi), BT = vec_two_prod(B.hi, T.hi);
    VecDd K = vec_fast_two_sum(A.hi, AS.hi);
    K.lo += A.lo + (AS.lo + (A.hi * S.lo + A.lo * S.hi));
    VecDd inverse = vec_fast_two_sum(B.hi, -BT.hi);
    inverse.lo += B.lo - (BT.lo + (B.hi * T.lo + B.lo * T.hi));
    *inv_K = vec_fast_two_sum(inverse.hi, inverse.lo);
    *K_out = vec_fast_two_sum(K.hi, K.lo);
    const VecDd bottom_factor = {1.0 + bottom_m * (0.25 + bottom_m * (9.0 / 64.0)), vec_all(0.0)};
    const VecDd K_bottom = vec_dd_mul(vec_fast_two_sum(vec_all(HALF_PI_HI), vec_all(HALF_PI_LO)), bottom_factor);
    *bottom_scale = vec_dd_mul(K_bottom, *inv_K).hi;
}

/* elliptic_param_begin and _finish lane by lane (m, kc, and k' = kc + kc_lo) in one pass: each
 * level's tail follows its
 * level of the chain, so that the two chains of quotients overlap (the same operations on each
 * lane, in another order). Writes the chain's levels to *c, K, 1/K and the bottom scale. */
ONCE_STAGE void chains_with_K_vec(Vec m, Vec kc, Vec kc_lo, ChainsVec *c, VecDd *K, VecDd *inv_K, Vec *bottom_scale)
{
    Vec kc_n = kc, m_n = m, levels = vec_all(0.0);
    VecMask going = VEC_EVERY;
    TailsVec t = tails_start_vec(kc_lo);
    int n = 0;
    for (;; ++n) {
        /* elliptic_param_begin's test: below the bottom, at least one level, at most 16 levels */
        const VecMask goes = going & ((VecMask)(m_n > BOTTOM_M) | (VecMask)(vec_all((double)n) == 0.0))
                            & (VecMask)(vec_all((double)n) < (double)ELLIPTIC_MAX_LEVELS);
        levels = vec_pick(going & ~goes, vec_all((double)n), levels);   /* ends here: N = n */
        going = goes;
        if (vec_bits(going) == 0) {
            break;
        }
        /* elliptic_param_begin's level on every lane, then elliptic_param_finish's */
        const Vec kc_level = kc_n;
        const Vec one_plus_kc = 1.0 + kc_n, half = 0.5 * one_plus_kc;
        const Vec root_kc = vec_sqrt(kc_n);
        const Vec kc_next = root_kc / half;
        const VecMask small = (VecMask)(kc_n < 0.5);   /* k_next by one quotient of either form */
        const Vec k_next = vec_pick(small, 1.0 - kc_n, m_n) / vec_pick(small, one_plus_kc, one_plus_kc * one_plus_kc);
        c->landen_k[n] = k_next;
        c->landen_1pk[n] = 1.0 + k_next;
        c->landen_1mk[n] = kc_n / half;
        kc_n = vec_pick(going, kc_next, kc_n);
        m_n = vec_pick(going, k_next * k_next, m_n);
        tails_level_vec(&t, going, kc_level, root_kc, one_plus_kc, kc_n);
    }
    c->most = n;
    c->levels = levels;
    c->bottom_m = m_n;
    tails_finish_vec(&t, kc_n, m_n, K, inv_K, bottom_scale);
}

/* --- elliptic_RF lane by lane (elliptic.c) ---------------------------------------------- */

/* elliptic_RF(x, y, z) for finite x, y, z >= 0 of which at most one is 0 (its duplication
 * and series): the duplication theorem (DLMF 19.26.18) until 4^-n spread0 < 0.004 A_n, each
 * lane stopping at its own step (a lane that has stopped keeps its A_n and 4^-n), then
 * DLMF 19.36.1's series in X = 1 - x_n / A_n, Y, Z. */
static inline Vec rf_vec(Vec x, Vec y, Vec z)
{
    const Vec x0 = x, y0 = y;
    const Vec mean0 = (x + y + z) / 3.0;
    const Vec spread0 = vec_max(vec_abs(mean0 - x), vec_max(vec_abs(mean0 - y), vec_abs(mean0 - z)));
    Vec mean = mean0, pow4 = vec_all(1.0);   /* pow4 = 4^-n */
    VecMask going = VEC_EVERY;
    for (int i = 0; i < 200; ++i) {
        going &= (VecMask)(pow4 * spread0 >= 0.004 * mean);
        if (vec_bits(going) == 0) {
            break;
        }
        const Vec sx = vec_sqrt(x), sy = vec_sqrt(y), sz = vec_sqrt(z);
        const Vec lambda = sx * sy + sy * sz + sz * sx;
        x = 0.25 * (x + lambda);   /* read no more once its lane has stopped */
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        mean = vec_pick(going, 0.25 * (mean + lambda), mean);
        pow4 = vec_pick(going, pow4 * 0.25, pow4);
    }
    const Vec X = (mean0 - x0) * pow4 / mean;
    const Vec Y = (mean0 - y0) * pow4 / mean;
    const Vec Z = -(X + Y);
    const Vec E2 = X * Y - Z * Z;
    const Vec E3 = X * Y * Z;
    const Vec series = ELLIPTIC_RF_SERIES(E2, E3);
    return series / vec_sqrt(mean);
}

/* --- eval_any's libration lane by lane (exact.c) ---------------------------------------- */

/* elliptic_atan_series */
static inline Vec vec_atan_series(Vec s)
{
    ELLIPTIC_ATAN_SERIES_BODY(Vec, s);
}

/* elliptic_atan_unit */
static inline Vec vec_atan_unit(Vec y, Vec x)
{
    const Vec a = vec_abs(y), b = x;
    const Vec w1 = vec_pick((VecMask)(a > ELLIPTIC_TAN_PI_8 * b), vec_all(1.0), vec_all(0.0)), w0 = 1.0 - w1;
    const Vec t = (w0 * a + w1 * (a - b)) / (w0 * b + w1 * (a + b));
    const Vec s = t * t;
    const Vec g = vec_atan_series(s);
    const Vec angle = w1 * ELLIPTIC_QUARTER_PI_HI + (w1 * ELLIPTIC_QUARTER_PI_LO + (t + t * s * g));
    return vec_copysign(angle, y);
}

/* elliptic_atan_ratio: its three sectors by exact 0/1 weights, as the scalar code */
static inline Vec vec_atan_ratio(Vec y, Vec x)
{
    const Vec a = vec_abs(y), b = x;
    const Vec w3 = vec_pick((VecMask)(a > ELLIPTIC_TAN_3PI_8 * b), vec_all(1.0), vec_all(0.0));
    const Vec w1 = vec_pick((VecMask)(a > ELLIPTIC_TAN_PI_8 * b), vec_all(1.0), vec_all(0.0)) - w3;
    const Vec w0 = 1.0 - w1 - w3;
    const Vec num = w0 * a + w1 * (a - b) - w3 * b;
    const Vec den = w0 * b + w1 * (a + b) + w3 * a;
    const Vec base_hi = w1 * ELLIPTIC_QUARTER_PI_HI + w3 * (2.0 * ELLIPTIC_QUARTER_PI_HI);
    const Vec base_lo = w1 * ELLIPTIC_QUARTER_PI_LO + w3 * (2.0 * ELLIPTIC_QUARTER_PI_LO);
    const Vec t = num / den;
    const Vec s = t * t;
    const Vec g = vec_atan_series(s);
    return vec_copysign(base_hi + (base_lo + (t + t * s * g)), y);
}

/* trig_series and trig_sincos_small */
static inline void vec_sincos_small(Vec r, Vec *sin_r, Vec *cos_r)
{
    const double *c = TRIG_SIGNED_INVERSE_FACTORIAL;
    const Vec z = r * r;
    const Vec z2 = z * z, z4 = z2 * z2;
    const Vec ps = ((c[3] + z * c[5]) + z2 * (c[7] + z * c[9])) + z4 * ((c[11] + z * c[13]) + z2 * (c[15] + z * c[17]));
    const Vec pc = ((c[2] + z * c[4]) + z2 * (c[6] + z * c[8])) + z4 * ((c[10] + z * c[12]) + z2 * (c[14] + z * c[16]));
    *sin_r = r + (r * z) * ps;
    *cos_r = 1.0 + z * pc;
}

/* elliptic_landen_step with each lane's level factors, where `step` is set: the plain step,
 * then for a chain of more than ELLIPTIC_LEVELS_WITHOUT_RESCALE levels (`long_chain`) the
 * renormalisation once D passes ELLIPTIC_HOMOGENEOUS_RESCALE */
static inline void vec_landen_step(VecMask step, VecMask long_chain, Vec kk, Vec one_plus_k, Vec one_minus_k, Vec *S,
                                  Vec *C, Vec *E, Vec *D)
{
    const Vec d2 = *D * *D;
    Vec up_S = one_plus_k * *S * *D, up_C = *C * *E;
    Vec up_E = one_minus_k * d2 + kk * *C * *C, up_D = d2 + kk * *S * *S;
    const VecMask rescale = long_chain & (VecMask)(up_D > ELLIPTIC_HOMOGENEOUS_RESCALE);
    if (vec_bits(rescale) != 0) {   /* only chains of more than 7 levels */
        const Vec inv = 1.0 / up_D;
        up_S = vec_pick(rescale, up_S * inv, up_S);
        up_C = vec_pick(rescale, up_C * inv, up_C);
        up_E = vec_pick(rescale, up_E * inv, up_E);
        up_D = vec_pick(rescale, vec_all(1.0), up_D);
    }
    if (vec_bits(step) != VEC_ALL_BITS) {   /* a lane whose chain has no such level keeps its values */
        up_S = vec_pick(step, up_S, *S);
        up_C = vec_pick(step, up_C, *C);
        up_E = vec_pick(step, up_E, *E);
        up_D = vec_pick(step, up_D, *D);
    }
    *S = up_S;
    *C = up_C;
    *E = up_E;
    *D = up_D;
}

/* What the evaluation reads of a vector of librations or rotations, lane by lane; the level factors
 * level by level (a lane's own up to its levels, any finite values beyond). */
typedef struct {
    Vec t0, rho_hi, rho_lo, x0_hi, x0_lo, K_hi, bottom_scale, bottom_m, sqrt_k1, kc, omega_half;
    Vec theta_turns;   /* whole turns of theta0, |theta_turns| < 2^50 */
    VecMask rotation;  /* the lanes of a rotation (the others librate) */
    Vec direction;     /* a rotation's sign of omega0 */
    Vec levels;   /* N as doubles */
    int most;    /* the largest N */
    const Vec *landen_k, *landen_1pk, *landen_1mk;   /* [level] */
} MotionVec;

/* Homogeneous coordinates of sn, cn, dn lane by lane (EllipticHomogeneous) */
typedef struct {
    Vec S, C, E, D;
} HomogeneousVec;

/* add_half_turns(half_turns, angle): half_turns_pi and plus_half_turns, the angle alone
 * where the half turns are 0 */
static inline Vec vec_add_half_turns(VecDd half_turns, Vec angle)
{
    const VecDd turn = vec_two_prod(half_turns.hi, vec_all(PI_HI));
    const Vec hi_pi_lo = half_turns.hi * PI_LO, lo_pi_hi = half_turns.lo * PI_HI;
    const Vec wound = turn.hi + (turn.lo + (hi_pi_lo + (lo_pi_hi + angle)));
    return vec_pick((VecMask)(half_turns.hi == 0.0) & (VecMask)(half_turns.lo == 0.0), angle, wound);
}

/* libration_angle_omega from levels 1 (h1) and 0 (h0), the quarter's weights odd and sign,
 * and add_half_turns(2 theta_turns, angle) */
ONCE_STAGE void libration_outputs_vec(const MotionVec *s, Vec odd, Vec sign, HomogeneousVec h1, HomogeneousVec h0,
                                     Vec *theta, Vec *omega)
{
    const Vec even = 1.0 - odd;
    const Vec y1 = even * h1.S + odd * h1.C, x1 = even * h1.D + odd * h1.E;
    const Vec angle = 4.0 * vec_atan_unit(sign * s->sqrt_k1 * y1, x1);
    *theta = vec_add_half_turns((VecDd){2.0 * s->theta_turns, vec_all(0.0)}, angle);
    const Vec cn_num = even * h0.C - odd * (s->kc * h0.S), den = even * h0.D + odd * h0.E;
    *omega = 2.0 * (sign * s->omega_half * (cn_num / den));
}

/* eval_any's rotation from level 0 (h0) and the quarter n (odd: its weight): am(nK + r) -
 * n pi/2 = atan(sn r / cn r) (n even), atan(k' sn r / cn r) (n odd); theta = 2 pi j +
 * direction (n pi + 2 delta), omega = 2 sqrt(m) w0 dn(nK + r), the winding direction n added
 * to the half turns 2 j in double-double */
ONCE_STAGE void rotation_outputs_vec(const MotionVec *s, Vec quarters, Vec odd, HomogeneousVec h0, Vec *theta,
                                    Vec *omega)
{
    const Vec even = 1.0 - odd;
    const Vec delta = vec_atan_ratio((even + odd * s->kc) * h0.S, h0.C);
    const Vec dn_num = even * h0.E + odd * (s->kc * h0.D), den = even * h0.D + odd * h0.E;
    const VecMask backwards = (VecMask)(s->direction < 0.0);
    const VecDd winding = {vec_pick(backwards, -quarters, quarters), vec_pick(backwards, vec_all(-0.0), vec_all(0.0))};
    const Vec angle = 2.0 * s->direction * delta;
    *omega = 2.0 * (s->direction * s->omega_half * (dn_num / den));
    *theta = vec_add_half_turns(vec_dd_add((VecDd){2.0 * s->theta_turns, vec_all(0.0)}, winding), angle);
}

/* eval_any's operations for a libration or rotation at times tv: *theta and *omega for every
 * lane, and a mask of the lanes on the common path (a phase below 2^50 quarter periods, a
 * bottom argument within the series, tv != t0; the caller checks the rest). The phase's
 * nearest integer by the shift where the fma build's phase_near rounds with rint: they differ
 * only in the sign of a zero, which no output reads (nor the half turns, a sum with it). The
 * Landen levels are the same for both motions (elliptic_sncndn_homogeneous_pair's, and
 * elliptic_sncndn_homogeneous's level 0); the outputs of each are formed where a lane has it
 * (rotating: the bits of s->rotation, 0 where the caller knows there is no rotation). */
ONCE_STAGE VecMask eval_motion_vec(const MotionVec *s, int rotating, Vec tv, Vec *theta, Vec *omega)
{
    /* phase_at and phase_near */
    const VecDd tau = vec_two_sum(tv, -s->t0);
    const Vec x_hi = s->rho_hi * tau.hi;
    const Vec x_lo = vec_fmadd(s->rho_hi, tau.hi, -x_hi);
    const Vec quarters = (x_hi + s->x0_hi + 0x1.8p52) - 0x1.8p52;
    const Vec f = ((x_hi - quarters) + s->x0_hi) + (x_lo + (s->rho_hi * tau.lo + s->rho_lo * tau.hi) + s->x0_lo);
    const Vec v = f * s->K_hi;
    /* the quarter n mod 4 as eval_libration_lanes' exact weights */
    const Vec r = quarters - 4.0 * ((0.25 * quarters + 0x1.8p52) - 0x1.8p52);
    const Vec r2 = r * r;
    const Vec odd = r2 * (4.0 - r2) / 3.0;
    const Vec sign = 1.0 - 2.0 * (r2 * (r2 - 1.0) / 12.0 + odd * (1.0 - r) * 0.5);
    const Vec z = vec_abs(v) * s->bottom_scale;
    /* elliptic_landen_bottom, then the steps up to level 1 */
    Vec sz, cz;
    vec_sincos_small(z, &sz, &cz);
    const Vec w = 0.25 * s->bottom_m * (z - sz * cz);
    Vec S = sz - w * cz, C = cz + w * sz, E = 1.0 - 0.5 * s->bottom_m * sz * sz, D = vec_all(1.0);
    const VecMask long_chain = (VecMask)(s->levels > (double)ELLIPTIC_LEVELS_WITHOUT_RESCALE);
    for (int i = s->most - 1; i >= 1; --i) {
        const VecMask below = (VecMask)(vec_all((double)i) < s->levels);   /* a step of this lane's chain */
        vec_landen_step(below, long_chain, s->landen_k[i], s->landen_1pk[i], s->landen_1mk[i], &S, &C, &E, &D);
    }
    Vec S0 = S, C0 = C, E0 = E, D0 = D;
    vec_landen_step(VEC_EVERY, long_chain, s->landen_k[0], s->landen_1pk[0], s->landen_1mk[0], &S0, &C0,
                   &E0, &D0);
    const VecMask negative = (VecMask)(v < 0.0);   /* sn is odd, cn and dn are even */
    const HomogeneousVec h1 = {vec_pick(negative, -S, S), C, E, D}, h0 = {vec_pick(negative, -S0, S0), C0, E0, D0};
    Vec lib_theta = vec_all(0.0), lib_omega = lib_theta, rot_theta = lib_theta, rot_omega = lib_theta;
    if (rotating != VEC_ALL_BITS) {
        libration_outputs_vec(s, odd, sign, h1, h0, &lib_theta, &lib_omega);
    }
    if (rotating != 0) {
        rotation_outputs_vec(s, quarters, odd, h0, &rot_theta, &rot_omega);
    }
    *theta = vec_pick(s->rotation, rot_theta, lib_theta);
    *omega = vec_pick(s->rotation, rot_omega, lib_omega);
    return (VecMask)(vec_abs(x_hi) < 0x1p50) & (VecMask)(z <= ELLIPTIC_SERIES_Z_MAX) & (VecMask)(tv != s->t0);
}

/* --- new states set up and evaluated once ------------------------------------------------ */

/* a and b the same double, bit for bit (+0 and -0 differ; NaN is no double of a set-up) */
static int same_double(double a, double b)
{
    uint64_t x, y;
    memcpy(&x, &a, sizeof x);
    memcpy(&y, &b, sizeof y);
    return x == y;
}

/* test_exact_batch counts the lanes each kind of block did through this; nothing here */
#ifndef ONCE_AVX_TALLY
#define ONCE_AVX_TALLY(kind, done) ((void)0)
#endif

/* A block's elements as lanes (a lane past `lanes` repeats element 0; omega0 NULL: 0) */
typedef struct {
    Vec th, om, w0_hi, w0_lo, tv;
} OnceInputsVec;

ONCE_STAGE OnceInputsVec once_inputs_vec(int lanes, const double *theta0, const double *omega0,
                                       const DoubleDouble *w0, const double *t)
{
    Vec th, om, w0_hi, w0_lo, tv;
    for (int l = 0; l < ONCE_LANES; ++l) {
        const int from = l < lanes ? l : 0;
        th[l] = theta0[from];
        om[l] = omega0 != NULL ? omega0[from] : 0.0;
        w0_hi[l] = w0[from].hi;
        w0_lo[l] = w0[from].lo;
        tv[l] = t[from];
    }
    const OnceInputsVec in = {th, om, w0_hi, w0_lo, tv};
    return in;
}

/* v on the lanes taken, lane `any`'s value (a lane taken) on the others: a lane not taken
 * runs a copy, so that no loop of the set-up runs longer for it */
ONCE_STAGE Vec copy_taken(Vec v, VecMask taken, int any)
{
    return vec_pick(taken, v, vec_all(v[any]));
}

/* set_libration_scales's fields (k, k' = kc, K from the chain, w0) and t0; the rates, the
 * initial phase and the turns are the caller's */
ONCE_STAGE void libration_scales_vec(MotionVec *s, const ChainsVec *c, Vec k, Vec kc, Vec w0_hi, Vec K_hi, double t0)
{
    s->t0 = vec_all(t0);
    s->K_hi = K_hi;
    s->bottom_m = c->bottom_m;
    s->sqrt_k1 = k / (1.0 + kc);
    s->kc = kc;
    s->omega_half = k * w0_hi;
    s->rotation = (VecMask){0};
    s->direction = vec_all(1.0);
    s->levels = c->levels;
    s->most = c->most;
    s->landen_k = c->landen_k;
    s->landen_1pk = c->landen_1pk;
    s->landen_1mk = c->landen_1mk;
}

/* The librations and rotations s evaluated at tv (rotating: as eval_motion_vec's); writes the
 * lanes taken that are on the evaluation's common path and returns them as bits */
ONCE_STAGE int eval_taken_vec(const MotionVec *s, int rotating, Vec tv, int lanes, VecMask taken, double *theta,
                              double *omega)
{
    Vec angle, om;
    const VecMask path = eval_motion_vec(s, rotating, tv, &angle, &om);
    int done = 0;
    for (int l = 0; l < lanes; ++l) {
        if (taken[l] && path[l]) {
            theta[l] = angle[l];
            omega[l] = om[l];
            done |= 1 << l;
        }
    }
    return done;
}

/* Up to ONCE_LANES releases from rest (omega0 = 0, |theta0| < 2^50, w0 accepted) set up at t0 and
 * evaluated once each at t[l], all in vectors: init_from_rest's operations (the cosine begun,
 * the chain, the cosine ended, K, the rates) and the evaluation's, without a set-up written.
 * Returns the lanes done as bits; the others (a cosine whose leading double is not certain or
 * within 2^-500 of 0, off the evaluation's common path) are the caller's. */
ONCE_STAGE int once_avx(int lanes, const double *theta0, const DoubleDouble *w0, double t0, const double *t,
                        double *theta, double *omega)
{
    const OnceInputsVec in = once_inputs_vec(lanes, theta0, NULL, w0, t);
    CosSinVec trig;
    Vec turns;
    VecMask reduced;
    const VecDd th = reduce_turns_vec(in.th, &turns, &reduced);
    cos_sin_begin_vec((VecDd){0.5 * th.hi, 0.5 * th.lo}, &trig);   /* step 1: th / 2 exact */
    VecMask taken = {0};   /* every lane set below */
    int any = -1;
    for (int l = 0; l < ONCE_LANES; ++l) {
        taken[l] = -(l < lanes && reduced[l] && trig.certain[l] && fabs(trig.cos_lead[l]) > 0x1p-500);
        any = taken[l] && any < 0 ? l : any;
    }
    if (any < 0) {
        return 0;
    }
    /* from_rest_start: m = k^2 (at most 1), k' = c's leading double */
    const Vec k = vec_abs(trig.sin_x), k2 = k * k;
    Vec m = vec_pick((VecMask)(k2 < 1.0), k2, vec_all(1.0)), kc = vec_abs(trig.cos_lead);
    m = copy_taken(m, taken, any);
    kc = copy_taken(kc, taken, any);
    /* settle_initial_angle: c < 0 (theta0 just past pi) moves th by a turn, s and c change sign */
    const VecMask past = (VecMask)(trig.cos_lead < 0.0);
    const VecDd cosine = cos_sin_end_vec(&trig);
    const VecDd c = vec_pick_dd(past, vec_dd_neg(cosine), cosine);
    const Vec s_hi = vec_pick(past, -trig.sin_x, trig.sin_x);
    /* the chain on c's leading double, K and 1/K from its tails with c's low part */
    ChainsVec chains;
    VecDd K, inv_K;
    MotionVec s;
    chains_with_K_vec(m, kc, c.lo, &chains, &K, &inv_K, &s.bottom_scale);
    /* from_rest_fields: rho = w0 / K, u0 = +-K (0 at the bottom), x0 = +-1 */
    libration_scales_vec(&s, &chains, k, kc, in.w0_hi, K.hi, t0);
    const VecDd rho = vec_dd_mul((VecDd){in.w0_hi, in.w0_lo}, inv_K);
    const Vec u0 = vec_pick((VecMask)(k == 0.0), vec_all(0.0), vec_pick((VecMask)(s_hi < 0.0), -K.hi, K.hi));
    s.theta_turns = turns + vec_pick(past, vec_pick((VecMask)(th.hi > 0.0), vec_all(1.0), vec_all(-1.0)), vec_all(0.0));
    s.rho_hi = rho.hi;
    s.rho_lo = rho.lo;
    s.x0_hi = vec_pick((VecMask)(u0 < 0.0), vec_all(-1.0), vec_pick((VecMask)(u0 > 0.0), vec_all(1.0), vec_all(0.0)));
    s.x0_lo = vec_all(0.0);
    const int done = eval_taken_vec(&s, 0, in.tv, lanes, taken, theta, omega);
    ONCE_AVX_TALLY(rest, done);
    return done;
}

/* A moving start's parameter lane by lane, libration_parameter's or rotation_parameter's
 * (the fine window left out), and what the initial phase needs of it */
typedef struct {
    Vec m;            /* the parameter of the Jacobi functions (mu = 1/m for a rotation) */
    VecDd m1;         /* its complement */
    Vec rf_x, rf_y;   /* the first two arguments of R_F for F(phi0) (the third is 1) */
    Vec factor;       /* F(phi0) = factor R_F: |s|/k (libration), direction s (rotation) */
    VecMask ok;       /* the parameter accepted (elliptic_param_acceptable), R_F's x or y > 0 */
} ParameterVec;

/* elliptic_param_acceptable lane by lane (isfinite(x) as |x| <= DBL_MAX) */
static inline VecMask acceptable_vec(Vec m, VecDd m1)
{
    return (VecMask)(m >= 0.0) & (VecMask)(m <= 1.0) & (VecMask)(m1.hi >= 0.0) & (VecMask)(m1.hi <= 1.0)
           & (VecMask)(vec_abs(m1.lo) <= DBL_MAX) & (VecMask)(vec_abs(m + m1.hi - 1.0) <= 1e-12);
}

/* libration_parameter for gap > 0: q = hs_n / w_n, m1 = (gap / w_n)(c + q), k = hypot(s, q)
 * (glibc's, lane by lane), m = min(k^2, 1); init_libration's F(|phi0| | m) = (|s|/k)
 * R_F((q/k)^2, c^2, 1) (DLMF 19.25.5, scaled) */
ONCE_STAGE ParameterVec libration_parameter_vec(VecDd c, Vec s_hi, VecDd w_n, Vec hs_n, VecDd gap, Vec *k_out)
{
    ParameterVec p;
    const VecDd q = vec_dd_div((VecDd){hs_n, vec_all(0.0)}, w_n);
    p.m1 = vec_dd_mul(vec_dd_div(gap, w_n), vec_dd_add(c, q));
    Vec k;
    for (int l = 0; l < ONCE_LANES; ++l) {
        k[l] = hypot(s_hi[l], q.hi[l]);
    }
    const Vec k2 = k * k;
    p.m = vec_pick((VecMask)(k2 < 1.0), k2, vec_all(1.0));
    const Vec q_k = q.hi / k;
    p.rf_x = q_k * q_k;
    p.rf_y = c.hi * c.hi;
    p.factor = vec_abs(s_hi) / k;
    p.ok = (VecMask)(gap.hi > 0.0) & (VecMask)(p.m1.hi > 0.0) & acceptable_vec(p.m, p.m1) & (VecMask)(k != 0.0)
           & (VecMask)(p.rf_y > 0.0);
    *k_out = k;
    return p;
}

/* rotation_parameter for gap < 0 outside the fine window: s = sin(th/2) in double-double
 * (dd_sin; th moved by a turn where `past`, finish_initial_angle), rho = s w_n / hs_n,
 * 1 + rho^2, mu1 = (1 - gamma)(1 + gamma)/(1 + rho^2) with 1 - gamma = -gap / hs_n and
 * gamma = c w_n / hs_n, mu = min((w_n / hs_n)^2 / (1 + rho^2), 1); init_rotation's
 * v0 = F(th/2 | mu) = direction s R_F(c^2, 1/(1 + rho^2), 1) (DLMF 19.25.5) */
ONCE_STAGE ParameterVec rotation_parameter_vec(const CosSinVec *trig, VecDd th, VecMask past, VecDd c, VecDd c_w,
                                               VecDd w_n, Vec hs_n, VecDd gap, Vec direction, VecDd *one_plus_rho2)
{
    ParameterVec p;
    VecDd s;
    if (vec_bits(past) == 0) {   /* th/2 = theta0/2: dd_cos_sin_begin's reduction and table point */
        s = sin_at_point_vec(&trig->point, trig->n);
    } else {
        const Vec shift = vec_pick((VecMask)(th.hi > 0.0), vec_all(1.0), vec_all(-1.0));
        const VecDd moved = vec_pick_dd(past, vec_subtract_turns(th, shift), th);
        s = dd_sin_vec((VecDd){0.5 * moved.hi, 0.5 * moved.lo});
    }
    const VecDd hs = {hs_n, vec_all(0.0)};
    const VecDd rho = vec_dd_div(vec_dd_mul(s, w_n), hs);
    const VecDd opr2 = vec_dd_add((VecDd){vec_all(1.0), vec_all(0.0)}, vec_dd_mul(rho, rho));
    const VecDd one_minus_gamma = vec_dd_div(vec_dd_neg(gap), hs), gamma = vec_dd_div(c_w, hs);
    p.m1 = vec_dd_div(vec_dd_mul(one_minus_gamma, vec_dd_add((VecDd){vec_all(1.0), vec_all(0.0)}, gamma)), opr2);
    const Vec w_hs = w_n.hi / hs_n, mu = w_hs * w_hs / opr2.hi;
    p.m = vec_pick((VecMask)(mu < 1.0), mu, vec_all(1.0));
    p.rf_x = c.hi * c.hi;
    p.rf_y = 1.0 / opr2.hi;
    p.factor = direction * s.hi;
    p.ok = (VecMask)(gap.hi < 0.0) & acceptable_vec(p.m, p.m1) & (VecMask)(p.rf_x > 0.0);
    *one_plus_rho2 = opr2;
    return p;
}

static inline ParameterVec pick_parameter(VecMask where, ParameterVec yes, ParameterVec no)
{
    ParameterVec p;
    p.m = vec_pick(where, yes.m, no.m);
    p.m1 = vec_pick_dd(where, yes.m1, no.m1);
    p.rf_x = vec_pick(where, yes.rf_x, no.rf_x);
    p.rf_y = vec_pick(where, yes.rf_y, no.rf_y);
    p.factor = vec_pick(where, yes.factor, no.factor);
    p.ok = (where & yes.ok) | (~where & no.ok);
    return p;
}

/* Up to ONCE_LANES moving starts (omega0 != 0, |theta0| < 2^50, w0 accepted) set up at t0 and
 * evaluated once each at t[l], in vectors: exact_init_dd's general path for a libration or a
 * rotation (finish_initial_angle, locate_separatrix, libration_parameter or
 * rotation_parameter, init_libration or init_rotation, set_quarter_rates) and the
 * evaluation, without a set-up written. The two kinds share the chain, K, R_F, the rates and
 * the Landen levels; what is a kind's own is formed where a lane has that kind. Returns the
 * lanes done as bits; the others are the caller's: the separatrix and locate_separatrix's
 * fine window next to it, parameters elliptic_param_acceptable refuses, k = 0, and the rare
 * lanes outside the vectors' range (a power of two of the rates beyond 2^+-1000, m1 below
 * 2^-900, where dd_scalbn and dd_sqrt take other paths), and times off the evaluation's
 * common path. *rotating: the lanes that rotate, as bits. With rotations_too = 0 (a
 * constant) the rotations' code is left out, and a block with a rotation returns 0 once it
 * has found it (see once_moving_avx). */
ONCE_STAGE int once_moving_block(int lanes, const double *theta0, const double *omega0, const DoubleDouble *w0,
                                 double t0, const double *t, double *theta, double *omega, int rotations_too,
                                 int *rotating_lanes)
{
    const OnceInputsVec in = once_inputs_vec(lanes, theta0, omega0, w0, t);
    CosSinVec trig;
    Vec turns;
    VecMask reduced;
    const VecDd th = reduce_turns_vec(in.th, &turns, &reduced);
    cos_sin_begin_vec((VecDd){0.5 * th.hi, 0.5 * th.lo}, &trig);   /* step 1: th / 2 exact */
    /* finish_initial_angle: c < 0 moves th by a turn, s and c change sign (its c = -0 with
     * th < 0 is taken by neither kind: gap = -hs_n, c^2 = 0) */
    const VecDd cosine = cos_sin_end_vec(&trig);
    const VecMask past = (VecMask)(cosine.hi < 0.0);
    const VecDd c = vec_pick_dd(past, vec_dd_neg(cosine), cosine);
    const Vec s_hi = vec_pick(past, -trig.sin_x, trig.sin_x);
    /* locate_separatrix: w_n = w0 2^-e, hs_n = (|omega0|/2) 2^-e for e the exponent of the
     * larger; gap = c w_n - hs_n, the sign of m1 */
    const Vec half_speed = 0.5 * vec_abs(in.om);
    Vec down, up;
    for (int l = 0; l < ONCE_LANES; ++l) {
        const int e = dd_frexp_exponent(larger(in.w0_hi[l], half_speed[l]));
        const int in_range = l < lanes && reduced[l] && e >= -1000 && e <= 1000;   /* dd_scalbn's 2^-e, 2^e */
        down[l] = in_range ? dd_scalbn(1.0, -e) : 0.0;   /* 0: a lane left to the caller */
        up[l] = in_range ? dd_scalbn(1.0, e) : 1.0;
    }
    const VecMask in_range = (VecMask)(down != 0.0);
    const VecDd w_n = {in.w0_hi * down, in.w0_lo * down};
    const Vec hs_n = half_speed * down;
    const VecDd c_w = vec_dd_mul(c, w_n);
    const VecDd gap = vec_dd_add(c_w, (VecDd){-hs_n, vec_all(-0.0)});   /* dd_sub */
    const VecMask outside = in_range & ~(VecMask)(vec_abs(gap.hi) < 0x1p-30 * hs_n);   /* the fine window */
    const VecMask rotation = outside & (VecMask)(gap.hi < 0.0);
    *rotating_lanes = vec_bits(rotation);
    const int rotating = rotations_too ? *rotating_lanes : 0, librating = vec_bits(outside & (VecMask)(gap.hi > 0.0));
    if ((rotating == 0 && librating == 0) || rotating != *rotating_lanes) {
        return 0;
    }
    /* each kind's parameter where a lane has it */
    const Vec direction = vec_pick((VecMask)(in.om > 0.0), vec_all(1.0), vec_all(-1.0));
    ParameterVec par;
    Vec k = vec_all(0.0);
    VecDd one_plus_rho2 = {vec_all(1.0), vec_all(0.0)};
    if (!rotations_too || librating != 0) {
        par = libration_parameter_vec(c, s_hi, w_n, hs_n, gap, &k);
    }
    if (rotating != 0) {
        const ParameterVec rot = rotation_parameter_vec(&trig, th, past, c, c_w, w_n, hs_n, gap, direction,
                                                      &one_plus_rho2);
        par = librating != 0 ? pick_parameter(rotation, rot, par) : rot;
    }
    /* elliptic_param_init_root: m1 = TwoSum(m1), k' = sqrt(m1) */
    VecDd m1_sum = vec_two_sum(par.m1.hi, par.m1.lo);
    const VecMask taken = outside & par.ok & (VecMask)(m1_sum.hi >= 0x1p-900);
    const int taken_bits = vec_bits(taken);
    if (taken_bits == 0) {
        return 0;
    }
    Vec m = par.m, rf_x = par.rf_x, rf_y = par.rf_y;
    if (taken_bits != VEC_ALL_BITS) {   /* a branch, not a wait on the masks, where every lane is taken */
        const int any = __builtin_ctz((unsigned)taken_bits);
        m = copy_taken(m, taken, any);
        rf_x = copy_taken(rf_x, taken, any);
        rf_y = copy_taken(rf_y, taken, any);
        m1_sum.hi = copy_taken(m1_sum.hi, taken, any);
        m1_sum.lo = copy_taken(m1_sum.lo, taken, any);
    }
    /* F first: its roots wait on nothing of the chain, whose roots then follow them */
    const Vec f = par.factor * rf_vec(rf_x, rf_y, vec_all(1.0));
    const VecDd kc = vec_dd_sqrt(m1_sum);
    ChainsVec chains;
    VecDd K, inv_K;
    MotionVec s;
    chains_with_K_vec(m, kc.hi, kc.lo, &chains, &K, &inv_K, &s.bottom_scale);
    libration_scales_vec(&s, &chains, k, kc.hi, in.w0_hi, K.hi, t0);
    /* a libration's u0 = F, or 2K - F for omega0 < 0 (F(pi - phi) = 2K - F(phi)), with the
     * sign of s, and its rate w_n; a rotation's u0 = v0 and rate (|omega0|/2) sqrt(1 + rho^2) */
    const Vec base = vec_pick((VecMask)(in.om >= 0.0), f, (2.0 * K.hi - f) + 2.0 * K.lo);
    Vec u0 = vec_pick((VecMask)(s_hi < 0.0), -base, base);
    VecDd rate_n = w_n;
    if (rotating != 0) {
        const VecDd rotation_rate = vec_dd_mul((VecDd){hs_n, vec_all(0.0)}, vec_dd_sqrt(one_plus_rho2));
        u0 = vec_pick(rotation, f, u0);
        rate_n = vec_pick_dd(rotation, rotation_rate, w_n);
        s.rotation = rotation;
        s.direction = direction;
        s.omega_half = vec_pick(rotation, rotation_rate.hi * up, s.omega_half);   /* dd_ldexp(rate, e).hi */
    }
    /* set_quarter_rates: rho = (rate_n / K) 2^e, x0 = u0 / K */
    const VecDd rho = vec_dd_mul(rate_n, inv_K), x0 = vec_dd_mul((VecDd){u0, vec_all(0.0)}, inv_K);
    s.rho_hi = rho.hi * up;
    s.rho_lo = rho.lo * up;
    s.x0_hi = x0.hi;
    s.x0_lo = x0.lo;
    s.theta_turns = turns + vec_pick(past, vec_pick((VecMask)(th.hi > 0.0), vec_all(1.0), vec_all(-1.0)), vec_all(0.0));
    const int done = eval_taken_vec(&s, rotating, in.tv, lanes, taken, theta, omega);
    ONCE_AVX_TALLY(moving, done & ~rotating);
    ONCE_AVX_TALLY(rotation, done & rotating);
    return done;
}

/* once_moving_block for librations alone, and for librations and rotations: two functions,
 * so that the rotations' code does not weigh on the librations' (in one function it cost a
 * moving libration 5-7 ns, bench_exact_moving) */
__attribute__((noinline)) static int once_moving_librations(int lanes, const double *theta0, const double *omega0,
                                                            const DoubleDouble *w0, double t0, const double *t,
                                                            double *theta, double *omega, int *rotating_lanes)
{
    return once_moving_block(lanes, theta0, omega0, w0, t0, t, theta, omega, 0, rotating_lanes);
}

__attribute__((noinline)) static int once_moving_rotations(int lanes, const double *theta0, const double *omega0,
                                                           const DoubleDouble *w0, double t0, const double *t,
                                                           double *theta, double *omega, int *rotating_lanes)
{
    return once_moving_block(lanes, theta0, omega0, w0, t0, t, theta, omega, 1, rotating_lanes);
}

/* A block of moving starts by once_moving_librations, or once_moving_rotations where the
 * block has a rotation: *expect_rotation (the last block's) sends it to the latter at once,
 * else the former finds the rotation after the angle and the gap and hands the block over */
static inline int once_moving_avx(int lanes, const double *theta0, const double *omega0, const DoubleDouble *w0,
                                  double t0, const double *t, double *theta, double *omega, int *expect_rotation)
{
    int rotating = 0, done = 0;
    if (!*expect_rotation) {
        done = once_moving_librations(lanes, theta0, omega0, w0, t0, t, theta, omega, &rotating);
    }
    if (*expect_rotation || rotating != 0) {
        done = once_moving_rotations(lanes, theta0, omega0, w0, t0, t, theta, omega, &rotating);
    }
    *expect_rotation = rotating != 0;
    return done;
}

#endif
