/* exact.h: the analytic solution of theta'' + w0^2 sin(theta) = 0 for any initial state.
 *
 * Regimes (documentation/math.html): libration (m < 1), separatrix (m1 == 0), rotation (m > 1),
 * with m = sin^2(theta0/2) + (omega0/(2 w0))^2 and m1 = cos^2(theta0/2) - (omega0/(2 w0))^2.
 * All constants are computed once by pendulum_exact_init; an evaluation is one argument
 * reduction and one sn/cn/dn call. The struct is plain data (no pointers), so an FMU can
 * copy and serialize it byte for byte. */
#ifndef PENDULUM_EXACT_H
#define PENDULUM_EXACT_H

#include "elliptic.h"

typedef enum {
    PENDULUM_LIBRATION = 0,
    PENDULUM_SEPARATRIX = 1,
    PENDULUM_ROTATION = 2
} PendulumRegime;

typedef struct {
    PendulumRegime regime;
    double w0;            /* sqrt(g / L), rad/s */
    double t0;            /* time at which the initial state is posed */
    double theta0;        /* the initial angle as given */
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

/* Sets up the solution through (theta0, omega0) at time t0 for w0 > 0.
 * Returns 0 on success, -1 if an input is not finite or w0 <= 0 (ex is then untouched). */
int pendulum_exact_init(PendulumExact *ex, double theta0, double omega0, double w0, double t0);

/* theta(t) and omega(t) of the exact solution; theta is continuous (winds up in rotation). */
void pendulum_exact_eval(const PendulumExact *ex, double t, double *theta, double *omega);

/* Period of the motion in seconds: 4 K(m) / w0 for libration, the time of one revolution
 * 2 K(1/m) / (sqrt(m) w0) for rotation, and +INFINITY on the separatrix. */
double pendulum_exact_period(const PendulumExact *ex);

#endif
