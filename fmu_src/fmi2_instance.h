/* fmi2_instance.h: one FMU instance, its FMI 2.0 state machine, logging and variables.
 * Everything an FMU state must capture lives in ModelData, which is plain data (no
 * pointers), so fmi2GetFMUstate is a copy and serialization a byte copy. */
#ifndef PENDULUM_FMI2_INSTANCE_H
#define PENDULUM_FMI2_INSTANCE_H

#include "fmi2_api.h"
#include "exact.h"
#include "integrator.h"

/* FMI 2.0 states of the calling sequence (sections 3.2.3 and 4.2.4). */
typedef enum {
    MODE_INSTANTIATED = 1 << 0,
    MODE_INITIALIZATION = 1 << 1,
    MODE_EVENT = 1 << 2,           /* Model Exchange */
    MODE_CONTINUOUS_TIME = 1 << 3, /* Model Exchange */
    MODE_STEP_COMPLETE = 1 << 4,   /* Co-Simulation */
    MODE_TERMINATED = 1 << 5,
    MODE_ERROR = 1 << 6
} Mode;

/* Log categories as declared in modelDescription.xml <LogCategories>. */
typedef enum {
    LOG_STATUS_ERROR = 0,
    LOG_STATUS_WARNING = 1,
    LOG_CALLS = 2,
    LOG_CATEGORY_COUNT = 3
} LogCategory;

/* Start values: must equal the start attributes of modelDescription.xml (a test checks). */
#define START_L 1.0
#define START_G 9.81
#define START_THETA 1.3089969389957472 /* 75 deg */
#define START_OMEGA 0.0
#define START_SOLVER SOLVER_RKN
#define DEFAULT_TOLERANCE 1e-8         /* used when fmi2SetupExperiment defines none */

typedef struct {
    Mode mode;
    int interface;              /* fmi2ModelExchange or fmi2CoSimulation: a state of one
                                   interface is refused by an instance of the other */
    int hard_case_reported;     /* 1 once fmi2DoStep has warned that the numerical solution
                                   went qualitatively wrong (fmi2_cosim.c) */
    double L, g;                /* parameters */
    int solver;                 /* SolverKind */
    double tolerance;           /* relative tolerance of the Co-Simulation solver */
    double start_time;
    double time;                /* current time: ME set by fmi2SetTime, CS the communication point */
    double theta, omega;        /* continuous states */
    PendulumExact exact;        /* exact solution through the initial state */
    Integrator integrator;      /* Co-Simulation solver */
} ModelData;

typedef struct {
    ModelData data;
    fmi2Type type;
    char *name;
    fmi2CallbackFunctions callbacks;
    int log_enabled[LOG_CATEGORY_COUNT];
} Instance;

/* The category of a name declared in <LogCategories>, or -1. */
int log_category_from_name(const char *name);

/* Logs through the host's logger if the category is enabled. */
void instance_log(const Instance *inst, fmi2Status status, LogCategory category, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Returns 1 if inst is non-NULL and in one of the allowed modes; otherwise logs
 * "<function>: not allowed in <mode>" and, for a live instance, returns 0. */
int instance_allowed(Instance *inst, const char *function, unsigned allowed_modes);

/* The same for a function of one interface only (FMI 2.0 3.2 Model Exchange, 4.2
 * Co-Simulation): an instance of the other interface refuses it with a logged reason. */
int instance_allowed_for(Instance *inst, const char *function, fmi2Type type, unsigned allowed_modes);

/* Puts the instance into MODE_ERROR after logging why; returns fmi2Error. */
fmi2Status instance_fail(Instance *inst, const char *function, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Sets start values (the just-instantiated state) for an instance of the given interface. */
void model_reset(ModelData *data, fmi2Type type);

/* Checks a ModelData read from untrusted bytes (fmi2SetFMUstate, fmi2DeSerializeFMUstate) for
 * an instance of interface `type`: every field in the range it can have, the exact solution
 * and the solver exactly what their recorded start values make. NULL, or the reason. */
const char *model_check_state(const ModelData *data, fmi2Type type);

/* Validates parameters and states, then sets up the exact solution and the solver.
 * Returns NULL on success, otherwise a message naming what is wrong. */
const char *model_initialize(ModelData *data, fmi2Type type);

/* Variable access by value reference; each returns NULL or an error message. */
const char *model_get_real(const ModelData *data, fmi2ValueReference vr, double *value);
const char *model_set_real(ModelData *data, fmi2ValueReference vr, double value);
const char *model_get_integer(const ModelData *data, fmi2ValueReference vr, int *value);
const char *model_set_integer(ModelData *data, fmi2ValueReference vr, int value);

/* Right-hand side: der(theta) = omega, der(omega) = -(g/L) sin(theta).
 * Returns NULL, or a message if g / L is not a finite positive number. */
const char *model_derivatives(const ModelData *data, double *der_theta, double *der_omega);

const char *mode_name(Mode mode);

/* The variable's name in modelDescription.xml, or "(unknown)". */
const char *variable_name(fmi2ValueReference vr);

#endif
