/* exact_avx.h: the evaluation of four librations to an AVX vector, for the fma build's batched
 * new states (exact.c: pendulum_exact_once_gl_many; exact_fma.c: GCC on x86-64), included by
 * exact.c there alone.
 *
 * Each lane runs eval_libration's operations in their order (phase_near, trig_sincos_small,
 * elliptic_landen_bottom, the Landen steps, libration_angle_omega with elliptic_atan_unit,
 * add_half_turns) on its own state's constants, elementwise IEEE operations as the scalar
 * code's (dd_avx.h), so its theta and omega have the scalar bits; a lane whose chain has fewer
 * Landen levels than another's keeps its values through the extra steps. A lane off
 * eval_libration's path (t == t0, a phase beyond 2^50 quarter periods or not finite, a bottom
 * argument past the series) is left to the caller. test_exact_batch compares every output. */
#ifndef PENDULUM_EXACT_AVX_H
#define PENDULUM_EXACT_AVX_H

#include "dd_avx.h"

/* elliptic_atan_series */
static inline V4 v4_atan_series(V4 s)
{
    const V4 s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
    const V4 g01 = -0x1.5555555555555p-2 + s * 0x1.9999999999953p-3;
    const V4 g23 = -0x1.249249248d7eep-3 + s * 0x1.c71c71c304b68p-4;
    const V4 g45 = -0x1.745d165df3f95p-4 + s * 0x1.3b1392d9e785cp-4;
    const V4 g67 = -0x1.110e880a7a521p-4 + s * 0x1.e19a13b9fc6dfp-5;
    const V4 g89 = -0x1.ac7a938b69c93p-5 + s * 0x1.74ddd408bb4c1p-5;
    const V4 g1011 = -0x1.1b33b923aa954p-5 + s * 0x1.0ad36a455cafbp-6;
    return ((g01 + s2 * g23) + s4 * (g45 + s2 * g67)) + s8 * (g89 + s2 * g1011);
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
    /* copysign(angle, y) */
    const __m256d sign_bit = _mm256_set1_pd(-0.0);
    return (V4)_mm256_or_pd(_mm256_andnot_pd(sign_bit, (__m256d)angle), _mm256_and_pd(sign_bit, (__m256d)y));
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
    *S = v4_pick(step, up_S, *S);
    *C = v4_pick(step, up_C, *C);
    *E = v4_pick(step, up_E, *E);
    *D = v4_pick(step, up_D, *D);
}

/* What eval_libration reads of four librations, lane by lane; the level factors level by
 * level (a lane's own up to its levels, any finite values beyond). */
typedef struct {
    V4 t0, rho_hi, rho_lo, x0_hi, x0_lo, K_hi, bottom_scale, bottom_m, sqrt_k1, kc, omega_half;
    V4 theta_turns;   /* whole turns of theta0, |theta_turns| < 2^50 */
    V4 levels;   /* N as doubles */
    int most;    /* the largest N */
    const V4 *landen_k, *landen_1pk, *landen_1mk;   /* [level] */
} LibrationV4;

/* eval_libration's operations at times tv: *theta and *omega for every lane, and a mask of
 * the lanes on its common path (a phase below 2^50 quarter periods, a bottom argument within
 * the series, tv != t0; the caller checks the rest). */
static inline V4Mask eval_libration_v4(const LibrationV4 *s, V4 tv, V4 *theta, V4 *omega)
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
    v4_landen_step(~(V4Mask){0, 0, 0, 0}, long_chain, s->landen_k[0], s->landen_1pk[0], s->landen_1mk[0], &S0, &C0,
                   &E0, &D0);
    const V4Mask negative = (V4Mask)(v < 0.0);   /* sn is odd, cn and dn are even */
    S = v4_pick(negative, -S, S);
    S0 = v4_pick(negative, -S0, S0);
    /* libration_angle_omega */
    const V4 even = 1.0 - odd;
    const V4 y1 = even * S + odd * C, x1 = even * D + odd * E;
    const V4 angle = 4.0 * v4_atan_unit(sign * s->sqrt_k1 * y1, x1);
    /* add_half_turns(2 theta_turns, angle): half_turns_pi and plus_half_turns (the low part of
     * the half turns is 0, and lo pi_hi with it), the angle alone without turns */
    const V4 half_turns = 2.0 * s->theta_turns;
    const V4Dd turn = v4_two_prod(half_turns, v4_all(PI_HI));
    const V4 hi_pi_lo = half_turns * PI_LO, lo_pi_hi = v4_all(0.0 * PI_HI);
    const V4 wound = turn.hi + (turn.lo + (hi_pi_lo + (lo_pi_hi + angle)));
    *theta = v4_pick((V4Mask)(half_turns == 0.0), angle, wound);
    const V4 cn_num = even * C0 - odd * (s->kc * S0), den = even * D0 + odd * E0;
    *omega = 2.0 * (sign * s->omega_half * (cn_num / den));
    return (V4Mask)(v4_abs(x_hi) < 0x1p50) & (V4Mask)(z <= ELLIPTIC_SERIES_Z_MAX) & (V4Mask)(tv != s->t0);
}

#endif
