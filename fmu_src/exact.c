/* exact.c: the exact solution of theta'' + w0^2 sin(theta) = 0 (see exact.h and
 * documentation/math.html for the formulas).
 *
 * Initial state: theta0 = 2 pi j + th with th in (-pi, pi], s = sin(th/2), c = cos(th/2) >= 0,
 * q = omega0 / (2 w0). All of s, c, q and the complementary parameter are formed in
 * double-double, so K (and with it the period) is right to ~1e-30 relative for the binary
 * inputs: over 1e6 periods the phase needs K to better than 1e-18, which a double m1 (two
 * roundings of cos) does not give.
 *
 * Libration, m = s^2 + q^2 < 1, m1 = (c - q)(c + q) > 0 (A&S 16 / documentation/math.html):
 *   sin(theta/2) = k sn u,  cos(theta/2) = dn u,  omega = 2 k w0 cn u,  u = w0 (t - t0) + u0,
 *   theta = 2 atan2(k sn u, dn u). With u = n K + r, |r| <= K/2 (A&S 16.8):
 *     n = 0 mod 4: theta = 2 atan2( k sn r, dn r),   omega =  2 k w0 cn r
 *     n = 1 mod 4: theta = 2 atan2( k cn r, k'),     omega = -2 k w0 k' sn r / dn r
 *     n = 2 mod 4: theta = 2 atan2(-k sn r, dn r),   omega = -2 k w0 cn r
 *     n = 3 mod 4: theta = 2 atan2(-k cn r, k'),     omega =  2 k w0 k' sn r / dn r
 *   (the common positive factor 1/dn r of sn and dn is dropped inside atan2). Evaluated one
 *   Landen level lower (elliptic.h): atan2(k sn u, dn u) = 2 atan(sqrt(k_1) sn(u_1 | m_1)),
 *   u_1 = u / (1 + k_1), where sn(u_1) = +-sn r_1 or +-cd r_1 by the same table, so
 *   theta = 4 atan(sqrt(k_1) sn(u_1)) with an argument of modulus <= sqrt(k_1) < 1; the last
 *   Landen step is only needed for omega.
 *   Initial phase: k sn u0 = s, k cn u0 = q, dn u0 = c, so am u0 = atan2(s, q) and by
 *   DLMF 19.25.5 with the homogeneity of R_F (DLMF 19.16.1 scaled by k^2):
 *     F(phi0 | m) = (|s|/k) R_F((q/k)^2, c^2, 1)  for |phi0| <= pi/2,
 *   all three arguments known without cancellation; q < 0 uses F(pi - phi) = 2K - F(phi).
 *
 * Rotation, m > 1, parameter mu = 1/m, mu1 = -m1/m, for omega0 > 0 (mirror for omega0 < 0):
 *   theta = 2 am(v | mu),  omega = 2 sqrt(m) w0 dn(v | mu),  v = sqrt(m) w0 (t - t0) + v0,
 *   v0 = F(th/2 | mu) = s R_F(c^2, 1 - mu s^2, 1), 1 - mu s^2 = q^2/m = 1/(1 + (s/q)^2).
 *   With rho = s/q and gamma = c/q (both formed as ratios to |omega0|/2, no overflow):
 *   mu = (w0/(|omega0|/2))^2 / (1 + rho^2), mu1 = (1 - gamma)(1 + gamma) / (1 + rho^2),
 *   sqrt(m) w0 = |omega0|/2 sqrt(1 + rho^2) (kept in double-double), and
 *   am(n K + r) = n pi/2 + atan2(sn r, cn r) (n even), n pi/2 + atan2(k' sn r, cn r) (n odd).
 *
 * Separatrix, m1 == 0: theta = 2 atan(sinh u), omega = 2 w0 sech u, u = w0 (t - t0) + u0,
 *   u0 = asinh(tan(th/2)) = asinh(s/c), mirrored for omega0 < 0. */
#include "exact.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#define PI_HI   ELLIPTIC_PI_HI
#define PI_LO   ELLIPTIC_PI_LO
#define PI_LOLO ELLIPTIC_PI_LOLO

static EllipticDD dd_sub(EllipticDD x, EllipticDD y)
{
    return elliptic_dd_add(x, elliptic_dd_neg(y));
}

/* x - j (2 pi), 2 pi in three parts, the two leading products exact. */
static EllipticDD subtract_turns(EllipticDD x, double j)
{
    x = dd_sub(x, elliptic_two_prod(j, 2.0 * PI_HI));
    x = dd_sub(x, elliptic_two_prod(j, 2.0 * PI_LO));
    return elliptic_dd_add(x, elliptic_dd(-j * 2.0 * PI_LOLO));
}

/* x * 2^exponent for a double-double (exact unless it overflows or underflows). */
static EllipticDD dd_ldexp(EllipticDD x, int exponent)
{
    x.hi = ldexp(x.hi, exponent);
    x.lo = ldexp(x.lo, exponent);
    return x;
}

static void init_separatrix(PendulumExact *e, EllipticDD s, EllipticDD c, double omega0, double w0)
{
    e->regime = PENDULUM_SEPARATRIX;
    e->m = 1.0;
    e->m1 = 0.0;
    e->k = 1.0;
    e->kc = 0.0;
    e->K_hi = INFINITY;
    e->K_lo = 0.0;
    e->scale = w0;
    e->scale_lo = 0.0;
    e->omega_half = w0;
    e->period = INFINITY;
    (void)elliptic_param_init(&e->ell, 1.0, 0.0, 0.0);   /* K = +inf; cannot fail */
    if (omega0 == 0.0) {
        /* At rest on the unstable equilibrium (c == 0): stays there. */
        e->direction = 0.0;
        e->u0 = 0.0;
    } else {
        e->direction = omega0 > 0.0 ? 1.0 : -1.0;
        e->u0 = asinh(e->direction * s.hi / c.hi);   /* u0 = asinh(tan(th/2)), mirrored */
    }
}

int pendulum_exact_init(PendulumExact *ex, double theta0, double omega0, double w0, double t0)
{
    if (ex == NULL || !isfinite(theta0) || !isfinite(omega0) || !isfinite(w0) || !isfinite(t0)
        || !(w0 > 0.0)) {
        return -1;
    }
    PendulumExact e;
    memset(&e, 0, sizeof e);
    e.w0 = w0;
    e.t0 = t0;
    e.theta0 = theta0;
    e.direction = 1.0;

    /* theta0 = 2 pi j + th, th in (-pi, pi] (double-double). One subtraction of whole turns
     * does it for |theta0| < 2^52; up to 2^60 j = nearest(theta0 / 2 pi) is itself rounded and
     * a second round finishes. From 2^60 on theta0 no longer resolves an angle (its ulp is
     * 256 rad): the exact remainder modulo the double 2 pi keeps everything finite there. */
    double turns = 0.0;
    EllipticDD th = elliptic_dd(theta0);
    if (fabs(theta0) >= 0x1p60) {
        th = elliptic_dd(fmod(theta0, 2.0 * PI_HI));
        turns = nearbyint((theta0 - th.hi) / (2.0 * PI_HI));
    }
    for (int round = 0; round < 8 && !(fabs(th.hi) <= 3.2); ++round) {
        const double j = nearbyint(th.hi / (2.0 * PI_HI));
        th = subtract_turns(th, j);
        turns += j;
    }
    EllipticDD half = elliptic_dd_mul(th, elliptic_dd(0.5));
    EllipticDD s, c;
    elliptic_dd_sincos(half, &s, &c);
    if (c.hi < 0.0 || (c.hi == 0.0 && th.hi < 0.0)) {
        /* th just outside (-pi, pi]: move it by one turn; th/2 moves by pi, s and c change sign. */
        double shift = th.hi > 0.0 ? 1.0 : -1.0;
        turns += shift;
        th = subtract_turns(th, shift);
        s = elliptic_dd_neg(s);
        c = elliptic_dd_neg(c);
    }
    e.theta_turns = turns;
    e.theta_reduced = th.hi;

    /* Only the ratio q = |omega0| / (2 w0) enters m and m1, so w0 and |omega0|/2 are scaled
     * by a common power of two that puts the larger in [1/2, 1): the double-double products
     * below then stay far from overflow (Dekker's split needs |x| < 2^996) for any inputs.
     * Rates come back to seconds by the inverse power of two. */
    const double half_speed = 0.5 * fabs(omega0);          /* |omega0| / 2, exact */
    int exponent;
    (void)frexp(fmax(w0, half_speed), &exponent);
    const double w_n = ldexp(w0, -exponent), hs_n = ldexp(half_speed, -exponent);
    /* Sign of m1 = cos^2(th/2) - q^2 is that of w0 c - |omega0|/2, formed exactly enough. */
    const EllipticDD c_w = elliptic_dd_mul(c, elliptic_dd(w_n));
    const EllipticDD gap = dd_sub(c_w, elliptic_dd(hs_n));         /* = w_n (c - |q|) */
    EllipticDD rate_n;                                     /* rate of u, scaled by 2^-exponent */

    if (gap.hi > 0.0) {
        /* Libration: w_n >= 1/2 here, q = |omega0| / (2 w0) <= c <= 1. */
        EllipticDD q = elliptic_dd_div(elliptic_dd(hs_n), elliptic_dd(w_n));
        EllipticDD m1 = elliptic_dd_mul(elliptic_dd_div(gap, elliptic_dd(w_n)), elliptic_dd_add(c, q));
        if (m1.hi > 0.0) {
            e.regime = PENDULUM_LIBRATION;
            double k = hypot(s.hi, q.hi);        /* sqrt(m) = sqrt(s^2 + q^2), no underflow */
            double m = fmin(k * k, 1.0);
            if (elliptic_param_init(&e.ell, m, m1.hi, m1.lo) != 0) {
                return -1;
            }
            e.m = m;
            e.m1 = m1.hi;
            e.k = k;
            e.kc = e.ell.kc;
            e.K_hi = e.ell.K_hi;
            e.K_lo = e.ell.K_lo;
            e.scale = w0;
            e.scale_lo = 0.0;
            rate_n = elliptic_dd(w_n);
            e.omega_half = k * w0;
            e.sqrt_k1 = k / (1.0 + e.ell.kc);   /* sqrt(k_1) = k / (1 + k'), no underflow of k^2 */
            if (k == 0.0) {
                e.u0 = 0.0;                          /* at rest at the bottom: theta = 0 */
            } else {
                double s_k = fabs(s.hi) / k, q_k = q.hi / k;
                /* F(|phi0| | m) = (|s|/k) R_F((q/k)^2, c^2, 1) (DLMF 19.25.5, scaled). */
                double f = s_k * elliptic_RF(q_k * q_k, c.hi * c.hi, 1.0);
                /* omega0 < 0: |phi0| = pi - atan2(|s|, |q|), F = 2K - F(pi - |phi0|). */
                double base = omega0 >= 0.0 ? f : (2.0 * e.K_hi - f) + 2.0 * e.K_lo;
                e.u0 = s.hi < 0.0 ? -base : base;
            }
        } else {
            init_separatrix(&e, s, c, omega0, w0);   /* m1 underflowed: treat as m1 == 0 */
        }
    } else if (gap.hi < 0.0) {
        /* Rotation (omega0 != 0 here). Ratios to |omega0|/2: rho = s/|q|, gamma = c/|q| < 1
         * (hs_n > c w_n, and c >= ~1e-33, so hs_n is not tiny). */
        e.regime = PENDULUM_ROTATION;
        e.direction = omega0 > 0.0 ? 1.0 : -1.0;
        const EllipticDD hs = elliptic_dd(hs_n);
        EllipticDD rho = elliptic_dd_div(elliptic_dd_mul(s, elliptic_dd(w_n)), hs);
        EllipticDD one_plus_rho2 = elliptic_dd_add(elliptic_dd(1.0), elliptic_dd_mul(rho, rho));
        EllipticDD one_minus_gamma = elliptic_dd_div(elliptic_dd_neg(gap), hs);  /* (|q| - c)/|q| */
        EllipticDD gamma = elliptic_dd_div(c_w, hs);
        /* mu1 = -m1/m = (q^2 - c^2)/(q^2 + s^2) = (1 - gamma)(1 + gamma)/(1 + rho^2). */
        EllipticDD mu1 = elliptic_dd_div(
            elliptic_dd_mul(one_minus_gamma, elliptic_dd_add(elliptic_dd(1.0), gamma)), one_plus_rho2);
        /* mu = 1/m = 1/(q^2 (1 + rho^2)). */
        double w_hs = w_n / hs_n;
        double mu = fmin(w_hs * w_hs / one_plus_rho2.hi, 1.0);
        if (elliptic_param_init(&e.ell, mu, mu1.hi, mu1.lo) != 0) {
            return -1;
        }
        /* sqrt(m) w0 = |q| w0 sqrt(1 + rho^2) = (|omega0|/2) sqrt(1 + rho^2). */
        rate_n = elliptic_dd_mul(hs, elliptic_dd_sqrt(one_plus_rho2));
        EllipticDD rate = dd_ldexp(rate_n, exponent);
        e.m = 1.0 / mu;
        e.m1 = -mu1.hi / mu;
        e.k = e.ell.k;
        e.kc = e.ell.kc;
        e.K_hi = e.ell.K_hi;
        e.K_lo = e.ell.K_lo;
        e.scale = rate.hi;
        e.scale_lo = rate.lo;
        e.omega_half = rate.hi;
        /* v0 = F(th/2 | mu) for the mirrored motion (direction * th), DLMF 19.25.5. */
        e.u0 = e.direction * s.hi * elliptic_RF(c.hi * c.hi, 1.0 / one_plus_rho2.hi, 1.0);
    } else {
        init_separatrix(&e, s, c, omega0, w0);
    }
    if (e.regime != PENDULUM_SEPARATRIX) {
        /* Rate and initial phase in quarter periods: rho = scale / K, x0 = u0 / K; the period
         * 4K / w0 (libration) or 2K / rate (one revolution, rotation), all in double-double. */
        EllipticDD K;
        K.hi = e.K_hi;
        K.lo = e.K_lo;
        EllipticDD rho = dd_ldexp(elliptic_dd_div(rate_n, K), exponent);
        EllipticDD x0 = elliptic_dd_div(elliptic_dd(e.u0), K);
        e.rho_hi = rho.hi;
        e.rho_lo = rho.lo;
        e.rho_head = elliptic_head26(rho.hi);
        e.rho_tail = rho.hi - e.rho_head;
        e.x0_hi = x0.hi;
        e.x0_lo = x0.lo;
        const double quarters_per_period = e.regime == PENDULUM_LIBRATION ? 4.0 : 2.0;
        e.period = ldexp(elliptic_dd_div(elliptic_dd_mul(K, elliptic_dd(quarters_per_period)), rate_n).hi,
                         -exponent);
    }
    memcpy(ex, &e, sizeof e); /* bytewise, padding included (see fmi2_state.c) */
    return 0;
}

/* Phase in quarter periods: x = (scale (t - t0) + u0) / K = rho (t - t0) + x0, split as
 * x = n + f with n the nearest integer and |f| <= 1/2; returns f, sets *n. rho tau.hi is
 * exact (Dekker's product, rho split once in init) and rho, x0 are double-double, so f keeps
 * its absolute accuracy for n in the millions. Then u = n K + f K (A&S 16.8 needs n mod 4).
 * Without a hardware fma the split tau = tau_head + tau_tail is Veltkamp's (no fma, so no
 * contraction can touch it). */
static double phase_quarters(const PendulumExact *ex, double t, double *n)
{
    const EllipticDD tau = elliptic_two_sum(t, -ex->t0);
    const double x_hi = ex->rho_hi * tau.hi;
    if (!(fabs(tau.hi) < 0x1p995 && fabs(x_hi) < 0x1p52)) {
        /* More than 2^52 quarter periods (or a non-finite t): doubles cannot resolve the
         * phase there; stay finite for a finite t, NaN for a NaN or infinite one. */
        *n = 0.0;
        return tau.hi - tau.hi;
    }
#ifdef FP_FAST_FMA
    const double x_lo = fma(ex->rho_hi, tau.hi, -x_hi);
#else
    const double tau_split = 134217729.0 * tau.hi;          /* Veltkamp split of tau.hi */
    const double tau_head = tau_split - (tau_split - tau.hi), tau_tail = tau.hi - tau_head;
    const double x_lo = ((ex->rho_head * tau_head - x_hi) + ex->rho_head * tau_tail
                         + ex->rho_tail * tau_head) + ex->rho_tail * tau_tail;
#endif
    const double quarters = elliptic_nearest_integer(x_hi + ex->x0_hi);
    *n = quarters;
    /* x_hi - quarters is exact once quarters exceeds a few (Sterbenz); below, all is small. */
    return ((x_hi - quarters) + ex->x0_hi)
           + (x_lo + (ex->rho_hi * tau.lo + ex->rho_lo * tau.hi) + ex->x0_lo);
}

void pendulum_exact_eval(const PendulumExact *ex, double t, double *theta, double *omega)
{
    double angle, om, half_turns = 2.0 * ex->theta_turns;   /* theta = half_turns pi + angle */

    if (ex->regime == PENDULUM_LIBRATION) {
        double n;
        const double f = phase_quarters(ex, t, &n);
        EllipticHomogeneous h0, h1;                 /* sn r = h0.S / h0.D, ... at levels 0, 1 */
        elliptic_sncndn_homogeneous_pair(&ex->ell, f * ex->K_hi, &h0, &h1);
        /* The quarter n mod 4 picks the formulas of the header comment through exact 0/1
         * weights (x * 0 + y * 1 == y exactly): no data-dependent branch. */
        const int quarter = elliptic_quarter_of(n);
        const double odd = (double)(quarter & 1), even = 1.0 - odd;
        const double sign = 1.0 - (double)(quarter & 2);          /* -1 for n = 2, 3 mod 4 */
        /* theta/2 = atan2(k sn u, dn u) = 2 atan(sqrt(k_1) sn(u_1 | m_1)) (elliptic.h), and at
         * level 1 sn(u_1) = sign sn r_1 (n even) or sign cd r_1 (n odd), |sn(u_1)| <= 1. */
        const double y1 = even * h1.S + odd * h1.C, x1 = even * h1.D + odd * h1.E;
        angle = 4.0 * elliptic_atan_unit(sign * ex->sqrt_k1 * y1, x1);
        /* cn u = sign cn r (n even), -sign k' sn r / dn r (n odd) */
        const double cn_num = even * h0.C - odd * (ex->kc * h0.S), den = even * h0.D + odd * h0.E;
        om = 2.0 * (sign * ex->omega_half * (cn_num / den));     /* 2 k w0 cn u */
    } else if (ex->regime == PENDULUM_ROTATION) {
        double n, S, C, E, D;
        const double f = phase_quarters(ex, t, &n);
        elliptic_sncndn_homogeneous(&ex->ell, f * ex->K_hi, &S, &C, &E, &D); /* sn r = S/D, ... */
        const int quarter = elliptic_quarter_of(n);
        const double odd = (double)(quarter & 1), even = 1.0 - odd;
        /* am(nK + r) - n pi/2 = atan(sn r / cn r) (n even), atan(k' sn r / cn r) (n odd); C > 0
         * for |r| < K, as elliptic_atan_ratio requires */
        const double delta = elliptic_atan_ratio((even + odd * ex->kc) * S, C);
        const double dn_num = even * E + odd * (ex->kc * D), den = even * D + odd * E;
        /* theta = 2 pi j + direction (n pi + 2 delta), omega = 2 sqrt(m) w0 dn(nK + r) */
        half_turns += ex->direction * n;
        angle = 2.0 * ex->direction * delta;
        om = 2.0 * (ex->direction * ex->omega_half * (dn_num / den));
    } else if (ex->direction != 0.0) {
        EllipticDD tau = elliptic_two_sum(t, -ex->t0);
        double u = ex->scale * (tau.hi + tau.lo) + ex->u0;
        angle = 2.0 * ex->direction * atan(sinh(u));          /* gd(u) */
        om = 2.0 * (ex->direction * (ex->omega_half / cosh(u)));   /* 2 w0 sech u */
    } else {
        angle = ex->theta_reduced;
        om = 0.0;
    }

    /* theta = half_turns * pi + angle, half_turns * pi_hi exact (two-product). */
    if (half_turns != 0.0) {
        if (fabs(ex->theta_turns) < 0x1p50 && fabs(half_turns) < 0x1p52) {
            EllipticDD turn = elliptic_two_prod(half_turns, PI_HI);
            angle = turn.hi + (turn.lo + (half_turns * PI_LO + angle));
        } else {
            /* theta0 or the winding beyond 2^50 rad, where no angle is resolved: theta0 plus
             * the change since t0 (finite; no two-product of huge numbers). */
            angle = ex->theta0 + ((half_turns - 2.0 * ex->theta_turns) * PI_HI
                                  + (angle - ex->theta_reduced));
        }
    }
    *theta = angle;
    *omega = om;
}

double pendulum_exact_period(const PendulumExact *ex)
{
    return ex->period;   /* computed in init: 4K/w0, 2K/(sqrt(m) w0), or +inf */
}
