/* elliptic_avx.h: elliptic_param_begin_many and _finish_many four lanes to a vector, for the fma
 * build (exact_fma.c: GCC on x86-64, AVX and FMA enabled by its target pragma), included by
 * elliptic.c there alone.
 *
 * Each lane runs the operations of chain_level, tail_level and finish_K in their order, on
 * GCC's vector type of four doubles (+, -, *, / elementwise, each IEEE-rounded as the scalar
 * operation), with the fma's two-product (fma(a, b, -p), exact: the same e) and the
 * correctly rounded vector square root: the same bits as the scalar code. Where the scalar
 * code branches, a lane computes both sides and keeps its own (blend); a lane whose chain has
 * ended is carried along with its values frozen. test_exact_setup compares every byte. */
#ifndef PENDULUM_ELLIPTIC_AVX_H
#define PENDULUM_ELLIPTIC_AVX_H

#include "dd_avx.h"

/* elliptic_param_begin for lanes <= 4 parameter sets (p[l], m[l], kc[l]), their chains in
 * chains' lanes first .. first + 3 (first + 4 <= ELLIPTIC_LANES); unused lanes compute lane
 * 0's chain frozen at its start and write no parameter set. */
static void chains_begin_avx(int lanes, EllipticParam *const *p, const double *m, const double *kc,
                             EllipticChains *chains, int first)
{
    V4 kc_n, m_n;
    int level[AVX_LANES];   /* N of each lane once its chain has ended, else -1 */
    for (int l = 0; l < AVX_LANES; ++l) {
        const int from = l < lanes ? l : 0;
        kc_n[l] = kc[from];
        m_n[l] = m[from];
        level[l] = l < lanes ? -1 : 0;
    }
    for (int l = 0; l < lanes; ++l) {
        chain_start(p[l], m[l], kc[l]);
    }
    int left = lanes;
    for (int n = 0; left > 0; ++n) {
        v4_store(&chains->kc[n][first], kc_n);   /* a lane's bottom k' (frozen past it) */
        V4Mask going;
        for (int l = 0; l < AVX_LANES; ++l) {
            if (level[l] < 0 && !chain_goes_on(n, m_n[l])) {
                level[l] = n;
                chain_end(p[l], n, m_n[l]);
                --left;
            }
            going[l] = level[l] < 0 ? -1 : 0;
        }
        if (left == 0) {
            break;
        }
        /* chain_level on every lane */
        const V4 one_plus_kc = 1.0 + kc_n, half = 0.5 * one_plus_kc;
        const V4 root_kc = (V4)_mm256_sqrt_pd((__m256d)kc_n);
        const V4 kc_next = root_kc / half;
        const V4 k_next = v4_pick((V4Mask)(kc_n < 0.5), (1.0 - kc_n) / one_plus_kc, m_n / (one_plus_kc * one_plus_kc));
        const V4 one_plus_k = 1.0 + k_next, one_minus_k = kc_n / half;
        v4_store(&chains->root[n][first], root_kc);
        v4_store(&chains->one_plus[n][first], one_plus_kc);
        for (int l = 0; l < lanes; ++l) {
            if (going[l]) {
                p[l]->landen_k[n] = k_next[l];
                p[l]->landen_1pk[n] = one_plus_k[l];
                p[l]->landen_1mk[n] = one_minus_k[l];
            }
        }
        kc_n = v4_pick(going, kc_next, kc_n);
        m_n = v4_pick(going, k_next * k_next, m_n);
    }
}

/* elliptic_param_finish for the lanes of chains_begin_avx: tail_level over every lane's
 * levels (a lane past its bottom keeps its values), then landen_K and finish_K. */
static void chains_finish_avx(int lanes, EllipticParam *const *p, const EllipticChains *chains, int first,
                              const double *m1, const double *kc_lo, DoubleDouble *inv_K)
{
    V4 tail, levels, kc_bottom, bottom_m;
    int most = 0;
    for (int l = 0; l < AVX_LANES; ++l) {
        const int from = l < lanes ? l : 0, n = p[from]->levels;
        tail[l] = kc_lo[from];
        levels[l] = (double)n;
        kc_bottom[l] = chains->kc[n][first + from];
        bottom_m[l] = p[from]->bottom_m;
        most = n > most ? n : most;
    }
    for (int l = 0; l < lanes; ++l) {
        p[l]->m1 = m1[l];
    }
    V4Dd mean = {v4_all(1.0), v4_all(0.0)};
    V4 mean_error = v4_all(0.0);
    for (int n = 0; n < most; ++n) {
        /* tail_level, and mean_times(&mean, &mean_error, one_plus / 2, tail_h / 2) */
        const V4Mask active = (V4Mask)(v4_all((double)n) < levels);
        const V4 kc_n = v4_load(&chains->kc[n][first]), root = v4_load(&chains->root[n][first]);
        const V4 one_plus = v4_load(&chains->one_plus[n][first]), kc_next = v4_load(&chains->kc[n + 1][first]);
        const V4 e_h = kc_n - (one_plus - 1.0);
        const V4Dd root_sq = v4_two_prod(root, root);
        const V4 e_s = (kc_n - root_sq.hi) - root_sq.lo;
        const V4Dd product = v4_two_prod(kc_next, one_plus);
        const V4 e_q = (2.0 * root - product.hi) - product.lo;
        const V4 tail_h = e_h + tail;
        const V4 f_hi = 0.5 * one_plus, f_lo = 0.5 * tail_h;
        const V4Dd pr = v4_two_prod(mean.hi, f_hi), a = v4_two_prod(mean.hi, f_lo);
        const V4Dd b = v4_two_prod(mean.lo, f_hi);
        const V4Dd s1 = v4_two_sum(pr.lo, a.hi), s2 = v4_two_sum(s1.hi, b.hi);
        const V4 error = mean_error * f_hi + (((s1.lo + s2.lo) + (a.lo + b.lo)) + mean.lo * f_lo);
        const V4Dd next_mean = v4_fast_two_sum(pr.hi, s2.hi);
        const V4 next_tail = ((root * e_q + (e_s + tail)) - root * kc_next * tail_h) / (root * one_plus);
        mean_error = v4_pick(active, error, mean_error);
        mean.hi = v4_pick(active, next_mean.hi, mean.hi);
        mean.lo = v4_pick(active, next_mean.lo, mean.lo);
        tail = v4_pick(active, next_tail, tail);
    }
    /* landen_K */
    V4Dd A = v4_dd_div(v4_fast_two_sum(v4_all(HALF_PI_HI), v4_all(HALF_PI_LO)), mean);
    V4Dd B = v4_dd_mul(mean, v4_fast_two_sum(v4_all(2.0 * INV_PI_HI), v4_all(2.0 * INV_PI_LO)));
    A.lo -= A.hi * (A.hi * (mean_error * (2.0 * INV_PI_HI)));
    B.lo += mean_error * (2.0 * INV_PI_HI);
    const V4Dd d = v4_two_sum(1.0 - kc_bottom, -tail);
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
    inverse = v4_fast_two_sum(inverse.hi, inverse.lo);
    K = v4_fast_two_sum(K.hi, K.lo);
    /* finish_K */
    const V4 reciprocal = 1.0 / K.hi;
    const V4Dd bottom_factor = {1.0 + bottom_m * (0.25 + bottom_m * (9.0 / 64.0)), v4_all(0.0)};
    const V4Dd K_bottom = v4_dd_mul(v4_fast_two_sum(v4_all(HALF_PI_HI), v4_all(HALF_PI_LO)), bottom_factor);
    const V4 bottom_scale = v4_dd_mul(K_bottom, inverse).hi;
    for (int l = 0; l < lanes; ++l) {
        p[l]->K_hi = K.hi[l];
        p[l]->K_lo = K.lo[l];
        p[l]->inv_K = reciprocal[l];
        p[l]->K_head = dd_head26(K.hi[l]);
        p[l]->K_tail = K.hi[l] - p[l]->K_head;
        p[l]->bottom_scale = bottom_scale[l];
        inv_K[l].hi = inverse.hi[l];
        inv_K[l].lo = inverse.lo[l];
    }
}

#endif
