/* elliptic_avx.h: the Landen chain, K and 1/K of four parameters to an AVX vector, for the fma
 * build's batched new states (exact.c: pendulum_exact_once_gl_many; exact_fma.c: GCC on
 * x86-64, AVX and FMA enabled by its target pragma), included by elliptic.c there alone.
 *
 * Each lane runs the operations of elliptic_param_begin and _finish (a level of the chain, a
 * level of the tails with mean_times, landen_K, the bottom scale) in their order on GCC's
 * vector of doubles (dd_avx.h: +, -, *, / elementwise, each IEEE-rounded as the scalar
 * operation, the fma's two-product, the correctly rounded vector square root): the same bits
 * as the scalar code. Where the scalar code
 * branches, a lane computes both sides and keeps its own; a lane whose chain has ended is
 * carried along with its values frozen. test_exact_batch compares every output. */
#ifndef PENDULUM_ELLIPTIC_AVX_H
#define PENDULUM_ELLIPTIC_AVX_H

#include "dd_avx.h"

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

/* elliptic_param_begin and _finish on four lanes (m, kc, and k' = kc + kc_lo; the lanes from
 * `lanes` on are carried frozen at their start) in one pass: each level's tail follows its
 * level of the chain, so that the two chains of quotients overlap (the same operations on each
 * lane, in another order). Writes the chain's levels to *c, K, 1/K and the bottom scale. */
static inline void chains_with_K_v4(int lanes, V4 m, V4 kc, V4 kc_lo, ChainsV4 *c, V4Dd *K, V4Dd *inv_K,
                                    V4 *bottom_scale)
{
    V4 kc_n = kc, m_n = m, levels = v4_all(0.0);
    V4Mask going;
    for (int l = 0; l < AVX_LANES; ++l) {
        going[l] = l < lanes ? -1 : 0;
    }
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
        const V4 root_kc = (V4)_mm256_sqrt_pd((__m256d)kc_n);
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

#endif
