/* once_avx.h: four new states set up and evaluated once, in AVX vectors, for
 * pendulum_exact_once_gl_many in the fma build (exact_fma.c: GCC on x86-64, AVX and FMA enabled
 * by its target pragma). Included at the end of exact.c there alone: that build compiles dd.c,
 * elliptic.c and exact.c as one translation unit, and this code reads their tables and
 * constants (dd.c's TABLE_64 and series, elliptic.c's BOTTOM_M and pi's parts).
 *
 * Each lane runs the scalar code's operations in their order, on GCC's vector of four doubles:
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
 * (v4_pick, a blend); the table's rows are read lane by lane; a lane whose Landen chain has
 * ended is carried along with its values frozen. test_exact_batch compares every output with
 * the scalar set-up and evaluation. */
#ifndef PENDULUM_ONCE_AVX_H
#define PENDULUM_ONCE_AVX_H

#include <float.h>
#include <immintrin.h>

/* --- double-double operations on four lanes ----------------------------------------------- */

typedef double V4 __attribute__((vector_size(32)));
typedef long long V4Mask __attribute__((vector_size(32)));

/* a stage inlined where it is used: left to GCC, the stages both kinds of block share and the
 * block of releases from rest went out of line, and a release from rest took 10-20 % longer
 * (bench_exact's once kind) */
#define ONCE_STAGE static inline __attribute__((always_inline))

/* lanes to a vector, and the mask of every lane */
#define AVX_LANES 4
#define V4_EVERY ((V4Mask){-1, -1, -1, -1})

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

/* dd_add of dd.h: the sums of the high and of the low parts, each error-free, two
 * renormalisations */
static inline V4Dd v4_dd_add(V4Dd x, V4Dd y)
{
    V4Dd s = v4_two_sum(x.hi, y.hi);
    const V4Dd t = v4_two_sum(x.lo, y.lo);
    s.lo += t.hi;
    s = v4_fast_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return v4_fast_two_sum(s.hi, s.lo);
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

/* the larger of a and b, neither NaN (fmax) */
static inline V4 v4_max(V4 a, V4 b)
{
    return (V4)_mm256_max_pd((__m256d)a, (__m256d)b);
}

static inline V4 v4_sqrt(V4 x)
{
    return (V4)_mm256_sqrt_pd((__m256d)x);
}

/* dd_sqrt of dd.h for x.hi in [2^-900, inf): s = sqrt(x.hi), sqrt(x) = s + (x - s^2) / (2 s) */
static inline V4Dd v4_dd_sqrt(V4Dd x)
{
    const V4 s = v4_sqrt(x.hi);
    const V4Dd sq = v4_two_prod(s, s);
    return v4_fast_two_sum(s, (((x.hi - sq.hi) - sq.lo) + x.lo) / (2.0 * s));
}

/* --- dd_cos_sin_begin and _end on four lanes (dd.c) -------------------------------------- */

/* table_point's DdTablePoint on four lanes: y = sign (a + r), a the table point, C, S = cos a, sin a */
typedef struct {
    V4 sign;
    V4Dd r, C, S;
} TablePointV4;

/* What cos_sin_begin_v4 knows of four arguments x (dd_cos_sin_begin's DdCosSin, lane by
 * lane): y = x - n pi/2, n in {-1, 0, 1}, the double sin x, the table point and the leading
 * double of cos x with its certificate. */
typedef struct {
    V4Dd y;
    V4 n;
    V4 sin_x;
    TablePointV4 point;
    V4 cos_lead;
    V4Mask certain;
} CosSinV4;

/* horner_double on four lanes */
static inline V4 v4_horner_double(const DoubleDouble *coef, V4 z)
{
    V4 tail = v4_all(coef[13].hi);
    for (int j = 12; j >= 0; --j) {
        tail = coef[j].hi + z * tail;
    }
    return tail;
}

/* sin_versine_small on four lanes */
static inline void v4_sin_versine_small(V4Dd r, V4Dd *w, V4Dd *v)
{
    V4Dd r2 = v4_two_prod(r.hi, r.hi);
    r2.lo += 2.0 * r.hi * r.lo;
    const V4 z = r2.hi;
    const V4 p_rest = SMALL_P_REST(z);
    const V4 q_rest = SMALL_Q_REST(z);
    const V4Dd p2 = v4_dd_mul(r2, (V4Dd){v4_all(INV_5F_HI), v4_all(INV_5F_LO)});
    const V4Dd q2 = v4_dd_mul(r2, (V4Dd){v4_all(-INV_6F_HI), v4_all(-INV_6F_LO)});
    V4Dd P = v4_fast_two_sum(v4_all(-INV_3F_HI), p2.hi), Q = v4_fast_two_sum(v4_all(INV_4F_HI), q2.hi);
    P.lo += (-INV_3F_LO + p2.lo) + p_rest;
    Q.lo += (INV_4F_LO + q2.lo) + q_rest;
    *w = v4_add_smaller(r, v4_dd_mul(v4_dd_mul(r, r2), P));
    *v = v4_add_smaller((V4Dd){0.5 * r2.hi, 0.5 * r2.lo}, v4_dd_neg(v4_dd_mul(v4_dd_mul(r2, r2), Q)));
}

/* reduce_quadrant's first branch on four arguments x, |x.hi| < 2: n in {-1, 0, 1},
 * y = x - n pi/2 (y = x for n = 0) */
ONCE_STAGE V4Dd reduce_quadrant_v4(V4Dd x, V4 *quadrants)
{
    const V4 n = v4_pick((V4Mask)(x.hi > 0.5 * HALF_PI_HI), v4_all(1.0), v4_all(0.0))
                 - v4_pick((V4Mask)(x.hi < -0.5 * HALF_PI_HI), v4_all(1.0), v4_all(0.0));
    const V4 head = x.hi - n * HALF_PI_HI;
    const V4Dd rest = v4_two_sum(x.lo, -n * HALF_PI_LO);
    V4Dd y = v4_two_sum(head, rest.hi);
    y.lo += rest.lo - n * HALF_PI_LOLO;
    y = v4_fast_two_sum(y.hi, y.lo);
    *quadrants = n;
    return v4_pick_dd((V4Mask)(n == 0.0), x, y);
}

/* table_point of four y, |y| <= pi/4 + small: i = nearest(64 |y|), ties up, its row read
 * lane by lane, r = |y| - i/64 */
ONCE_STAGE TablePointV4 table_point_v4(V4Dd y)
{
    TablePointV4 t;
    t.sign = v4_pick((V4Mask)(y.hi < 0.0), v4_all(-1.0), v4_all(1.0));
    const V4Dd u = {t.sign * y.hi, t.sign * y.lo};
    const V4 scaled = u.hi * 64.0;
    const V4 whole = (V4)_mm256_round_pd((__m256d)scaled, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
    const V4 index = whole + v4_pick((V4Mask)(scaled - whole >= 0.5), v4_all(1.0), v4_all(0.0));
    /* the four rows {cos hi, cos lo, sin hi, sin lo} loaded whole and transposed */
    const __m256d r0 = _mm256_loadu_pd(TABLE_64[(int)index[0]]), r1 = _mm256_loadu_pd(TABLE_64[(int)index[1]]);
    const __m256d r2 = _mm256_loadu_pd(TABLE_64[(int)index[2]]), r3 = _mm256_loadu_pd(TABLE_64[(int)index[3]]);
    const __m256d even01 = _mm256_unpacklo_pd(r0, r1), odd01 = _mm256_unpackhi_pd(r0, r1);
    const __m256d even23 = _mm256_unpacklo_pd(r2, r3), odd23 = _mm256_unpackhi_pd(r2, r3);
    t.C.hi = (V4)_mm256_permute2f128_pd(even01, even23, 0x20);
    t.C.lo = (V4)_mm256_permute2f128_pd(odd01, odd23, 0x20);
    t.S.hi = (V4)_mm256_permute2f128_pd(even01, even23, 0x31);
    t.S.lo = (V4)_mm256_permute2f128_pd(odd01, odd23, 0x31);
    t.r = v4_two_sum(u.hi - index * 0.015625, u.lo);
    return t;
}

/* sincos_at on four lanes: cos y where `cosine` is set, sin y elsewhere, by the addition
 * theorems cos(a + r) = C - (S w + C v), sin(a + r) = S + (C w - S v) */
ONCE_STAGE V4Dd table_sincos_v4(const TablePointV4 *t, V4Mask cosine)
{
    V4Dd w, v;
    v4_sin_versine_small(t->r, &w, &v);
    const V4Dd C = t->C, S = t->S;
    V4Dd cos_y = {v4_all(0.0), v4_all(0.0)}, sin_y = cos_y;
    if (v4_bits(cosine) != 0) {   /* the sums a lane needs; both where the lanes differ */
        cos_y = v4_add_smaller(C, v4_dd_neg(v4_add_smaller(v4_dd_mul(S, w), v4_dd_mul(C, v))));
    }
    if (v4_bits(cosine) != 0xF) {
        const V4Dd sin_abs = v4_add_smaller(S, v4_add_smaller(v4_dd_mul(C, w), v4_dd_neg(v4_dd_mul(S, v))));
        sin_y.hi = t->sign * sin_abs.hi;
        sin_y.lo = t->sign * sin_abs.lo;
    }
    return v4_pick_dd(cosine, cos_y, sin_y);
}

/* dd_cos_sin_begin on four arguments x + 0, |x| < 2 (reduce_quadrant's first branch), into
 * a CosSinV4 */
ONCE_STAGE void cos_sin_begin_v4(V4 xh, CosSinV4 *out)
{
    V4 n;
    const V4Dd y = reduce_quadrant_v4((V4Dd){xh, v4_all(0.0)}, &n);
    /* quadrant_of(n): 0, 1, or 3 for n = -1; odd for n != 0; flip = -1 for quadrant 1 */
    const V4Mask odd = (V4Mask)(n != 0.0), flip_minus = (V4Mask)(n > 0.0);
    /* the double sin x: the series in double of sincos_reduced */
    const V4 z = v4_dd_mul(y, y).hi;
    V4 other;
    if (v4_bits(odd) == 0) {   /* the series a lane needs; both where the lanes differ */
        other = y.hi + y.hi * z * v4_horner_double(SIN_COEF, z);
    } else if (v4_bits(odd) == 0xF) {
        other = 1.0 + z * v4_horner_double(COS_COEF, z);
    } else {
        other = v4_pick(odd, 1.0 + z * v4_horner_double(COS_COEF, z), y.hi + y.hi * z * v4_horner_double(SIN_COEF, z));
    }
    const V4 sin_x = v4_pick((V4Mask)(n < 0.0), -other, other);
    const TablePointV4 point = table_point_v4(y);
    const V4 sign = point.sign;
    const V4Dd r = point.r, C = point.C, S = point.S;
    /* table_leading */
    const V4Dd R2 = v4_two_prod(r.hi, r.hi);
    const V4 zr = R2.hi;
    const V4 w_rest = TABLE_SIN_REST(r.hi, r.lo, zr);
    const V4 v_rest = TABLE_VERSINE_REST(r.hi, r.lo, R2.lo, zr);
    const V4Dd first = v4_two_prod(v4_pick(odd, C.hi, -S.hi), r.hi);
    const V4 base = v4_pick(odd, S.hi, C.hi), other_hi = v4_pick(odd, C.hi, -S.hi);
    const V4 base_lo = v4_pick(odd, S.lo, C.lo), other_lo = v4_pick(odd, C.lo, -S.lo);
    const V4Dd second = v4_two_prod(-base, 0.5 * zr);
    const V4Dd A = v4_two_sum(base, first.hi), B = v4_two_sum(A.hi, second.hi);
    const V4 rest_sum = ((A.lo + B.lo) + (first.lo + second.lo))
                        + ((base_lo - base_lo * (0.5 * zr) - base * v_rest) + (other_hi * w_rest + other_lo * r.hi));
    const V4Dd sum = v4_two_sum(B.hi, rest_sum);
    const V4 bound = 0x1p-66 * v4_abs(sum.hi);
    const V4 flip = v4_pick(flip_minus, v4_all(-1.0), v4_all(1.0));
    out->y = y;
    out->n = n;
    out->sin_x = sin_x;
    out->point = point;
    out->cos_lead = flip * v4_pick(odd, sign * sum.hi, sum.hi);
    out->certain = (V4Mask)(sum.hi + (sum.lo + bound) == sum.hi) & (V4Mask)(sum.hi + (sum.lo - bound) == sum.hi);
}

/* dd_cos_sin_end of cos_sin_begin_v4's lanes: cos x in double-double */
ONCE_STAGE V4Dd cos_sin_end_v4(const CosSinV4 *in)
{
    const V4Mask odd = (V4Mask)(in->n != 0.0);
    const V4 flip = v4_pick((V4Mask)(in->n > 0.0), v4_all(-1.0), v4_all(1.0));
    /* sincos_at: cos for even quadrants, sin for odd */
    const V4Dd value = table_sincos_v4(&in->point, ~odd);
    /* the certain leading double, or the value itself */
    const V4 lead = in->cos_lead;
    const V4Dd known = {lead, flip * ((value.hi - flip * lead) + value.lo)};
    return v4_pick_dd(in->certain, known, (V4Dd){flip * value.hi, flip * value.lo});
}

/* dd_sin's value from the table point of y = x - n pi/2: sin y, cos y (n = 1) or -cos y
 * (n = -1) */
ONCE_STAGE V4Dd sin_at_point_v4(const TablePointV4 *point, V4 n)
{
    const V4Dd value = table_sincos_v4(point, (V4Mask)(n != 0.0));
    return v4_pick_dd((V4Mask)(n < 0.0), v4_dd_neg(value), value);
}

/* dd_sin of four x, |x.hi| < 2 */
ONCE_STAGE V4Dd dd_sin_v4(V4Dd x)
{
    V4 n;
    const TablePointV4 point = table_point_v4(reduce_quadrant_v4(x, &n));
    return sin_at_point_v4(&point, n);
}

/* --- elliptic_param_begin and _finish on four lanes (elliptic.c) ------------------------- */

/* The Landen chains of four lanes, as the evaluation reads them: each level's factors (a
 * lane's own up to its N, frozen values past it), N and m_N. */
typedef struct {
    V4 landen_k[ELLIPTIC_MAX_LEVELS], landen_1pk[ELLIPTIC_MAX_LEVELS], landen_1mk[ELLIPTIC_MAX_LEVELS];
    V4 levels;    /* N as doubles */
    int most;     /* the largest N */
    V4 bottom_m;  /* m_N */
} ChainsV4;

/* elliptic_param_finish's running values on four lanes: the tail, the mean and its error */
typedef struct {
    V4 tail;
    V4Dd mean;
    V4 mean_error;
} TailsV4;

static inline TailsV4 tails_start_v4(V4 kc_lo)
{
    const TailsV4 t = {kc_lo, {v4_all(1.0), v4_all(0.0)}, v4_all(0.0)};
    return t;
}

/* elliptic_param_finish's level n, with mean_times(&mean, &mean_error, one_plus / 2,
 * tail_h / 2), on the lanes whose chain has that level (active); the others keep their values */
static inline void tails_level_v4(TailsV4 *t, V4Mask active, V4 kc_n, V4 root_n, V4 one_plus_n, V4 kc_next)
{
    const V4 tail = t->tail;
    const V4Dd mean = t->mean;
    const V4 e_h = kc_n - (one_plus_n - 1.0);
    const V4Dd root_sq = v4_two_prod(root_n, root_n);
    const V4 e_s = (kc_n - root_sq.hi) - root_sq.lo;
    const V4Dd product = v4_two_prod(kc_next, one_plus_n);
    const V4 e_q = (2.0 * root_n - product.hi) - product.lo;
    const V4 tail_h = e_h + tail;
    const V4 f_hi = 0.5 * one_plus_n, f_lo = 0.5 * tail_h;
    const V4Dd pr = v4_two_prod(mean.hi, f_hi), a = v4_two_prod(mean.hi, f_lo);
    const V4Dd b = v4_two_prod(mean.lo, f_hi);
    const V4Dd s1 = v4_two_sum(pr.lo, a.hi), s2 = v4_two_sum(s1.hi, b.hi);
    const V4 error = t->mean_error * f_hi + (((s1.lo + s2.lo) + (a.lo + b.lo)) + mean.lo * f_lo);
    const V4Dd next_mean = v4_fast_two_sum(pr.hi, s2.hi);
    const V4 next_tail = ((root_n * e_q + (e_s + tail)) - root_n * kc_next * tail_h) / (root_n * one_plus_n);
    if (v4_bits(active) == 0xF) {   /* every lane: no blends */
        t->mean_error = error;
        t->mean = next_mean;
        t->tail = next_tail;
        return;
    }
    t->mean_error = v4_pick(active, error, t->mean_error);
    t->mean.hi = v4_pick(active, next_mean.hi, mean.hi);
    t->mean.lo = v4_pick(active, next_mean.lo, mean.lo);
    t->tail = v4_pick(active, next_tail, tail);
}

/* landen_K from the tails at the bottom (k'_N = kc_bottom), and elliptic_param_finish's
 * bottom scale */
static inline void tails_finish_v4(const TailsV4 *t, V4 kc_bottom, V4 bottom_m, V4Dd *K_out, V4Dd *inv_K,
                                   V4 *bottom_scale)
{
    const V4Dd mean = t->mean;
    const V4 mean_error = t->mean_error;
    V4Dd A = v4_dd_div(v4_fast_two_sum(v4_all(HALF_PI_HI), v4_all(HALF_PI_LO)), mean);
    V4Dd B = v4_dd_mul(mean, v4_fast_two_sum(v4_all(2.0 * INV_PI_HI), v4_all(2.0 * INV_PI_LO)));
    A.lo -= A.hi * (A.hi * (mean_error * (2.0 * INV_PI_HI)));
    B.lo += mean_error * (2.0 * INV_PI_HI);
    const V4Dd d = v4_two_sum(1.0 - kc_bottom, -t->tail);
    V4Dd d2 = v4_two_prod(d.hi, d.hi);
    d2.lo += 2.0 * d.hi * d.lo;
    const V4 cube = d.hi * d2.hi;
    const V4Dd s2 = v4_two_prod(v4_all(0.3125), d2.hi);
    V4Dd S = v4_fast_two_sum(0.5 * d.hi, s2.hi);
    S.lo += (s2.lo + 0.3125 * d2.lo + 0.5 * d.lo) + cube * (7.0 / 32.0 + d.hi * (169.0 / 1024.0));
    V4Dd T = v4_fast_two_sum(0.5 * d.hi, 0.0625 * d2.hi);
    T.lo += (0.0625 * d2.lo + 0.5 * d.lo) + cube * (1.0 / 32.0 + d.hi * (21.0 / 1024.0));
    const V4Dd AS = v4_two_prod(A.hi, S.hi), BT = v4_two_prod(B.hi, T.hi);
    V4Dd K = v4_fast_two_sum(A.hi, AS.hi);
    K.lo += A.lo + (AS.lo + (A.hi * S.lo + A.lo * S.hi));
    V4Dd inverse = v4_fast_two_sum(B.hi, -BT.hi);
    inverse.lo += B.lo - (BT.lo + (B.hi * T.lo + B.lo * T.hi));
    *inv_K = v4_fast_two_sum(inverse.hi, inverse.lo);
    *K_out = v4_fast_two_sum(K.hi, K.lo);
    const V4Dd bottom_factor = {1.0 + bottom_m * (0.25 + bottom_m * (9.0 / 64.0)), v4_all(0.0)};
    const V4Dd K_bottom = v4_dd_mul(v4_fast_two_sum(v4_all(HALF_PI_HI), v4_all(HALF_PI_LO)), bottom_factor);
    *bottom_scale = v4_dd_mul(K_bottom, *inv_K).hi;
}

/* elliptic_param_begin and _finish on four lanes (m, kc, and k' = kc + kc_lo) in one pass: each
 * level's tail follows its
 * level of the chain, so that the two chains of quotients overlap (the same operations on each
 * lane, in another order). Writes the chain's levels to *c, K, 1/K and the bottom scale. */
ONCE_STAGE void chains_with_K_v4(V4 m, V4 kc, V4 kc_lo, ChainsV4 *c, V4Dd *K, V4Dd *inv_K, V4 *bottom_scale)
{
    V4 kc_n = kc, m_n = m, levels = v4_all(0.0);
    V4Mask going = V4_EVERY;
    TailsV4 t = tails_start_v4(kc_lo);
    int n = 0;
    for (;; ++n) {
        /* elliptic_param_begin's test: below the bottom, at least one level, at most 16 levels */
        const V4Mask goes = going & ((V4Mask)(m_n > BOTTOM_M) | (V4Mask)(v4_all((double)n) == 0.0))
                            & (V4Mask)(v4_all((double)n) < (double)ELLIPTIC_MAX_LEVELS);
        levels = v4_pick(going & ~goes, v4_all((double)n), levels);   /* ends here: N = n */
        going = goes;
        if (v4_bits(going) == 0) {
            break;
        }
        /* elliptic_param_begin's level on every lane, then elliptic_param_finish's */
        const V4 kc_level = kc_n;
        const V4 one_plus_kc = 1.0 + kc_n, half = 0.5 * one_plus_kc;
        const V4 root_kc = v4_sqrt(kc_n);
        const V4 kc_next = root_kc / half;
        const V4Mask small = (V4Mask)(kc_n < 0.5);   /* k_next by one quotient of either form */
        const V4 k_next = v4_pick(small, 1.0 - kc_n, m_n) / v4_pick(small, one_plus_kc, one_plus_kc * one_plus_kc);
        c->landen_k[n] = k_next;
        c->landen_1pk[n] = 1.0 + k_next;
        c->landen_1mk[n] = kc_n / half;
        kc_n = v4_pick(going, kc_next, kc_n);
        m_n = v4_pick(going, k_next * k_next, m_n);
        tails_level_v4(&t, going, kc_level, root_kc, one_plus_kc, kc_n);
    }
    c->most = n;
    c->levels = levels;
    c->bottom_m = m_n;
    tails_finish_v4(&t, kc_n, m_n, K, inv_K, bottom_scale);
}

/* --- elliptic_RF on four lanes (elliptic.c) ---------------------------------------------- */

/* elliptic_RF(x, y, z) for finite x, y, z >= 0 of which at most one is 0 (its duplication
 * and series): the duplication theorem (DLMF 19.26.18) until 4^-n spread0 < 0.004 A_n, each
 * lane stopping at its own step (a lane that has stopped keeps its A_n and 4^-n), then
 * DLMF 19.36.1's series in X = 1 - x_n / A_n, Y, Z. */
static inline V4 rf_v4(V4 x, V4 y, V4 z)
{
    const V4 x0 = x, y0 = y;
    const V4 mean0 = (x + y + z) / 3.0;
    const V4 spread0 = v4_max(v4_abs(mean0 - x), v4_max(v4_abs(mean0 - y), v4_abs(mean0 - z)));
    V4 mean = mean0, pow4 = v4_all(1.0);   /* pow4 = 4^-n */
    V4Mask going = V4_EVERY;
    for (int i = 0; i < 200; ++i) {
        going &= (V4Mask)(pow4 * spread0 >= 0.004 * mean);
        if (v4_bits(going) == 0) {
            break;
        }
        const V4 sx = v4_sqrt(x), sy = v4_sqrt(y), sz = v4_sqrt(z);
        const V4 lambda = sx * sy + sy * sz + sz * sx;
        x = 0.25 * (x + lambda);   /* read no more once its lane has stopped */
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        mean = v4_pick(going, 0.25 * (mean + lambda), mean);
        pow4 = v4_pick(going, pow4 * 0.25, pow4);
    }
    const V4 X = (mean0 - x0) * pow4 / mean;
    const V4 Y = (mean0 - y0) * pow4 / mean;
    const V4 Z = -(X + Y);
    const V4 E2 = X * Y - Z * Z;
    const V4 E3 = X * Y * Z;
    const V4 series = ELLIPTIC_RF_SERIES(E2, E3);
    return series / v4_sqrt(mean);
}

/* --- eval_any's libration on four lanes (exact.c) ---------------------------------------- */

/* elliptic_atan_series */
static inline V4 v4_atan_series(V4 s)
{
    ELLIPTIC_ATAN_SERIES_BODY(V4, s);
}

/* copysign(x, y) */
static inline V4 v4_copysign(V4 x, V4 y)
{
    const __m256d sign_bit = _mm256_set1_pd(-0.0);
    return (V4)_mm256_or_pd(_mm256_andnot_pd(sign_bit, (__m256d)x), _mm256_and_pd(sign_bit, (__m256d)y));
}

/* elliptic_atan_unit */
static inline V4 v4_atan_unit(V4 y, V4 x)
{
    const V4 a = v4_abs(y), b = x;
    const V4 w1 = v4_pick((V4Mask)(a > ELLIPTIC_TAN_PI_8 * b), v4_all(1.0), v4_all(0.0)), w0 = 1.0 - w1;
    const V4 t = (w0 * a + w1 * (a - b)) / (w0 * b + w1 * (a + b));
    const V4 s = t * t;
    const V4 g = v4_atan_series(s);
    const V4 angle = w1 * ELLIPTIC_QUARTER_PI_HI + (w1 * ELLIPTIC_QUARTER_PI_LO + (t + t * s * g));
    return v4_copysign(angle, y);
}

/* elliptic_atan_ratio: its three sectors by exact 0/1 weights, as the scalar code */
static inline V4 v4_atan_ratio(V4 y, V4 x)
{
    const V4 a = v4_abs(y), b = x;
    const V4 w3 = v4_pick((V4Mask)(a > ELLIPTIC_TAN_3PI_8 * b), v4_all(1.0), v4_all(0.0));
    const V4 w1 = v4_pick((V4Mask)(a > ELLIPTIC_TAN_PI_8 * b), v4_all(1.0), v4_all(0.0)) - w3;
    const V4 w0 = 1.0 - w1 - w3;
    const V4 num = w0 * a + w1 * (a - b) - w3 * b;
    const V4 den = w0 * b + w1 * (a + b) + w3 * a;
    const V4 base_hi = w1 * ELLIPTIC_QUARTER_PI_HI + w3 * (2.0 * ELLIPTIC_QUARTER_PI_HI);
    const V4 base_lo = w1 * ELLIPTIC_QUARTER_PI_LO + w3 * (2.0 * ELLIPTIC_QUARTER_PI_LO);
    const V4 t = num / den;
    const V4 s = t * t;
    const V4 g = v4_atan_series(s);
    return v4_copysign(base_hi + (base_lo + (t + t * s * g)), y);
}

/* trig_series and trig_sincos_small */
static inline void v4_sincos_small(V4 r, V4 *sin_r, V4 *cos_r)
{
    const double *c = TRIG_SIGNED_INVERSE_FACTORIAL;
    const V4 z = r * r;
    const V4 z2 = z * z, z4 = z2 * z2;
    const V4 ps = ((c[3] + z * c[5]) + z2 * (c[7] + z * c[9])) + z4 * ((c[11] + z * c[13]) + z2 * (c[15] + z * c[17]));
    const V4 pc = ((c[2] + z * c[4]) + z2 * (c[6] + z * c[8])) + z4 * ((c[10] + z * c[12]) + z2 * (c[14] + z * c[16]));
    *sin_r = r + (r * z) * ps;
    *cos_r = 1.0 + z * pc;
}

/* elliptic_landen_step with each lane's level factors, where `step` is set: the plain step,
 * then for a chain of more than ELLIPTIC_LEVELS_WITHOUT_RESCALE levels (`long_chain`) the
 * renormalisation once D passes ELLIPTIC_HOMOGENEOUS_RESCALE */
static inline void v4_landen_step(V4Mask step, V4Mask long_chain, V4 kk, V4 one_plus_k, V4 one_minus_k, V4 *S,
                                  V4 *C, V4 *E, V4 *D)
{
    const V4 d2 = *D * *D;
    V4 up_S = one_plus_k * *S * *D, up_C = *C * *E;
    V4 up_E = one_minus_k * d2 + kk * *C * *C, up_D = d2 + kk * *S * *S;
    const V4Mask rescale = long_chain & (V4Mask)(up_D > ELLIPTIC_HOMOGENEOUS_RESCALE);
    if (v4_bits(rescale) != 0) {   /* only chains of more than 7 levels */
        const V4 inv = 1.0 / up_D;
        up_S = v4_pick(rescale, up_S * inv, up_S);
        up_C = v4_pick(rescale, up_C * inv, up_C);
        up_E = v4_pick(rescale, up_E * inv, up_E);
        up_D = v4_pick(rescale, v4_all(1.0), up_D);
    }
    if (v4_bits(step) != 0xF) {   /* a lane whose chain has no such level keeps its values */
        up_S = v4_pick(step, up_S, *S);
        up_C = v4_pick(step, up_C, *C);
        up_E = v4_pick(step, up_E, *E);
        up_D = v4_pick(step, up_D, *D);
    }
    *S = up_S;
    *C = up_C;
    *E = up_E;
    *D = up_D;
}

/* What the evaluation reads of four librations or rotations, lane by lane; the level factors
 * level by level (a lane's own up to its levels, any finite values beyond). */
typedef struct {
    V4 t0, rho_hi, rho_lo, x0_hi, x0_lo, K_hi, bottom_scale, bottom_m, sqrt_k1, kc, omega_half;
    V4 theta_turns;   /* whole turns of theta0, |theta_turns| < 2^50 */
    V4Mask rotation;  /* the lanes of a rotation (the others librate) */
    V4 direction;     /* a rotation's sign of omega0 */
    V4 levels;   /* N as doubles */
    int most;    /* the largest N */
    const V4 *landen_k, *landen_1pk, *landen_1mk;   /* [level] */
} MotionV4;

/* Homogeneous coordinates of sn, cn, dn on four lanes (EllipticHomogeneous) */
typedef struct {
    V4 S, C, E, D;
} HomogeneousV4;

/* add_half_turns(half_turns, angle): half_turns_pi and plus_half_turns, the angle alone
 * where the half turns are 0 */
static inline V4 v4_add_half_turns(V4Dd half_turns, V4 angle)
{
    const V4Dd turn = v4_two_prod(half_turns.hi, v4_all(PI_HI));
    const V4 hi_pi_lo = half_turns.hi * PI_LO, lo_pi_hi = half_turns.lo * PI_HI;
    const V4 wound = turn.hi + (turn.lo + (hi_pi_lo + (lo_pi_hi + angle)));
    return v4_pick((V4Mask)(half_turns.hi == 0.0) & (V4Mask)(half_turns.lo == 0.0), angle, wound);
}

/* libration_angle_omega from levels 1 (h1) and 0 (h0), the quarter's weights odd and sign,
 * and add_half_turns(2 theta_turns, angle) */
ONCE_STAGE void libration_outputs_v4(const MotionV4 *s, V4 odd, V4 sign, HomogeneousV4 h1, HomogeneousV4 h0,
                                     V4 *theta, V4 *omega)
{
    const V4 even = 1.0 - odd;
    const V4 y1 = even * h1.S + odd * h1.C, x1 = even * h1.D + odd * h1.E;
    const V4 angle = 4.0 * v4_atan_unit(sign * s->sqrt_k1 * y1, x1);
    *theta = v4_add_half_turns((V4Dd){2.0 * s->theta_turns, v4_all(0.0)}, angle);
    const V4 cn_num = even * h0.C - odd * (s->kc * h0.S), den = even * h0.D + odd * h0.E;
    *omega = 2.0 * (sign * s->omega_half * (cn_num / den));
}

/* eval_any's rotation from level 0 (h0) and the quarter n (odd: its weight): am(nK + r) -
 * n pi/2 = atan(sn r / cn r) (n even), atan(k' sn r / cn r) (n odd); theta = 2 pi j +
 * direction (n pi + 2 delta), omega = 2 sqrt(m) w0 dn(nK + r), the winding direction n added
 * to the half turns 2 j in double-double */
ONCE_STAGE void rotation_outputs_v4(const MotionV4 *s, V4 quarters, V4 odd, HomogeneousV4 h0, V4 *theta,
                                    V4 *omega)
{
    const V4 even = 1.0 - odd;
    const V4 delta = v4_atan_ratio((even + odd * s->kc) * h0.S, h0.C);
    const V4 dn_num = even * h0.E + odd * (s->kc * h0.D), den = even * h0.D + odd * h0.E;
    const V4Mask backwards = (V4Mask)(s->direction < 0.0);
    const V4Dd winding = {v4_pick(backwards, -quarters, quarters), v4_pick(backwards, v4_all(-0.0), v4_all(0.0))};
    const V4 angle = 2.0 * s->direction * delta;
    *omega = 2.0 * (s->direction * s->omega_half * (dn_num / den));
    *theta = v4_add_half_turns(v4_dd_add((V4Dd){2.0 * s->theta_turns, v4_all(0.0)}, winding), angle);
}

/* eval_any's operations for a libration or rotation at times tv: *theta and *omega for every
 * lane, and a mask of the lanes on the common path (a phase below 2^50 quarter periods, a
 * bottom argument within the series, tv != t0; the caller checks the rest). The phase's
 * nearest integer by the shift where the fma build's phase_near rounds with rint: they differ
 * only in the sign of a zero, which no output reads (nor the half turns, a sum with it). The
 * Landen levels are the same for both motions (elliptic_sncndn_homogeneous_pair's, and
 * elliptic_sncndn_homogeneous's level 0); the outputs of each are formed where a lane has it
 * (rotating: the bits of s->rotation, 0 where the caller knows there is no rotation). */
ONCE_STAGE V4Mask eval_motion_v4(const MotionV4 *s, int rotating, V4 tv, V4 *theta, V4 *omega)
{
    /* phase_at and phase_near */
    const V4Dd tau = v4_two_sum(tv, -s->t0);
    const V4 x_hi = s->rho_hi * tau.hi;
    const V4 x_lo = (V4)_mm256_fmadd_pd((__m256d)s->rho_hi, (__m256d)tau.hi, (__m256d)(-x_hi));
    const V4 quarters = (x_hi + s->x0_hi + 0x1.8p52) - 0x1.8p52;
    const V4 f = ((x_hi - quarters) + s->x0_hi) + (x_lo + (s->rho_hi * tau.lo + s->rho_lo * tau.hi) + s->x0_lo);
    const V4 v = f * s->K_hi;
    /* the quarter n mod 4 as eval_libration_lanes' exact weights */
    const V4 r = quarters - 4.0 * ((0.25 * quarters + 0x1.8p52) - 0x1.8p52);
    const V4 r2 = r * r;
    const V4 odd = r2 * (4.0 - r2) / 3.0;
    const V4 sign = 1.0 - 2.0 * (r2 * (r2 - 1.0) / 12.0 + odd * (1.0 - r) * 0.5);
    const V4 z = v4_abs(v) * s->bottom_scale;
    /* elliptic_landen_bottom, then the steps up to level 1 */
    V4 sz, cz;
    v4_sincos_small(z, &sz, &cz);
    const V4 w = 0.25 * s->bottom_m * (z - sz * cz);
    V4 S = sz - w * cz, C = cz + w * sz, E = 1.0 - 0.5 * s->bottom_m * sz * sz, D = v4_all(1.0);
    const V4Mask long_chain = (V4Mask)(s->levels > (double)ELLIPTIC_LEVELS_WITHOUT_RESCALE);
    for (int i = s->most - 1; i >= 1; --i) {
        const V4Mask below = (V4Mask)(v4_all((double)i) < s->levels);   /* a step of this lane's chain */
        v4_landen_step(below, long_chain, s->landen_k[i], s->landen_1pk[i], s->landen_1mk[i], &S, &C, &E, &D);
    }
    V4 S0 = S, C0 = C, E0 = E, D0 = D;
    v4_landen_step(V4_EVERY, long_chain, s->landen_k[0], s->landen_1pk[0], s->landen_1mk[0], &S0, &C0,
                   &E0, &D0);
    const V4Mask negative = (V4Mask)(v < 0.0);   /* sn is odd, cn and dn are even */
    const HomogeneousV4 h1 = {v4_pick(negative, -S, S), C, E, D}, h0 = {v4_pick(negative, -S0, S0), C0, E0, D0};
    V4 lib_theta = v4_all(0.0), lib_omega = lib_theta, rot_theta = lib_theta, rot_omega = lib_theta;
    if (rotating != 0xF) {
        libration_outputs_v4(s, odd, sign, h1, h0, &lib_theta, &lib_omega);
    }
    if (rotating != 0) {
        rotation_outputs_v4(s, quarters, odd, h0, &rot_theta, &rot_omega);
    }
    *theta = v4_pick(s->rotation, rot_theta, lib_theta);
    *omega = v4_pick(s->rotation, rot_omega, lib_omega);
    return (V4Mask)(v4_abs(x_hi) < 0x1p50) & (V4Mask)(z <= ELLIPTIC_SERIES_Z_MAX) & (V4Mask)(tv != s->t0);
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
    V4 th, om, w0_hi, w0_lo, tv;
} OnceInputsV4;

ONCE_STAGE OnceInputsV4 once_inputs_v4(int lanes, const double *theta0, const double *omega0,
                                       const DoubleDouble *w0, const double *t)
{
    V4 th, om, w0_hi, w0_lo, tv;
    for (int l = 0; l < AVX_LANES; ++l) {
        const int from = l < lanes ? l : 0;
        th[l] = theta0[from];
        om[l] = omega0 != NULL ? omega0[from] : 0.0;
        w0_hi[l] = w0[from].hi;
        w0_lo[l] = w0[from].lo;
        tv[l] = t[from];
    }
    const OnceInputsV4 in = {th, om, w0_hi, w0_lo, tv};
    return in;
}

/* v on the lanes taken, lane `any`'s value (a lane taken) on the others: a lane not taken
 * runs a copy, so that no loop of the set-up runs longer for it */
ONCE_STAGE V4 copy_taken(V4 v, V4Mask taken, int any)
{
    return v4_pick(taken, v, v4_all(v[any]));
}

/* set_libration_scales's fields (k, k' = kc, K from the chain, w0) and t0; the rates, the
 * initial phase and the turns are the caller's */
ONCE_STAGE void libration_scales_v4(MotionV4 *s, const ChainsV4 *c, V4 k, V4 kc, V4 w0_hi, V4 K_hi, double t0)
{
    s->t0 = v4_all(t0);
    s->K_hi = K_hi;
    s->bottom_m = c->bottom_m;
    s->sqrt_k1 = k / (1.0 + kc);
    s->kc = kc;
    s->omega_half = k * w0_hi;
    s->rotation = (V4Mask){0, 0, 0, 0};
    s->direction = v4_all(1.0);
    s->levels = c->levels;
    s->most = c->most;
    s->landen_k = c->landen_k;
    s->landen_1pk = c->landen_1pk;
    s->landen_1mk = c->landen_1mk;
}

/* The librations and rotations s evaluated at tv (rotating: as eval_motion_v4's); writes the
 * lanes taken that are on the evaluation's common path and returns them as bits */
ONCE_STAGE int eval_taken_v4(const MotionV4 *s, int rotating, V4 tv, int lanes, V4Mask taken, double *theta,
                              double *omega)
{
    V4 angle, om;
    const V4Mask path = eval_motion_v4(s, rotating, tv, &angle, &om);
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

/* Up to four releases from rest (omega0 = 0, |theta0| <= 3.2, w0 accepted) set up at t0 and
 * evaluated once each at t[l], all in vectors: init_from_rest's operations (the cosine begun,
 * the chain, the cosine ended, K, the rates) and the evaluation's, without a set-up written.
 * Returns the lanes done as bits; the others (a cosine whose leading double is not certain or
 * within 2^-500 of 0, off the evaluation's common path) are the caller's. */
ONCE_STAGE int once_avx(int lanes, const double *theta0, const DoubleDouble *w0, double t0, const double *t,
                        double *theta, double *omega)
{
    const OnceInputsV4 in = once_inputs_v4(lanes, theta0, NULL, w0, t);
    CosSinV4 trig;
    cos_sin_begin_v4(0.5 * in.th, &trig);   /* step 1: theta0 / 2 exact, no turn to subtract */
    V4Mask taken;
    int any = -1;
    for (int l = 0; l < AVX_LANES; ++l) {
        taken[l] = -(l < lanes && trig.certain[l] && fabs(trig.cos_lead[l]) > 0x1p-500);
        any = taken[l] && any < 0 ? l : any;
    }
    if (any < 0) {
        return 0;
    }
    /* from_rest_start: m = k^2 (at most 1), k' = c's leading double */
    const V4 k = v4_abs(trig.sin_x), k2 = k * k;
    V4 m = v4_pick((V4Mask)(k2 < 1.0), k2, v4_all(1.0)), kc = v4_abs(trig.cos_lead);
    m = copy_taken(m, taken, any);
    kc = copy_taken(kc, taken, any);
    /* settle_initial_angle: c < 0 (theta0 just past pi) moves th by a turn, s and c change sign */
    const V4Mask past = (V4Mask)(trig.cos_lead < 0.0);
    const V4Dd cosine = cos_sin_end_v4(&trig);
    const V4Dd c = v4_pick_dd(past, v4_dd_neg(cosine), cosine);
    const V4 s_hi = v4_pick(past, -trig.sin_x, trig.sin_x);
    /* the chain on c's leading double, K and 1/K from its tails with c's low part */
    ChainsV4 chains;
    V4Dd K, inv_K;
    MotionV4 s;
    chains_with_K_v4(m, kc, c.lo, &chains, &K, &inv_K, &s.bottom_scale);
    /* from_rest_fields: rho = w0 / K, u0 = +-K (0 at the bottom), x0 = +-1 */
    libration_scales_v4(&s, &chains, k, kc, in.w0_hi, K.hi, t0);
    const V4Dd rho = v4_dd_mul((V4Dd){in.w0_hi, in.w0_lo}, inv_K);
    const V4 u0 = v4_pick((V4Mask)(k == 0.0), v4_all(0.0), v4_pick((V4Mask)(s_hi < 0.0), -K.hi, K.hi));
    s.theta_turns = v4_pick(past, v4_pick((V4Mask)(in.th > 0.0), v4_all(1.0), v4_all(-1.0)), v4_all(0.0));
    s.rho_hi = rho.hi;
    s.rho_lo = rho.lo;
    s.x0_hi = v4_pick((V4Mask)(u0 < 0.0), v4_all(-1.0), v4_pick((V4Mask)(u0 > 0.0), v4_all(1.0), v4_all(0.0)));
    s.x0_lo = v4_all(0.0);
    const int done = eval_taken_v4(&s, 0, in.tv, lanes, taken, theta, omega);
    ONCE_AVX_TALLY(rest, done);
    return done;
}

/* A moving start's parameter on four lanes, libration_parameter's or rotation_parameter's
 * (the fine window left out), and what the initial phase needs of it */
typedef struct {
    V4 m;            /* the parameter of the Jacobi functions (mu = 1/m for a rotation) */
    V4Dd m1;         /* its complement */
    V4 rf_x, rf_y;   /* the first two arguments of R_F for F(phi0) (the third is 1) */
    V4 factor;       /* F(phi0) = factor R_F: |s|/k (libration), direction s (rotation) */
    V4Mask ok;       /* the parameter accepted (elliptic_param_acceptable), R_F's x or y > 0 */
} ParameterV4;

/* elliptic_param_acceptable on four lanes (isfinite(x) as |x| <= DBL_MAX) */
static inline V4Mask acceptable_v4(V4 m, V4Dd m1)
{
    return (V4Mask)(m >= 0.0) & (V4Mask)(m <= 1.0) & (V4Mask)(m1.hi >= 0.0) & (V4Mask)(m1.hi <= 1.0)
           & (V4Mask)(v4_abs(m1.lo) <= DBL_MAX) & (V4Mask)(v4_abs(m + m1.hi - 1.0) <= 1e-12);
}

/* libration_parameter for gap > 0: q = hs_n / w_n, m1 = (gap / w_n)(c + q), k = hypot(s, q)
 * (glibc's, lane by lane), m = min(k^2, 1); init_libration's F(|phi0| | m) = (|s|/k)
 * R_F((q/k)^2, c^2, 1) (DLMF 19.25.5, scaled) */
ONCE_STAGE ParameterV4 libration_parameter_v4(V4Dd c, V4 s_hi, V4Dd w_n, V4 hs_n, V4Dd gap, V4 *k_out)
{
    ParameterV4 p;
    const V4Dd q = v4_dd_div((V4Dd){hs_n, v4_all(0.0)}, w_n);
    p.m1 = v4_dd_mul(v4_dd_div(gap, w_n), v4_dd_add(c, q));
    V4 k;
    for (int l = 0; l < AVX_LANES; ++l) {
        k[l] = hypot(s_hi[l], q.hi[l]);
    }
    const V4 k2 = k * k;
    p.m = v4_pick((V4Mask)(k2 < 1.0), k2, v4_all(1.0));
    const V4 q_k = q.hi / k;
    p.rf_x = q_k * q_k;
    p.rf_y = c.hi * c.hi;
    p.factor = v4_abs(s_hi) / k;
    p.ok = (V4Mask)(gap.hi > 0.0) & (V4Mask)(p.m1.hi > 0.0) & acceptable_v4(p.m, p.m1) & (V4Mask)(k != 0.0)
           & (V4Mask)(p.rf_y > 0.0);
    *k_out = k;
    return p;
}

/* subtract_turns(x, j): x - j (2 pi), 2 pi in three parts, the two leading products exact */
static inline V4Dd v4_subtract_turns(V4Dd x, V4 j)
{
    x = v4_dd_add(x, v4_dd_neg(v4_two_prod(j, v4_all(2.0 * PI_HI))));
    x = v4_dd_add(x, v4_dd_neg(v4_two_prod(j, v4_all(2.0 * PI_LO))));
    return v4_dd_add(x, (V4Dd){-j * 2.0 * PI_LOLO, v4_all(0.0)});
}

/* rotation_parameter for gap < 0 outside the fine window: s = sin(th/2) in double-double
 * (dd_sin; th moved by a turn where `past`, finish_initial_angle), rho = s w_n / hs_n,
 * 1 + rho^2, mu1 = (1 - gamma)(1 + gamma)/(1 + rho^2) with 1 - gamma = -gap / hs_n and
 * gamma = c w_n / hs_n, mu = min((w_n / hs_n)^2 / (1 + rho^2), 1); init_rotation's
 * v0 = F(th/2 | mu) = direction s R_F(c^2, 1/(1 + rho^2), 1) (DLMF 19.25.5) */
ONCE_STAGE ParameterV4 rotation_parameter_v4(const CosSinV4 *trig, V4 th, V4Mask past, V4Dd c, V4Dd c_w, V4Dd w_n,
                                             V4 hs_n, V4Dd gap, V4 direction, V4Dd *one_plus_rho2)
{
    ParameterV4 p;
    V4Dd s;
    if (v4_bits(past) == 0) {   /* th/2 = theta0/2: dd_cos_sin_begin's reduction and table point */
        s = sin_at_point_v4(&trig->point, trig->n);
    } else {
        const V4 shift = v4_pick((V4Mask)(th > 0.0), v4_all(1.0), v4_all(-1.0));
        const V4Dd moved = v4_pick_dd(past, v4_subtract_turns((V4Dd){th, v4_all(0.0)}, shift),
                                      (V4Dd){th, v4_all(0.0)});
        s = dd_sin_v4((V4Dd){0.5 * moved.hi, 0.5 * moved.lo});
    }
    const V4Dd hs = {hs_n, v4_all(0.0)};
    const V4Dd rho = v4_dd_div(v4_dd_mul(s, w_n), hs);
    const V4Dd opr2 = v4_dd_add((V4Dd){v4_all(1.0), v4_all(0.0)}, v4_dd_mul(rho, rho));
    const V4Dd one_minus_gamma = v4_dd_div(v4_dd_neg(gap), hs), gamma = v4_dd_div(c_w, hs);
    p.m1 = v4_dd_div(v4_dd_mul(one_minus_gamma, v4_dd_add((V4Dd){v4_all(1.0), v4_all(0.0)}, gamma)), opr2);
    const V4 w_hs = w_n.hi / hs_n, mu = w_hs * w_hs / opr2.hi;
    p.m = v4_pick((V4Mask)(mu < 1.0), mu, v4_all(1.0));
    p.rf_x = c.hi * c.hi;
    p.rf_y = 1.0 / opr2.hi;
    p.factor = direction * s.hi;
    p.ok = (V4Mask)(gap.hi < 0.0) & acceptable_v4(p.m, p.m1) & (V4Mask)(p.rf_x > 0.0);
    *one_plus_rho2 = opr2;
    return p;
}

static inline ParameterV4 pick_parameter(V4Mask where, ParameterV4 yes, ParameterV4 no)
{
    ParameterV4 p;
    p.m = v4_pick(where, yes.m, no.m);
    p.m1 = v4_pick_dd(where, yes.m1, no.m1);
    p.rf_x = v4_pick(where, yes.rf_x, no.rf_x);
    p.rf_y = v4_pick(where, yes.rf_y, no.rf_y);
    p.factor = v4_pick(where, yes.factor, no.factor);
    p.ok = (where & yes.ok) | (~where & no.ok);
    return p;
}

/* Up to four moving starts (omega0 != 0, |theta0| <= 3.2, w0 accepted) set up at t0 and
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
    const OnceInputsV4 in = once_inputs_v4(lanes, theta0, omega0, w0, t);
    CosSinV4 trig;
    cos_sin_begin_v4(0.5 * in.th, &trig);   /* step 1: theta0 / 2 exact, no turn to subtract */
    /* finish_initial_angle: c < 0 moves th by a turn, s and c change sign (its c = -0 with
     * th < 0 is taken by neither kind: gap = -hs_n, c^2 = 0) */
    const V4Dd cosine = cos_sin_end_v4(&trig);
    const V4Mask past = (V4Mask)(cosine.hi < 0.0);
    const V4Dd c = v4_pick_dd(past, v4_dd_neg(cosine), cosine);
    const V4 s_hi = v4_pick(past, -trig.sin_x, trig.sin_x);
    /* locate_separatrix: w_n = w0 2^-e, hs_n = (|omega0|/2) 2^-e for e the exponent of the
     * larger; gap = c w_n - hs_n, the sign of m1 */
    const V4 half_speed = 0.5 * v4_abs(in.om);
    V4 down, up;
    for (int l = 0; l < AVX_LANES; ++l) {
        const int e = dd_frexp_exponent(larger(in.w0_hi[l], half_speed[l]));
        const int in_range = l < lanes && e >= -1000 && e <= 1000;   /* dd_scalbn's 2^-e and 2^e */
        down[l] = in_range ? dd_scalbn(1.0, -e) : 0.0;   /* 0: a lane left to the caller */
        up[l] = in_range ? dd_scalbn(1.0, e) : 1.0;
    }
    const V4Mask in_range = (V4Mask)(down != 0.0);
    const V4Dd w_n = {in.w0_hi * down, in.w0_lo * down};
    const V4 hs_n = half_speed * down;
    const V4Dd c_w = v4_dd_mul(c, w_n);
    const V4Dd gap = v4_dd_add(c_w, (V4Dd){-hs_n, v4_all(-0.0)});   /* dd_sub */
    const V4Mask outside = in_range & ~(V4Mask)(v4_abs(gap.hi) < 0x1p-30 * hs_n);   /* the fine window */
    const V4Mask rotation = outside & (V4Mask)(gap.hi < 0.0);
    *rotating_lanes = v4_bits(rotation);
    const int rotating = rotations_too ? *rotating_lanes : 0, librating = v4_bits(outside & (V4Mask)(gap.hi > 0.0));
    if ((rotating == 0 && librating == 0) || rotating != *rotating_lanes) {
        return 0;
    }
    /* each kind's parameter where a lane has it */
    const V4 direction = v4_pick((V4Mask)(in.om > 0.0), v4_all(1.0), v4_all(-1.0));
    ParameterV4 par;
    V4 k = v4_all(0.0);
    V4Dd one_plus_rho2 = {v4_all(1.0), v4_all(0.0)};
    if (!rotations_too || librating != 0) {
        par = libration_parameter_v4(c, s_hi, w_n, hs_n, gap, &k);
    }
    if (rotating != 0) {
        const ParameterV4 rot = rotation_parameter_v4(&trig, in.th, past, c, c_w, w_n, hs_n, gap, direction,
                                                      &one_plus_rho2);
        par = librating != 0 ? pick_parameter(rotation, rot, par) : rot;
    }
    /* elliptic_param_init_root: m1 = TwoSum(m1), k' = sqrt(m1) */
    V4Dd m1_sum = v4_two_sum(par.m1.hi, par.m1.lo);
    const V4Mask taken = outside & par.ok & (V4Mask)(m1_sum.hi >= 0x1p-900);
    const int taken_bits = v4_bits(taken);
    if (taken_bits == 0) {
        return 0;
    }
    V4 m = par.m, rf_x = par.rf_x, rf_y = par.rf_y;
    if (taken_bits != 0xF) {   /* a branch, not a wait on the masks, where every lane is taken */
        const int any = __builtin_ctz((unsigned)taken_bits);
        m = copy_taken(m, taken, any);
        rf_x = copy_taken(rf_x, taken, any);
        rf_y = copy_taken(rf_y, taken, any);
        m1_sum.hi = copy_taken(m1_sum.hi, taken, any);
        m1_sum.lo = copy_taken(m1_sum.lo, taken, any);
    }
    /* F first: its roots wait on nothing of the chain, whose roots then follow them */
    const V4 f = par.factor * rf_v4(rf_x, rf_y, v4_all(1.0));
    const V4Dd kc = v4_dd_sqrt(m1_sum);
    ChainsV4 chains;
    V4Dd K, inv_K;
    MotionV4 s;
    chains_with_K_v4(m, kc.hi, kc.lo, &chains, &K, &inv_K, &s.bottom_scale);
    libration_scales_v4(&s, &chains, k, kc.hi, in.w0_hi, K.hi, t0);
    /* a libration's u0 = F, or 2K - F for omega0 < 0 (F(pi - phi) = 2K - F(phi)), with the
     * sign of s, and its rate w_n; a rotation's u0 = v0 and rate (|omega0|/2) sqrt(1 + rho^2) */
    const V4 base = v4_pick((V4Mask)(in.om >= 0.0), f, (2.0 * K.hi - f) + 2.0 * K.lo);
    V4 u0 = v4_pick((V4Mask)(s_hi < 0.0), -base, base);
    V4Dd rate_n = w_n;
    if (rotating != 0) {
        const V4Dd rotation_rate = v4_dd_mul((V4Dd){hs_n, v4_all(0.0)}, v4_dd_sqrt(one_plus_rho2));
        u0 = v4_pick(rotation, f, u0);
        rate_n = v4_pick_dd(rotation, rotation_rate, w_n);
        s.rotation = rotation;
        s.direction = direction;
        s.omega_half = v4_pick(rotation, rotation_rate.hi * up, s.omega_half);   /* dd_ldexp(rate, e).hi */
    }
    /* set_quarter_rates: rho = (rate_n / K) 2^e, x0 = u0 / K */
    const V4Dd rho = v4_dd_mul(rate_n, inv_K), x0 = v4_dd_mul((V4Dd){u0, v4_all(0.0)}, inv_K);
    s.rho_hi = rho.hi * up;
    s.rho_lo = rho.lo * up;
    s.x0_hi = x0.hi;
    s.x0_lo = x0.lo;
    s.theta_turns = v4_pick(past, v4_pick((V4Mask)(in.th > 0.0), v4_all(1.0), v4_all(-1.0)), v4_all(0.0));
    const int done = eval_taken_v4(&s, rotating, in.tv, lanes, taken, theta, omega);
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
