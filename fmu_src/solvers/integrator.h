/* integrator.h: numerical time integration of the pendulum state y = (theta, omega),
 *   theta' = omega,  omega' = -w0^2 sin(theta)   (no small-angle shortcut).
 *
 * The integrator keeps its own internal solution point, which may lie ahead of the
 * communication point: integrator_advance interpolates (dense output) where the method
 * has it, so communication points never shorten the internal steps. The struct is plain
 * data (no pointers, no heap), so an FMU can copy and serialize it byte for byte, and the
 * step loop allocates nothing.
 *
 * Because the internal step sequence depends only on the initial state, w0sq and tol
 * (never on the output times), every method gives identical values at a given time for
 * any output grid. */
#ifndef PENDULUM_INTEGRATOR_H
#define PENDULUM_INTEGRATOR_H

/* The values of the items of the enumeration Solver (both model descriptions); each has its row
 * in the solver table, SOLVERS in integrator.c, where a new solver is added. */
typedef enum {
    SOLVER_DOPRI5 = 1,      /* adaptive Dormand-Prince 5(4) with dense output */
    SOLVER_RK4 = 2,         /* classic RK4, fixed step derived from the tolerance */
    SOLVER_RKN = 3,         /* adaptive Runge-Kutta-Nystrom 12(10) pair for theta'' = f(theta):
                               the FMU's default (docs/solvers.md, the speed-against-error study) */
    SOLVER_SYMPLECTIC = 4   /* structure-preserving method for long horizons */
} SolverKind;

typedef struct {
    long steps;       /* accepted steps */
    long rejected;    /* rejected steps */
    long rhs_evals;   /* evaluations of the right-hand side (one sin each), plus the other
                         trigonometric evaluations of theta, one count each (a sin/cos pair
                         counts one): the energy projection's cos(theta/2) at t0, its
                         sin/cos(theta/2) pair at every accepted point and at every Newton
                         correction larger than 2e-3 rad (DOPRI5, RKN), RKN's sin/cos of
                         theta0 for its dense output, the symplectic method's cos for its
                         interpolation */
} SolverStats;

#define INTEGRATOR_MAX_STAGES 16

typedef struct {
    SolverKind kind;
    double w0sq;                 /* g / L */
    double w0sq_lo;              /* its low part, g / L - w0sq (integrator_init_gl; 0 from
                                    integrator_init): the right-hand side uses both, so that the
                                    ODE is the one of the doubles g and L (rounded, g/L moved
                                    1 - m by 1e-16, which the period amplifies near the
                                    separatrix) */
    double rtol;                 /* relative tolerance of the local error test: the user's tol
                                    (adaptive methods: scaled near the separatrix and at least
                                    1e-14, integrator.c) */
    double atol[2];              /* absolute tolerances of theta and omega: rtol and rtol w0, the
                                    states in units of 1 rad and of the motion's rate w0 (so the
                                    step rules see only dimensionless numbers: the same steps
                                    for every L and g) */
    double t;                    /* time of the internal solution point: t + t_lo, kept as a
                                    compensated sum of the steps (without it, the rounding of
                                    t += h, ulp(t)/2 a step, is a phase error of 2.5e-9 after
                                    10,000 periods at 90 deg) */
    double t_lo;                 /* low part of that time, |t_lo| <= ulp(t)/2 */
    double y[2];                 /* internal solution (theta, omega) at t */
    double f[2];                 /* y' = (omega, -w0sq sin theta) at (t, y), already counted:
                                    first stage of the next step (FSAL) and end-point slope
                                    for interpolation */
    double rate;                 /* the motion's own angular rate: w0 in libration, sqrt(m) w0
                                    (half the largest speed) in rotation; sets the time scale
                                    of the fixed steps */
    double closeness;            /* distance from the separatrix, |m1| / max(1, m) (at least
                                    INTEGRATOR_REACH / tol): the period's sensitivity to energy
                                    errors grows like 1/closeness there */
    double h;                    /* next step size to try (fixed-step methods: the step) */
    double hmax;                 /* largest step the adaptive methods may take */
    double t_prev, y_prev[2];    /* start of the last accepted step (for dense output) */
    double t_prev_lo;            /* low part of t_prev */
    double f_prev[2];            /* y' at (t_prev, y_prev) */
    double h_last;               /* length of the last accepted step, the h its formulas used
                                    (0 before the first) */
    double err_prev;             /* PI controller: error norm of the last accepted step */
    double energy0;              /* G = omega^2/2 - 2 w0sq cos^2(theta/2) at t0 (if projecting):
                                    the energy H = omega^2/2 + 2 w0sq sin^2(theta/2) measured
                                    from the separatrix, G = H - 2 w0sq, which keeps its
                                    relative accuracy near the top, where H loses it */
    double energy0_lo;           /* low part of energy0 (double-double): rounded to a double, G
                                    near the separatrix is off by ~1e-16 of 2 w0sq, a bias of
                                    1 - m that the period turns into a phase error growing like
                                    1 / (1 - m) (docs/certificate.md) */
    int project_energy;          /* 1: every accepted point is projected back onto G = energy0
                                    (set by integrator_init: DOPRI5 and RKN always, RK4 and the
                                    symplectic method near the separatrix; 0 runs the plain
                                    methods) */
    int last_rejected;           /* the previous step attempt was rejected */
    double dense[INTEGRATOR_MAX_STAGES][2]; /* method-specific dense-output data */
    SolverStats stats;
} Integrator;

/* Smallest tol |1 - m| / max(1, m) (1 - m: the distance from the separatrix) at which a method
 * holds 100 tol over ten periods (measured, docs/certificate.md, tests/c/test_certificate.c):
 * DOPRI5, RKN and the symplectic method (projecting onto the energy near the separatrix) down to
 * 1e-21, where the rounding of the state itself moves the period by more; RK4 down to 1e-19.
 * The FMU's certificate names the line in its warning. */
#define INTEGRATOR_REACH 1e-21
#define INTEGRATOR_REACH_RK4 1e-19

/* The smallest tolerance a Co-Simulation experiment runs at (instance/calls.c runs a smaller
 * one at this floor, with a warning; model.c refuses a state that carries one). Below it the step certificate's bound,
 * 100 tol less the exact port's own error 5e-14 (instance.h), is not the tolerance's
 * (at 1e-15 it would be half of it, at 5e-16 zero), and the solvers do not follow the
 * tolerance: the adaptive methods' local tolerance stops at 1e-14 (INTEGRATOR_MIN_TOL,
 * integrator.c). Measured with mpmath (docs/certificate.md) by a build that sets it lower on
 * the compiler's command line. */
#ifndef INTEGRATOR_TOLERANCE_FLOOR
#define INTEGRATOR_TOLERANCE_FLOOR 1e-14
#endif

/* That line for a method (INTEGRATOR_REACH for an unknown one). */
double integrator_reach(SolverKind kind);

/* The name of a solver, its item in the enumeration Solver ("rkn", ...), or NULL for a value that
 * names none: what integrator_init accepts. The solvers and what each one is: the table SOLVERS
 * in integrator.c. */
const char *integrator_solver_name(int kind);

/* Prepares integration from (theta0, omega0) at t0. tol is the relative tolerance
 * (fmi2SetupExperiment's); w0sq = g / L > 0. Returns 0, or -1 for invalid input.
 * Resets the statistics. */
int integrator_init(Integrator *it, SolverKind kind, double w0sq, double tol,
                    double t0, double theta0, double omega0);

/* The same for the parameters g > 0 and L > 0: w0sq = g / L in double-double. */
int integrator_init_gl(Integrator *it, SolverKind kind, double g, double L, double tol,
                       double t0, double theta0, double omega0);

/* Most internal steps (accepted or rejected) one integrator_advance may take (a fuzzing
 * build may set a smaller one on the command line, so that each of its runs stays short). */
#ifndef INTEGRATOR_MAX_STEPS_PER_ADVANCE
#define INTEGRATOR_MAX_STEPS_PER_ADVANCE 10000000L
#endif

/* Communication points (FMI's currentCommunicationPoint, FMI 3's the same): a master's point
 * may differ from the current time by its own rounding, at most this many ulps of the time. */
#define INTEGRATOR_POINT_ULPS 4.0

/* Outcome of integrator_step_end. */
typedef enum {
    STEP_END_OK = 0,
    STEP_END_BAD_SIZE,      /* the step size is not a finite number > 0 */
    STEP_END_BAD_POINT,     /* the point is not within INTEGRATOR_POINT_ULPS ulps of the time */
    STEP_END_NOT_FINITE,    /* point + step overflows */
    STEP_END_BACKWARDS      /* point + step lies before the current time */
} StepEnd;

/* The time a step from the master's `point` by `step` ends at, given the current `time`: the
 * rule shared by every co-simulation interface (time never goes backwards). Sets *t_end when
 * the answer is STEP_END_OK. */
StepEnd integrator_step_end(double time, double point, double step, double *t_end);

/* Fewest internal steps that reaching t_out can take (the largest step the method may take
 * bounds it from below); 0 if t_out <= the internal time. */
double integrator_min_steps(const Integrator *it, double t_out);

/* Checks an integrator read from untrusted bytes (an FMU state blob) against `fresh`, the
 * integrator that integrator_init makes from the same inputs: the fields fixed at init must
 * equal fresh's, the others lie in their possible ranges (finite, ordered times, step sizes,
 * counts >= 0, flags 0 or 1). Returns NULL, or a message naming the first bad field. */
const char *integrator_check(const Integrator *it, const Integrator *fresh);

/* Advances to t_out >= the last output time and writes the solution at t_out.
 * Returns 0 on success, -1 if the step size underflows or the solution is not finite
 * (or t_out lies before the start of the last internal step, which the contract rules
 * out), -2 if reaching t_out would take more than INTEGRATOR_MAX_STEPS_PER_ADVANCE steps
 * (at once, without stepping, when even integrator_min_steps exceeds it). */
int integrator_advance(Integrator *it, double t_out, double y_out[2]);

#endif
