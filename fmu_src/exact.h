/* exact.h: the analytic solution of theta'' + w0^2 sin(theta) = 0 for any initial state.
 *
 * Regimes (pendulum-math.md): libration (m < 1), separatrix (m1 == 0), rotation (m > 1),
 * with m = sin^2(theta0/2) + (omega0/(2 w0))^2 and m1 = cos^2(theta0/2) - (omega0/(2 w0))^2.
 * All constants are computed once by pendulum_exact_init; an evaluation is one argument
 * reduction and one sn/cn/dn call. The struct is plain data (no pointers), so an FMU can
 * copy and serialize it byte for byte. */
#ifndef PENDULUM_EXACT_H
#define PENDULUM_EXACT_H

typedef enum {
    PENDULUM_LIBRATION = 0,
    PENDULUM_SEPARATRIX = 1,
    PENDULUM_ROTATION = 2
} PendulumRegime;

typedef struct {
    PendulumRegime regime;
    double w0;          /* sqrt(g / L), rad/s */
    double t0;          /* time at which the initial state is posed */
    double m, m1;       /* elliptic parameter and its complement (m1 from the cosine form) */
    double k, kc;       /* modulus sqrt(m) and complementary modulus sqrt(m1) (libration) */
    double K_hi, K_lo;  /* complete integral of the motion's parameter, double-double */
    double u0;          /* initial phase of the elliptic argument */
    double scale;       /* rate of the elliptic argument: w0 (libration), sqrt(m) w0 (rotation) */
    double direction;   /* +1 or -1: sign of the motion for separatrix and rotation */
    double theta_offset;/* multiple of 2 pi removed from theta0, added back on evaluation */
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
