/* exact.h: the analytic solution of theta'' + w0^2 sin(theta) = 0 for any initial state.
 *
 * Regimes (documentation/math.html): libration (m < 1), separatrix (m1 == 0), rotation (m > 1),
 * with m = sin^2(theta0/2) + (omega0/(2 w0))^2 and m1 = cos^2(theta0/2) - (omega0/(2 w0))^2.
 * All constants are computed once by the set-up (pendulum_exact_init_gl from g and L, as the
 * FMU and pendulum_exact_lib do, or pendulum_exact_init from w0); an evaluation is one argument
 * reduction and one sn/cn/dn call. The struct is plain data (no pointers), so an FMU can
 * copy and serialize it byte for byte. On a processor with an fma, init, init_gl, eval,
 * eval_many, once_gl_many and sin_cos run a second build of the same sources that forms its
 * exact two-products with the fma (exact_fma.h): the same bits, fewer operations; its
 * once_gl_many sets up and evaluates four new librations at once in AVX vectors. */
#ifndef PENDULUM_EXACT_H
#define PENDULUM_EXACT_H

#include <stddef.h>

#include "elliptic.h"

typedef enum {
    PENDULUM_LIBRATION = 0,
    PENDULUM_SEPARATRIX = 1,
    PENDULUM_ROTATION = 2
} PendulumRegime;

typedef struct {
    PendulumRegime regime;
    double w0, w0_lo;     /* sqrt(g / L), rad/s, in double-double */
    double g, L;          /* the parameters it was set up from (0, 0: set up from w0) */
    double t0;            /* time at which the initial state is posed */
    double theta0;        /* the initial angle as given */
    double omega0;        /* the initial angular velocity as given */
    double m, m1;         /* elliptic parameter of the motion and its complement (m1 from the
                             cosine form): m < 1 libration, m1 == 0 separatrix, m > 1 rotation */
    double k, kc;         /* modulus and complementary modulus of the parameter the Jacobi
                             functions are taken at: sqrt(m), sqrt(m1) (libration);
                             1/sqrt(m), sqrt(-m1/m) (rotation) */
    double K_hi, K_lo;    /* complete integral of that parameter, double-double (+inf on the
                             separatrix) */
    double u0;            /* initial phase of the elliptic argument */
    double scale;         /* rate of the elliptic argument: w0 (libration, separatrix),
                             sqrt(m) w0 (rotation) */
    double scale_lo;      /* low part of that rate in double-double (0 when it is w0 itself) */
    double rho_hi, rho_lo;     /* scale / K in double-double: quarter periods per second */
    double rho_head, rho_tail; /* rho_hi = head (26 bits) + tail (27 bits), for the exact
                                  product rho * t of every evaluation (Dekker) */
    double x0_hi, x0_lo;  /* u0 / K in double-double: initial phase in quarter periods */
    double direction;     /* sign of the motion for separatrix and rotation (+1 for libration;
                             0 at rest on the unstable equilibrium) */
    double omega_half;    /* half the amplitude of omega: k w0 (libration), sqrt(m) w0
                             (rotation), w0 (separatrix); omega = 2 (omega_half ...) */
    double sqrt_k1;       /* libration: sqrt of the first Landen modulus, k / (1 + k') */
    double period;        /* pendulum_exact_period's value, computed in init */
    double theta_turns;   /* theta0 = 2 pi theta_turns + reduced theta0 in (-pi, pi] */
    double theta_reduced; /* that reduced theta0 */
    EllipticParam ell;    /* Landen chain and K of the parameter (plain data) */
} PendulumExact;

/* Sets up the solution through (theta0, omega0) at time t0 for w0 > 0 as the double given.
 * Returns 0 on success, -1 if an input is not finite or w0 <= 0 (ex is then untouched).
 * For callers that pose w0 itself, as the C tests' tables (references at a binary w0, the
 * separatrix at omega0 = 2 w0 exactly) and the benchmarks do; the FMU calls only
 * pendulum_exact_init_gl (its g and L give w0 only as a double-double). */
int pendulum_exact_init(PendulumExact *ex, double theta0, double omega0, double w0, double t0);

/* The same for the parameters g > 0 and L > 0 as given: w0 = sqrt(g / L) is formed in
 * double-double, so the solution is the one of theta'' = -(g/L) sin theta for these two
 * doubles (no rounding of g/L or of its root moves the state across the separatrix).
 * Returns -1 for a non-finite input, g or L <= 0, or g / L not a normal double's range. */
int pendulum_exact_init_gl(PendulumExact *ex, double theta0, double omega0, double g, double L, double t0);

/* 1 if *ex is exactly (bytewise) what pendulum_exact_init_gl sets up from its own recorded
 * inputs (theta0, omega0, g, L, t0), 0 otherwise (also for a solution set up from w0 by
 * pendulum_exact_init, which the FMU never makes): the check of a solution read from
 * untrusted bytes (an FMU state blob), which so can never carry a field out of its range. */
int pendulum_exact_same(const PendulumExact *ex);

/* Most quarter periods from t0 at which the phase is resolved: the rate is held in
 * double-double (~2^-102 relative), so at 2^60 quarter periods the phase is still known to
 * ~2^-42 of a quarter period (~1e-13 rad). */
#define PENDULUM_EXACT_MAX_QUARTERS 0x1p60

/* 1 if t is finite and within PENDULUM_EXACT_MAX_QUARTERS quarter periods of t0 (always on
 * the separatrix and at rest), 0 otherwise; pendulum_exact_eval gives NaN where this is 0. */
int pendulum_exact_resolvable(const PendulumExact *ex, double t);

/* theta(t) and omega(t) of the exact solution; theta is continuous (winds up in rotation).
 * At t == t0 exactly (theta0, omega0) as given. NaN where pendulum_exact_resolvable is 0. */
void pendulum_exact_eval(const PendulumExact *ex, double t, double *theta, double *omega);

/* sin(theta(t)) and cos(theta(t)) of the exact solution, formed from the Jacobi functions of
 * the half angle (libration: sin(theta/2) = k sn u, cos(theta/2) = dn u; rotation: sin and
 * cos of am v = sn v, cn v; separatrix: tanh u, sech u), not from the rounded theta: near the
 * top and after many turns they keep their own relative accuracy. At t == t0 (and at rest on
 * the top) sin and cos of theta0 as given; NaN where pendulum_exact_resolvable is 0. */
void pendulum_exact_sin_cos(const PendulumExact *ex, double t, double *sin_theta, double *cos_theta);

/* theta[i], omega[i] = pendulum_exact_eval(ex, t[i], ...) for i < n, bit for bit the same,
 * with several points of a libration evaluated in lock-step (faster per point than the loop
 * over pendulum_exact_eval). The arrays must not overlap. */
void pendulum_exact_eval_many(const PendulumExact *ex, size_t n, const double *t, double *theta,
                              double *omega);

/* For i < n: theta[i], omega[i] of the solution pendulum_exact_init_gl(theta0[i], omega0[i],
 * g[i], L[i], t0) sets up, at t[i], bit for bit what that set-up and pendulum_exact_eval
 * give (NaN for refused inputs): many new states, each evaluated once, without their
 * set-ups written (in the fma build four releases from rest, or four moving starts, at once
 * in vectors; eight with AVX-512F). The outputs must not overlap the inputs (a chunk's moving
 * starts are read after its releases from rest are written). Returns the number of elements
 * whose inputs were refused or whose time is not resolvable. */
size_t pendulum_exact_once_gl_many(size_t n, const double *theta0, const double *omega0, const double *g,
                                   const double *L, double t0, const double *t, double *theta, double *omega);

/* Compares a numerical state (theta, omega) at some time with the exact motion, qualitatively:
 * NULL if it is the same kind of motion, else what went wrong, as a phrase:
 * "carried the libration over the top" (exact libration, |theta - its centre| > pi + 0.5),
 * "reversed the rotation" (exact rotation, omega of the other sign),
 * "went over the top past the separatrix" / "fell back from the separatrix" (on it). */
const char *pendulum_exact_qualitative_miss(const PendulumExact *ex, double theta, double omega);

/* Period of the motion in seconds: 4 K(m) / w0 for libration, the time of one revolution
 * 2 K(1/m) / (sqrt(m) w0) for rotation, and +INFINITY on the separatrix. */
double pendulum_exact_period(const PendulumExact *ex);

#endif
