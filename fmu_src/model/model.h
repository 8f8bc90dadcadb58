/* model.h: the model core shared by the FMI 2.0 and FMI 3.0 layers: the modes of the
 * calling sequence, the variables, their checks and the equations, with no FMI type.
 * Everything an FMU state must capture lives in ModelData, which is plain data (no
 * pointers), so getting an FMU state is a copy and serializing it a byte copy. */
#ifndef PENDULUM_MODEL_H
#define PENDULUM_MODEL_H

#include "exact.h"
#include "integrator.h"

/* States of the calling sequence (FMI 2.0 sections 3.2.3 and 4.2.4, FMI 3.0 section 3.2;
 * MODE_STEP_COMPLETE is FMI 3.0's Step Mode). */
typedef enum {
    MODE_INSTANTIATED = 1 << 0,
    MODE_INITIALIZATION = 1 << 1,
    MODE_EVENT = 1 << 2,           /* Model Exchange */
    MODE_CONTINUOUS_TIME = 1 << 3, /* Model Exchange */
    MODE_STEP_COMPLETE = 1 << 4,   /* Co-Simulation */
    MODE_TERMINATED = 1 << 5,
    MODE_ERROR = 1 << 6
} Mode;

/* The interface an instance serves; the numbers are fmi2Type's (FMU states store them). */
typedef enum {
    INTERFACE_MODEL_EXCHANGE = 0,
    INTERFACE_CO_SIMULATION = 1
} InterfaceType;

/* A value reference as both FMI versions pass it (fmi2ValueReference, fmi3ValueReference). */
typedef unsigned int ValueReference;

/* Start values: must equal the start attributes of both model descriptions (tests check). */
#define START_L 1.0
#define START_G 9.81
#define START_THETA 1.3089969389957472 /* 75 deg */
#define START_OMEGA 0.0
#define START_SOLVER SOLVER_RKN
#define DEFAULT_TOLERANCE 1e-8         /* used when the experiment defines none */

typedef struct {
    Mode mode;
    int interface;              /* an InterfaceType: a state of one interface is refused by
                                   an instance of the other */
    int hard_case_reported;     /* 1 once a step has warned that the numerical solution went
                                   qualitatively wrong (instance/motion.c) */
    double certificate_logged;  /* the departure (in units of the certificate's bound) of the last
                                   step whose certificate was logged; 0 before the first
                                   (instance/certificate.c) */
    double L, g;                /* parameters */
    int solver;                 /* SolverKind */
    double tolerance;           /* relative tolerance of the Co-Simulation solver */
    double start_time;
    double time;                /* current time: ME set by SetTime, CS the communication point */
    double theta, omega;        /* continuous states */
    PendulumExact exact;        /* exact solution through the initial state */
    Integrator integrator;      /* Co-Simulation solver */
} ModelData;

/* The exact state (theta_exact, omega_exact) at the current time, evaluated once by whoever
 * needs it first (the certificate after a DoStep, a GetReal, the output derivatives) and
 * reused while `time` and the exact solution stay the same. It is no part of ModelData, so
 * no part of an FMU state: a restored state recomputes it. The instance owns one beside its
 * ModelData and drops it (model_exact_forget) at every change of time, parameter, start
 * value, state restore and reset. Filled only after initialization, when the exact solution
 * is the one ExitInitializationMode set up; before it every read evaluates afresh. */
typedef struct {
    int valid;                  /* 1: theta and omega are those at `time` */
    double time;
    double theta, omega;
    unsigned long evaluations;  /* exact evaluations made for this instance (never reset):
                                   tests count them, one per time */
} ExactCache;

/* Drops the cached exact state (the count of evaluations stays). */
void model_exact_forget(ExactCache *cache);

/* theta_exact and omega_exact at data->time, from the cache or evaluated once and kept.
 * NULL, or why there is no such value (the time is not resolvable, the start values or
 * parameters cannot set up an exact solution). The values are pendulum_exact_eval's, bit for
 * bit. */
const char *model_exact_now(const ModelData *data, ExactCache *cache, double *theta, double *omega);

/* Sets start values (the just-instantiated state) for an instance of the given interface. */
void model_reset(ModelData *data, InterfaceType type);

/* Checks a ModelData read from untrusted bytes (a set or deserialized FMU state) for an
 * instance of interface `type`: every field in the range it can have, the exact solution
 * and the solver exactly what their recorded start values make. NULL, or the reason. */
const char *model_check_state(const ModelData *data, InterfaceType type);

/* Validates parameters and states, then sets up the exact solution and the solver.
 * Returns NULL on success, otherwise a message naming what is wrong. */
const char *model_initialize(ModelData *data, InterfaceType type);

/* Variable access by value reference; each returns NULL or an error message. theta_exact and
 * omega_exact come through the cache (model_exact_now). */
const char *model_get_real(const ModelData *data, ExactCache *cache, ValueReference vr, double *value);
const char *model_set_real(ModelData *data, ValueReference vr, double value);
const char *model_get_integer(const ModelData *data, ValueReference vr, int *value);
const char *model_set_integer(ModelData *data, ValueReference vr, int value);

/* Right-hand side: der(theta) = omega, der(omega) = -(g/L) sin(theta).
 * Returns NULL, or a message if g / L is not a finite positive number. */
const char *model_derivatives(const ModelData *data, double *der_theta, double *der_omega);

/* The mode's name in the standard of that FMI version (2 or 3). */
const char *mode_name(Mode mode, int fmi_version);

/* The variable's name in the model descriptions, or "(unknown)". */
const char *variable_name(ValueReference vr);

#endif
