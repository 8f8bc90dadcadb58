/* dd.c: sin and cos of a double-double argument (see dd.h). */
#include "dd.h"

#include <math.h>

/* A branch the processor should predict taken, so that it need not wait for its other side. */
#if defined(__GNUC__)
#define DD_LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define DD_LIKELY(x) (x)
#endif

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

/* cos(i/64) and sin(i/64) in double-double, i = 0..50 (i/64 up to 0.78 < pi/4 + 1/128), from
 * mpmath at 400 bits: {cos hi, cos lo, sin hi, sin lo}. */
static const double TABLE_64[51][4] = {
    {0x1.0000000000000p+0, 0x0.0p+0, 0x0.0p+0, 0x0.0p+0},
    {0x1.fff000155549fp-1, 0x1.28a28a03a5ef3p-55, 0x1.fffaaaaeeeed5p-7, -0x1.2ab639a9f0776p-63},
    {0x1.ffc00155527d3p-1, -0x1.3b54492d89b5bp-55, 0x1.ffeaaaeeee86fp-6, -0x1.cd406fb224ae2p-60},
    {0x1.ff7006bfdf99fp-1, -0x1.8b3b560648d5fp-56, 0x1.7fdc01032fba9p-5, -0x1.599bdf46e997ap-59},
    {0x1.ff0015549f4d3p-1, 0x1.328387b99426fp-55, 0x1.ffaaaeeed4edbp-5, -0x1.2d16d32684b69p-59},
    {0x1.fe7034129ef6fp-1, -0x1.cbf4337c96f97p-57, 0x1.3facb12d1755bp-4, -0x1.921915299468bp-58},
    {0x1.fdc06bf7e6b9bp-1, 0x1.31902b535f8dbp-55, 0x1.7f701032550e4p-4, 0x1.afc2d1800501ap-60},
    {0x1.fcf0c800e99b1p-1, 0x1.ea3d786d186acp-57, 0x1.bf1b78568391dp-4, 0x1.e91841dea4cc8p-58},
    {0x1.fc015527d5bd3p-1, 0x1.b68f35094efb8p-55, 0x1.feaaeee86ee36p-4, -0x1.afcb2bcc6f03bp-59},
    {0x1.faf22263c4bd3p-1, -0x1.52ace133a2769p-58, 0x1.1f0d3d7afceafp-3, -0x1.6ef95099769a5p-57},
    {0x1.f9c340a7cc428p-1, 0x1.c5b6b063b7462p-55, 0x1.3eb312c5d66cbp-3, 0x1.47d666b66cb91p-57},
    {0x1.f874c2e1eecf6p-1, -0x1.c6514e1332b16p-55, 0x1.5e44fcfa126f3p-3, -0x1.6f443063f89b6p-57},
    {0x1.f706bdf9ece1cp-1, -0x1.698c80c36dcb4p-55, 0x1.7dc102fbaf2b5p-3, 0x1.5ab50e23c97c3p-59},
    {0x1.f57948cff6797p-1, 0x1.e3a0d3e03b1d4p-57, 0x1.9d252d0cec312p-3, 0x1.9c43d80b1137dp-58},
    {0x1.f3cc7c3b3d16ep-1, -0x1.21a3ad28a3494p-57, 0x1.bc6f84edc6199p-3, 0x1.9c1a56a7b0cabp-57},
    {0x1.f20073086649fp-1, 0x1.b940416c1984bp-56, 0x1.db9e15fb5a5d0p-3, -0x1.32e20d6cc6fc2p-57},
    {0x1.f01549f7deea1p-1, 0x1.d3c1e99e5cafdp-55, 0x1.faaeed4f31577p-3, -0x1.15d88508e32b8p-57},
    {0x1.ee0b1fbc0f11cp-1, -0x1.bfd2380bbc3b1p-59, 0x1.0cd00cef36436p-2, -0x1.9fb0a0c93e2b4p-56},
    {0x1.ebe214f76efa8p-1, -0x1.02f9f12ba543ep-55, 0x1.1c37d64c6b876p-2, 0x1.46076fe0dcff4p-56},
    {0x1.e99a4c3a7cd83p-1, -0x1.2264b1bc53ce8p-55, 0x1.2b8ddc43eb49fp-2, 0x1.1553899f2d807p-57},
    {0x1.e733ea0193d40p-1, -0x1.6428b3546ce13p-55, 0x1.3ad129769d3d8p-2, 0x1.03d550487839ap-63},
    {0x1.e4af14b2a449cp-1, -0x1.68ca02e8a6833p-55, 0x1.4a00c9b0f3d20p-2, 0x1.823ba6bb08eadp-56},
    {0x1.e20bf49acd6c1p-1, -0x1.660aec7ef636bp-58, 0x1.591bc9fa2f597p-2, 0x1.7c74bac3fe0cbp-57},
    {0x1.df4ab3ebd875ep-1, -0x1.e2d8a7e6736c4p-55, 0x1.682138a38d7f7p-2, -0x1.d889202444aadp-56},
    {0x1.dc6b7eb995912p-1, 0x1.4b364776dcd35p-58, 0x1.7710255764214p-2, -0x1.6ead7314bb6cep-57},
    {0x1.d96e82f71a9dcp-1, 0x1.ff61bd5d2039dp-55, 0x1.85e7a12826949p-2, 0x1.8a40e9b5face0p-56},
    {0x1.d653f073e4040p-1, -0x1.76236434bec37p-55, 0x1.94a6be9f546c5p-2, -0x1.69ce13e683f58p-56},
    {0x1.d31bf8d8d7c06p-1, 0x1.e60dd3089cbddp-56, 0x1.a34c91cc50ccap-2, -0x1.a310e3b50cecdp-58},
    {0x1.cfc6cfa52ad9fp-1, 0x1.8b5b5508f2a0dp-55, 0x1.b1d8305321617p-2, -0x1.ae242cb99f519p-56},
    {0x1.cc54aa2b2972ep-1, 0x1.4ee162ba83a98p-57, 0x1.c048b17b140a3p-2, 0x1.19fe6757e9fa7p-57},
    {0x1.c8c5bf8ce1a84p-1, 0x1.ab3d1a1590123p-56, 0x1.ce9d2e3d4a51fp-2, -0x1.2fc8a12dae298p-57},
    {0x1.c51a48b8b175ep-1, -0x1.1bbb43b9aa880p-57, 0x1.dcd4c15329c9ap-2, 0x1.0d4c6e171fd9ap-56},
    {0x1.c1528065b7d50p-1, -0x1.892111312e828p-55, 0x1.eaee8744b05f0p-2, -0x1.789b43c9b027dp-58},
    {0x1.bd6ea310294f5p-1, 0x1.31bbcc88c109dp-56, 0x1.f8e99e76abc97p-2, 0x1.9d950af2d00a3p-58},
    {0x1.b96eeef58840ep-1, 0x1.45a3cc78fade0p-58, 0x1.0362939c69955p-1, -0x1.2d8cd78397b01p-55},
    {0x1.b553a410c104ep-1, 0x1.8ff7947027a15p-58, 0x1.0a4021e9e1001p-1, -0x1.6f643a13914f6p-55},
    {0x1.b11d04162a4c6p-1, 0x1.1dd561efbc0c2p-56, 0x1.110d0c4b69c3bp-1, 0x1.d918998809981p-55},
    {0x1.accb526f69de5p-1, 0x1.8fb6a8dd6b6ccp-55, 0x1.17c8e5f2eedb0p-1, 0x1.35e57102e2488p-57},
    {0x1.a85ed4373e02dp-1, 0x1.9be06385ec792p-57, 0x1.1e7343236574cp-1, 0x1.22a3fa4f41d5ap-56},
    {0x1.a3d7d0352bdcfp-1, -0x1.68dbaeca19669p-55, 0x1.250bb93788bbbp-1, 0x1.ea3d02457bccep-56},
    {0x1.9f368ed912f85p-1, -0x1.1d200c5791606p-55, 0x1.2b91dea88421ep-1, -0x1.fa371db216ab0p-55},
    {0x1.9a7b5a36a6514p-1, 0x1.722cfcc9fa7a9p-55, 0x1.32054b148bc4fp-1, 0x1.f6b42095a135bp-55},
    {0x1.95a67e00cb1fdp-1, -0x1.0befda21f862dp-55, 0x1.386597456282bp-1, -0x1.10fada93b07a8p-56},
    {0x1.90b84784ddaf7p-1, -0x1.0feb10ab93b87p-56, 0x1.3eb25d36cd53ap-1, -0x1.be570e1570fc0p-58},
    {0x1.8bb105a5dc900p-1, 0x1.863e03e9474c1p-55, 0x1.44eb381cf386bp-1, -0x1.3ed6c1e6a5505p-55},
    {0x1.869108d77a6c6p-1, 0x1.338ffe2bfe9ddp-56, 0x1.4b0fc46aab761p-1, 0x1.0da05738cc59cp-61},
    {0x1.8158a31916d5dp-1, -0x1.de8b90b8228dep-57, 0x1.511f9fd7b351cp-1, -0x1.5c0e861c48831p-55},
    {0x1.7c0827f09e54fp-1, -0x1.c73d6d72aee68p-57, 0x1.571a6966d59b3p-1, 0x1.c843b4d0fb197p-58},
    {0x1.769fec655211fp-1, -0x1.827d5cf8c68c5p-57, 0x1.5cffc16bf8f0dp-1, 0x1.96cb370eb578ap-55},
    {0x1.712046fa77678p-1, 0x1.425b0a5029c81p-55, 0x1.62cf49921ac79p-1, -0x1.edd9855b6241ap-55},
    {0x1.6b898fa9efb5dp-1, 0x1.15ac786ccf4b2p-56, 0x1.6888a4e134b2fp-1, -0x1.6b7d37644d5e6p-55}
};

/* Coefficients in double-double (mpmath): 1/6, 1/120, 1/24, 1/720. */
#define INV_3F_HI 0x1.5555555555555p-3
#define INV_3F_LO 0x1.5555555555555p-57
#define INV_5F_HI 0x1.1111111111111p-7
#define INV_5F_LO 0x1.1111111111111p-63
#define INV_4F_HI 0x1.5555555555555p-5
#define INV_4F_LO 0x1.5555555555555p-59
#define INV_6F_HI 0x1.6c16c16c16c17p-10
#define INV_6F_LO (-0x1.f49f49f49f49fp-65)

/* The parts in double of the series below: sin_versine_small's P and Q beyond their two
 * leading terms (in z = r2.hi), table_leading's sin r - r_hi and 1 - cos r - R2_hi/2 (in
 * z = R2_hi). Written once for doubles here and for the vectors of four of once_avx.h, which
 * the fma build compiles in this same unit (exact_fma.c): the same operations on each. */
#define SMALL_P_REST(z) \
    ((z) * (z) * (-0x1.a01a01a01a01ap-13 + (z) * (0x1.71de3a556c734p-19 - (z) * 0x1.ae64567f544e4p-26)))
#define SMALL_Q_REST(z) ((z) * (z) * (0x1.a01a01a01a01ap-16 - (z) * 0x1.27e4fb7789f5cp-22))
#define TABLE_SIN_REST(r_hi, r_lo, z) \
    ((r_lo) - (r_hi) * (z) * (0x1.5555555555555p-3 - (z) * (0x1.1111111111111p-7 - (z) * 0x1.a01a01a01a01ap-13)))
#define TABLE_VERSINE_REST(r_hi, r_lo, R2_lo, z) \
    ((0.5 * (R2_lo) + (r_hi) * (r_lo)) - (z) * (z) * (0x1.5555555555555p-5 - (z) * 0x1.6c16c16c16c17p-10))

/* x + y for |y.hi| <= |x.hi| (or x == 0) and no cancellation (|x + y| >= |x|/2): Fast2Sum on
 * the heads, the tails added (the "sloppy" sum of Hida, Li and Bailey), relative error a few
 * 2^-106 under that condition. */
static DoubleDouble dd_add_smaller(DoubleDouble x, DoubleDouble y)
{
    DoubleDouble s = dd_fast_two_sum(x.hi, y.hi);
    s.lo += x.lo + y.lo;
    return dd_fast_two_sum(s.hi, s.lo);
}

/* w = sin r and v = 1 - cos r in double-double for |r| <= 1/128 (and a tail of r below its ulp),
 * by their Maclaurin series (A&S 4.3.65-66) in r2 = r^2:
 *   w = r + r r2 P,  P = -1/6 + r2/120 - r2^2/5040 + r2^3/9! - r2^4/11!,
 *   v = r2/2 - r2^2 Q,  Q = 1/24 - r2/720 + r2^2/8! - r2^3/10!;
 * the first omitted terms, r^13/13! and r^12/12!, are below 2^-106 |r| and 2^-98 r^2/2.
 * r2 P is below 2^-16 and r2 Q below 2^-18, so P and Q need about 90 bits: their two leading
 * terms in double-double, the rest in double. w to ~2^-105 relative, v to ~2^-103. */
static void sin_versine_small(DoubleDouble r, DoubleDouble *w, DoubleDouble *v)
{
    DoubleDouble r2 = dd_two_prod(r.hi, r.hi);
    r2.lo += 2.0 * r.hi * r.lo;
    const double z = r2.hi;
    const double p_rest = SMALL_P_REST(z);
    const double q_rest = SMALL_Q_REST(z);
    /* P = -1/6 + r2/120 + p_rest, Q = 1/24 - r2/720 + q_rest: the products below 2^-18 of the
     * constants, so one Fast2Sum of the heads and the rest added to the tail */
    const DoubleDouble p2 = dd_mul(r2, (DoubleDouble){INV_5F_HI, INV_5F_LO});
    const DoubleDouble q2 = dd_mul(r2, (DoubleDouble){-INV_6F_HI, -INV_6F_LO});
    DoubleDouble P = dd_fast_two_sum(-INV_3F_HI, p2.hi), Q = dd_fast_two_sum(INV_4F_HI, q2.hi);
    P.lo += (-INV_3F_LO + p2.lo) + p_rest;
    Q.lo += (INV_4F_LO + q2.lo) + q_rest;
    *w = dd_add_smaller(r, dd_mul(dd_mul(r, r2), P));
    *v = dd_add_smaller((DoubleDouble){0.5 * r2.hi, 0.5 * r2.lo}, dd_neg(dd_mul(dd_mul(r2, r2), Q)));
}

/* sin y (want & WANT_SIN) and cos y (want & WANT_COS) in double-double for |y| <= pi/4 + 2^-50
 * (y normalised): |y| = a + r with a = i/64 the nearest table point, |r| <= 1/128 (r exact:
 * |y.hi| - a by Sterbenz, |y.hi| >= a/2 for i >= 1, then TwoSum with y.lo), and by the
 * addition theorems
 *   cos(a + r) = C - (C v + S w),  sin(a + r) = S + (C w - S v),
 * C, S = cos a, sin a (TABLE_64), w = sin r, v = 1 - cos r (sin_versine_small). The corrections
 * are at most 2^-7 of cos and half of sin (a >= 2|r| unless a = 0), so both keep ~2^-104 relative
 * accuracy, sin also for tiny y (a = 0: sin y = w). */
static DdTablePoint table_point(DoubleDouble y)
{
    DdTablePoint t;
    t.sign = y.hi < 0.0 ? -1.0 : 1.0;
    const DoubleDouble u = {t.sign * y.hi, t.sign * y.lo};   /* |y| */
    /* i = nearest(64 |y|), ties up, from the exact 64 |y|: (int)(64 |y| + 0.5) would round
     * 1/128 - 2^-60 up to i = 1, where |y| - 1/64 is not exact */
    const double scaled = u.hi * 64.0;
    const int whole = (int)scaled;
    const int i = whole + (scaled - (double)whole >= 0.5);   /* 0..50 */
    const double *row = TABLE_64[i];
    t.C = (DoubleDouble){row[0], row[1]};
    t.S = (DoubleDouble){row[2], row[3]};
    t.r = dd_two_sum(u.hi - (double)i * 0.015625, u.lo);
    return t;
}

static void sincos_at(const DdTablePoint *t, int want, DoubleDouble *sin_y, DoubleDouble *cos_y)
{
    DoubleDouble w, v;
    sin_versine_small(t->r, &w, &v);
    if (want & WANT_COS) {
        /* |C v| <= r^2/2 <= |S w|/4 unless S = 0 */
        *cos_y = dd_add_smaller(t->C, dd_neg(dd_add_smaller(dd_mul(t->S, w), dd_mul(t->C, v))));
    }
    if (want & WANT_SIN) {
        const DoubleDouble s = dd_add_smaller(t->S, dd_add_smaller(dd_mul(t->C, w), dd_neg(dd_mul(t->S, v))));
        *sin_y = (DoubleDouble){t->sign * s.hi, t->sign * s.lo};
    }
}

static void sincos_table(DoubleDouble y, int want, DoubleDouble *sin_y, DoubleDouble *cos_y)
{
    const DdTablePoint t = table_point(y);
    sincos_at(&t, want, sin_y, cos_y);
}

/* The leading double of cos |y| (odd = 0) or sin |y| (odd = 1) of sincos_table, formed early and
 * certified: the terms of order 0, 1 and 2 in r exactly (two-products, TwoSum),
 *   cos(a + r) = C_hi - S_hi r_hi - C_hi r_hi^2/2 + rest,  sin(a + r) = S_hi + C_hi r_hi - S_hi r_hi^2/2 + rest,
 * the rest (below 2^-21) in double to ~2^-74, then *lead = fl(sum) and 1 when *lead is
 * certainly the value rounded to nearest: the exact remainder of that sum (TwoSum), moved by
 * the bound 2^-66 |lead| on what was left out or rounded, rounds back to *lead either way.
 * It is then the leading double of the double-double result (the same rounding to nearest),
 * which the caller need not wait for. */
static int table_leading(const DdTablePoint *t, int odd, double *lead)
{
    const DoubleDouble r = t->r, C = t->C, S = t->S;
    const DoubleDouble R2 = dd_two_prod(r.hi, r.hi);
    /* w = sin r = r_hi + w_rest, v = 1 - cos r = R2_hi/2 + v_rest (A&S 4.3.65-66) */
    const double z = R2.hi;
    const double w_rest = TABLE_SIN_REST(r.hi, r.lo, z);
    const double v_rest = TABLE_VERSINE_REST(r.hi, r.lo, R2.lo, z);
    const DoubleDouble first = odd ? dd_two_prod(C.hi, r.hi) : dd_two_prod(-S.hi, r.hi);
    const double base = odd ? S.hi : C.hi, other = odd ? C.hi : -S.hi;
    const double base_lo = odd ? S.lo : C.lo, other_lo = odd ? C.lo : -S.lo;
    const DoubleDouble second = dd_two_prod(-base, 0.5 * z);
    const DoubleDouble A = dd_two_sum(base, first.hi), B = dd_two_sum(A.hi, second.hi);
    const double rest = ((A.lo + B.lo) + (first.lo + second.lo))
                        + ((base_lo - base_lo * (0.5 * z) - base * v_rest) + (other * w_rest + other_lo * r.hi));
    const DoubleDouble sum = dd_two_sum(B.hi, rest);
    const double bound = 0x1p-66 * fabs(sum.hi);
    *lead = sum.hi;
    return sum.hi + (sum.lo + bound) == sum.hi && sum.hi + (sum.lo - bound) == sum.hi;
}

/* y = x - n pi/2 for n = nearest(x / (pi/2)), in double-double: for |n| = 1, x.hi - n (pi/2)_hi
 * is exact (Sterbenz), x.lo - n (pi/2)_lo exact by TwoSum, so y keeps its relative accuracy
 * next to the zeros (the same y as reduce_half_pi, ~2^-160 absolute); other n by
 * reduce_half_pi. Below 2 in magnitude n comes from comparisons with (pi/2)_hi / 2 (exact):
 * the same n as the rounded quotient x.hi / (pi/2)_hi, which is 1/2 only at x.hi =
 * (pi/2)_hi / 2 itself (n = 0 then, ties to even) and otherwise at least 2^-53.6 from 1/2,
 * beyond its rounding; a comparison does not wait for a division. */
static DoubleDouble reduce_quadrant(DoubleDouble x, double *quadrants)
{
    if (!(fabs(x.hi) < 2.0)) {
        return reduce_half_pi(x, quadrants);
    }
    const double n = (double)(x.hi > 0.5 * HALF_PI_HI) - (double)(x.hi < -0.5 * HALF_PI_HI);
    *quadrants = n;
    if (n == 0.0) {
        return x;
    }
    const double head = x.hi - n * HALF_PI_HI;
    const DoubleDouble rest = dd_two_sum(x.lo, -n * HALF_PI_LO);
    DoubleDouble y = dd_two_sum(head, rest.hi);
    y.lo += rest.lo - n * HALF_PI_LOLO;
    return dd_fast_two_sum(y.hi, y.lo);
}

/* sum_j coef[j].hi z^j, j = 0..13, by Horner's scheme in double: the series of sin y / y - 1
 * (times 1/z) and cos y - 1 as sincos_reduced forms them for its double result, so that
 * dd_cos_sin gives the same double sin as it always has. */
static double horner_double(const DoubleDouble *coef, double z)
{
    double tail = coef[13].hi;
    for (int j = 12; j >= 0; --j) {
        tail = coef[j].hi + z * tail;
    }
    return tail;
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

void dd_cos_sin_begin(DoubleDouble x, DdCosSin *t)
{
    if (!isfinite(x.hi)) {
        t->y = dd_of(NAN);
        t->quadrant = 0;
        t->sin_x = NAN;
        t->cos_lead = NAN;
        t->cos_lead_certain = 0;
        return;
    }
    double n;
    const DoubleDouble y = reduce_quadrant(x, &n);
    const int quadrant = quadrant_of(n), odd = quadrant & 1;
    t->y = y;
    t->quadrant = quadrant;
    /* cos x is +-cos y for even n, -+sin y for odd n; the other one, the double sin x, as the
     * series in double of sincos_reduced, y + y z P(z) or 1 + z Q(z) with z = (y^2)_hi */
    const double z = dd_mul(y, y).hi;
    const double other = odd ? 1.0 + z * horner_double(COS_COEF, z) : y.hi + y.hi * z * horner_double(SIN_COEF, z);
    t->sin_x = (quadrant == 0 || quadrant == 1) ? other : -other;
    t->point = table_point(y);
    double lead;
    t->cos_lead_certain = table_leading(&t->point, odd, &lead);
    /* cos x = flip (cos y or sin y); table_leading works on |y| and sin is odd */
    const double flip = (quadrant == 1 || quadrant == 2) ? -1.0 : 1.0;
    t->cos_lead = flip * (odd ? t->point.sign * lead : lead);
}

DoubleDouble dd_cos_sin_end(const DdCosSin *t)
{
    if (!isfinite(t->y.hi)) {
        return dd_of(NAN);
    }
    const int odd = t->quadrant & 1;
    const double flip = (t->quadrant == 1 || t->quadrant == 2) ? -1.0 : 1.0;
    DoubleDouble sin_y, cos_y;
    sincos_at(&t->point, odd ? WANT_SIN : WANT_COS, &sin_y, &cos_y);
    const DoubleDouble value = odd ? sin_y : cos_y;
    DoubleDouble cos_x;
    if (DD_LIKELY(t->cos_lead_certain)) {
        /* the same double as flip value.hi (both rounded to nearest), known before it */
        cos_x.hi = t->cos_lead;
        cos_x.lo = flip * ((value.hi - flip * t->cos_lead) + value.lo);
    } else {
        cos_x.hi = flip * value.hi;
        cos_x.lo = flip * value.lo;
    }
    return cos_x;
}

void dd_cos_sin(DoubleDouble x, DoubleDouble *cos_x, double *sin_x)
{
    DdCosSin t;
    dd_cos_sin_begin(x, &t);
    *cos_x = dd_cos_sin_end(&t);
    *sin_x = t.sin_x;
}

DoubleDouble dd_sin(DoubleDouble x)
{
    if (!isfinite(x.hi)) {
        return dd_of(NAN);
    }
    double n;
    const DoubleDouble y = reduce_quadrant(x, &n);
    const int quadrant = quadrant_of(n);
    DoubleDouble sin_y, cos_y;
    sincos_table(y, (quadrant & 1) ? WANT_COS : WANT_SIN, &sin_y, &cos_y);
    switch (quadrant) {
    case 0: return sin_y;
    case 1: return cos_y;
    case 2: return dd_neg(sin_y);
    default: return dd_neg(cos_y);
    }
}
