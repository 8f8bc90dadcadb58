/* instance.h: one FMU instance and every FMI call's work, written once for both FMI
 * versions. The layers in fmi2/ and fmi3/ only translate types and arguments: each
 * instance_* call below takes the name of the FMI function it serves (for its messages),
 * checks the calling sequence and the arguments, logs a refusal with its reason, and returns
 * a Status whose numbers are those of fmi2Status and fmi3Status. */
#ifndef PENDULUM_INSTANCE_H
#define PENDULUM_INSTANCE_H

#include <stddef.h>

#include "model.h"

/* fmi2Status and fmi3Status share these numbers (FMI 2.0 2.1.3, FMI 3.0 2.2.3). */
typedef enum {
    STATUS_OK = 0,
    STATUS_WARNING = 1,
    STATUS_DISCARD = 2,
    STATUS_ERROR = 3,
    STATUS_FATAL = 4
} Status;

/* Log categories as declared in both model descriptions' <LogCategories>. */
typedef enum {
    LOG_STATUS_ERROR = 0,
    LOG_STATUS_WARNING = 1,
    LOG_CALLS = 2,
    LOG_CATEGORY_COUNT = 3
} LogCategory;

typedef struct Instance Instance;
typedef struct StateNode StateNode; /* an FMU state handed out (instance/state.c) */

/* What an FMU state of a model holds beyond the instance's ModelData, and how a state handed
 * back is checked (instance/state.c). A state is ModelData followed by `extra_size` bytes that
 * lie `extra_offset` bytes into the layer's instance (the split FMUs' input polynomial), and a
 * serialized state starts with `magic`, so a blob of another model is refused. An Instance
 * whose state_model is NULL is Pendulum.fmu's: ModelData alone, checked by model_check_state. */
#define STATE_EXTRA_MAX 64
typedef struct {
    const char *magic;  /* 8 characters */
    size_t extra_size;  /* at most STATE_EXTRA_MAX */
    size_t extra_offset;
    /* NULL, or why `inst` refuses the state: data and extra are untrusted copies */
    const char *(*check)(const Instance *inst, const ModelData *data, const void *extra);
} StateModel;

/* What the FMI layer supplies: its host's logger and memory, behind one signature, and a
 * pointer to the host's callbacks, so that one set of these functions serves every layer of
 * an FMI version (fmi2/host2.h, fmi3/layer.h) whatever its instance type. */
typedef struct {
    void (*log)(const Instance *inst, Status status, const char *category, const char *message);
    void *(*allocate)(const Instance *inst, size_t size); /* zeroed memory, or NULL */
    void (*release)(const Instance *inst, void *memory);
    const void *context; /* the layer's own: where it keeps its host's callbacks */
} InstanceHost;

struct Instance {
    ModelData data;
    InterfaceType type;
    int fmi_version;         /* 2 or 3: the names of modes in messages, FMI 3.0's `time` */
    char *name;
    InstanceHost host;
    int log_enabled[LOG_CATEGORY_COUNT];
    StateNode *states;       /* the FMU states this instance handed out and has not freed:
                                the registry FreeFMUstate checks a pointer against */
    const StateModel *state_model; /* what its FMU states hold; NULL: Pendulum.fmu's */
    ExactCache exact_now;    /* theta_exact, omega_exact at data.time, evaluated once (model.h):
                                beside data, so no part of an FMU state; every call that changes
                                the time, a value or the whole data drops it */
    int certificate_off;     /* 1: DoStep skips the certificate (instance/certificate.c). No FMI
                                call sets it: only C tests that link the core, to show that the
                                certificate changes no number (tests/c/test_certificate.c) */
};

/* Instantiation checks shared by every Instantiate: NULL, or why the instance is refused. */
const char *instance_refusal(const char *name, const char *token);

/* Fills a zeroed Instance (allocated by the layer, host set): copies the name, sets the log
 * switches and the start values. Returns 0, or -1 when out of memory. */
int instance_setup(Instance *inst, const char *name, InterfaceType type, int fmi_version, int logging_on);

/* Frees the FMU states still live and the name; the layer frees the instance itself
 * (instance/calls.c). */
void instance_release(Instance *inst);

/* Logs through the host's logger if the category is enabled. */
void instance_log(const Instance *inst, Status status, LogCategory category, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Puts the instance into MODE_ERROR after logging why; returns STATUS_ERROR. */
Status instance_fail(Instance *inst, const char *function, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* The FMI functions, grouped by what the shared core does for them: each has one row in the
 * table of the modes in which it is allowed, CALL_RULES in instance.c (the FMI 2.0 and 3.0
 * functions of each row are named there). A layer's function passes its row to the instance_*
 * call that does its work, or checks it with instance_call_allowed first. */
typedef enum {
    CALL_SET_DEBUG_LOGGING,
    CALL_SETUP_EXPERIMENT,
    CALL_ENTER_INITIALIZATION,
    CALL_EXIT_INITIALIZATION,
    CALL_TERMINATE,
    CALL_RESET,
    CALL_GET_VARIABLES,
    CALL_SET_VARIABLES,
    CALL_GET_FMU_STATE,
    CALL_SET_FMU_STATE,
    CALL_FREE_FMU_STATE,
    CALL_SERIALIZED_FMU_STATE_SIZE,
    CALL_SERIALIZE_FMU_STATE,
    CALL_DESERIALIZE_FMU_STATE,
    CALL_PARTIAL_DERIVATIVES,
    CALL_NOT_PROVIDED,
    CALL_ENTER_EVENT_MODE,
    CALL_ENTER_CONTINUOUS_TIME_MODE,
    CALL_UPDATE_DISCRETE_STATES,
    CALL_COMPLETED_INTEGRATOR_STEP,
    CALL_SET_TIME,
    CALL_SET_CONTINUOUS_STATES,
    CALL_GET_DERIVATIVES,
    CALL_GET_EVENT_INDICATORS,
    CALL_GET_CONTINUOUS_STATES,
    CALL_GET_NOMINALS,
    CALL_GET_NUMBER_OF,
    CALL_DO_STEP,
    CALL_SET_INPUT_DERIVATIVES,
    CALL_GET_OUTPUT_DERIVATIVES,
    CALL_CANCEL_STEP,
    CALL_GET_STATUS,
    CALL_ENTER_STEP_MODE,
    CALL_COUNT
} FmiCall;

/* 1 if inst is non-NULL, of an interface that has the call, and in one of the modes where its
 * row allows it (then the call is traced under logCalls); otherwise logs why ("<function> is a
 * Model Exchange function; ...", "<function>: not allowed in state <mode>"), puts a live
 * instance into the Error state and returns 0. */
int instance_call_allowed(Instance *inst, const char *function, FmiCall call);

/* --- life cycle and variables (instance/calls.c) ------------------------------------------ */
Status instance_set_debug_logging(Instance *inst, const char *function, int logging_on, size_t n,
                                  const char *const categories[]);
Status instance_setup_experiment(Instance *inst, const char *function, int tolerance_defined, double tolerance,
                                 double start_time, int stop_time_defined, double stop_time);
Status instance_enter_initialization(Instance *inst, const char *function);
/* Both in one call, checked and logged once (FMI 3.0's fmi3EnterInitializationMode). */
Status instance_enter_initialization_with(Instance *inst, const char *function, int tolerance_defined,
                                          double tolerance, double start_time, int stop_time_defined,
                                          double stop_time);
Status instance_exit_initialization(Instance *inst, const char *function);
Status instance_terminate(Instance *inst, const char *function);
Status instance_reset(Instance *inst, const char *function);
Status instance_get_reals(Instance *inst, const char *function, const ValueReference vr[], size_t nvr, double value[]);
Status instance_set_reals(Instance *inst, const char *function, const ValueReference vr[], size_t nvr,
                          const double value[]);
/* Integer and Enumeration variables; the layer converts to and from its integer type. */
Status instance_get_integer(Instance *inst, const char *function, ValueReference vr, long *value);
Status instance_set_integer(Instance *inst, const char *function, ValueReference vr, long value);
/* Checks the arrays of a Get/Set call: vr and values non-NULL when nvr > 0. */
int instance_arrays_allowed(Instance *inst, const char *function, FmiCall call, const ValueReference vr[],
                            size_t nvr, const void *values);
/* Get/Set of a type the model has no variable of: every value reference is unknown. */
Status instance_no_variables(Instance *inst, const char *function, FmiCall call, const ValueReference vr[],
                             size_t nvr, const void *values);

/* --- Model Exchange and Co-Simulation (instance/motion.c) ---------------------------------- */
#define N_STATES 2
Status instance_enter_event_mode(Instance *inst, const char *function);
Status instance_enter_continuous_time_mode(Instance *inst, const char *function);
Status instance_new_discrete_states(Instance *inst, const char *function, int any_pointer_null);
Status instance_completed_integrator_step(Instance *inst, const char *function, int *enter_event_mode,
                                          int *terminate_simulation);
Status instance_set_time(Instance *inst, const char *function, double time);
Status instance_set_states(Instance *inst, const char *function, const double x[], size_t nx);
Status instance_get_state_derivatives(Instance *inst, const char *function, double derivatives[], size_t nx);
Status instance_get_states(Instance *inst, const char *function, double x[], size_t nx);
Status instance_get_nominals(Instance *inst, const char *function, double nominals[], size_t nx);
Status instance_get_event_indicators(Instance *inst, const char *function, double indicators[], size_t ni);
/* A communication step from `point` by `step` (FMI 2.0 4.2.2, FMI 3.0 4.2.1). */
Status instance_do_step(Instance *inst, const char *function, double point, double step);

/* --- the certificate of a Co-Simulation step (instance/certificate.c) --------------------- */
/* OK certifies that the true error is within the bound: |theta - theta(t)| <=
 * CERTIFICATE_FACTOR tol max(1, |theta_exact|) and |omega - omega(t)| <= CERTIFICATE_FACTOR tol
 * max(w0, |omega_exact|), theta(t), omega(t) the pendulum's true motion. The step compares with
 * the exact port, whose own error is at most CERTIFICATE_EXACT_ERROR in the same units, so it
 * asks |theta - theta_exact| <= (CERTIFICATE_FACTOR tol - CERTIFICATE_EXACT_ERROR) max(1,
 * |theta_exact|) (and the same for omega): by the triangle inequality the true error is then
 * within the bound. Co-Simulation runs a tolerance below INTEGRATOR_TOLERANCE_FLOOR
 * (integrator.h), where the reduced bound would no longer be the tolerance's, at the floor,
 * with a warning (instance/calls.c). */
#define CERTIFICATE_FACTOR 100.0
/* The exact port's error bound relative to max(1, |theta|) and max(w0, |omega|): what
 * tests/exact/test_exact_mpmath.py and tests/exact/test_exact_properties.py assert against mpmath at 50
 * digits in every regime (5e-14; measured worst 8.6e-15, docs/math.md). */
#define CERTIFICATE_EXACT_ERROR 5e-14
/* The bound's factor at tolerance tol: CERTIFICATE_FACTOR tol - CERTIFICATE_EXACT_ERROR. */
double certificate_factor(double tolerance);
/* The departure of (theta, omega) from the exact state (theta_exact, omega_exact) at the same
 * time, in units of the bound: the larger of the two ratios (<= 1: certified; +inf where the
 * state is not finite). The step reads the exact state from the instance's exact_now. */
double certificate_ratio(double w0, double tolerance, double theta, double omega, double theta_exact,
                         double omega_exact);
/* 1 if the solver holds the bound over ten periods for a motion of parameter m (m1 = 1 - m from
 * its cosine form) at this tolerance: tol |1 - m| / max(1, m) >= integrator_reach(solver). */
int certificate_reachable(int solver, double tolerance, double m1, double m);
/* After a DoStep has moved the state to data.time: the certificate (unless certificate_off) and
 * the hard-case check, their messages, and the step's status (OK or WARNING). */
Status instance_check_step(Instance *inst);

/* --- FMU states (instance/state.c) --------------------------------------------------------- */
Status instance_get_state(Instance *inst, const char *function, void **state);
Status instance_set_state(Instance *inst, const char *function, const void *state);
/* Frees *state only if it is one of this instance's live states (the registry), else refuses it. */
Status instance_free_state(Instance *inst, const char *function, void **state);
/* Frees every state still live (from instance_release). */
void instance_release_states(Instance *inst);
Status instance_serialized_state_size(Instance *inst, const char *function, const void *state, size_t *size);
Status instance_serialize_state(Instance *inst, const char *function, const void *state, char bytes[], size_t size);
Status instance_deserialize_state(Instance *inst, const char *function, const char bytes[], size_t size,
                                  void **state);

/* --- partial derivatives (instance/derivatives.c) ------------------------------------------ */
/* Directional (sensitivity = J seed) or, with adjoint = 1, adjoint (sensitivity = seed^T J)
 * derivatives of the unknowns by the knowns, J exact from the equations. */
Status instance_partials(Instance *inst, const char *function, int adjoint, const ValueReference unknowns[],
                         size_t n_unknowns, const ValueReference knowns[], size_t n_knowns, const double seed[],
                         double sensitivity[]);
/* The highest order instance_output_derivatives gives (maxOutputDerivativeOrder). */
#define MAX_OUTPUT_DERIVATIVE_ORDER 3
/* Time derivatives of the Co-Simulation outputs at the current communication point. */
Status instance_output_derivatives(Instance *inst, const char *function, const ValueReference vr[], size_t nvr,
                                   const int order[], double value[]);

#endif
