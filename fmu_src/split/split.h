/* split.h: the split pendulum, two Co-Simulation FMUs built on the one instance of
 * Pendulum.fmu (instance.h) and its model core (model.h):
 *
 *   PendulumBody     input alpha; states theta, omega with theta' = omega, omega' = alpha;
 *                    outputs theta, omega and the exact solution of the whole pendulum
 *   PendulumGravity  input theta; output alpha = -(g/L) sin(theta)
 *
 * Coupled (Body.theta -> Gravity.theta, Gravity.alpha -> Body.alpha) they are the pendulum
 * theta'' + (g/L) sin(theta) = 0. Each binary links split.c (what both FMUs share: the input
 * as FMI defines it over a step, variable access, the step, the output derivatives, all
 * FMI-free) with one model file, body.c or gravity.c, which defines the split_model_* functions
 * below, and with one layer, layer2.c (FMI 2.0) or layer3.c (FMI 3.0), which only translates
 * types. The calling sequence, logging and the experiment are the shared instance's. */
#ifndef PENDULUM_SPLIT_H
#define PENDULUM_SPLIT_H

#include <stddef.h>

#include "instance.h"

/* Value references: those Body and Gravity share with Pendulum.fmu keep Pendulum's numbers
 * (L 1, g 2, theta 3, der(theta) 4, omega 5, der(omega) 6, theta_exact 7, omega_exact 8), so the
 * model core serves them; alpha is new. FMI 3.0's `time` is 0. */
#define SPLIT_VR_TIME 0u
#define SPLIT_VR_L 1u
#define SPLIT_VR_G 2u
#define SPLIT_VR_THETA 3u
#define SPLIT_VR_DER_THETA 4u
#define SPLIT_VR_OMEGA 5u
#define SPLIT_VR_DER_OMEGA 6u
#define SPLIT_VR_THETA_EXACT 7u
#define SPLIT_VR_OMEGA_EXACT 8u
#define SPLIT_VR_ALPHA 16u

/* The highest input derivative a master may set (fmi2SetRealInputDerivatives): the input is
 * a polynomial of degree <= 2 over a communication step. */
#define SPLIT_MAX_INPUT_ORDER 2

/* The input as the FMU sees it at the current time `data.time`: its value and first two time
 * derivatives. Over a step of size h from there the input is
 *     u(t + s) = value + d1 s + d2 s^2 / 2,   0 <= s <= h,
 * held (d1 = d2 = 0) unless the master set derivatives (FMI 2.0 only). A step moves the
 * polynomial to its end (value = u(t + h), d1 = u'(t + h)): the input the FMU extrapolates
 * until the master sets the value or a derivative again. */
typedef struct {
    double value, d1, d2;
} InputPolynomial;

typedef struct {
    Instance core;          /* first: a SplitInstance is an Instance */
    InputPolynomial input;
} SplitInstance;

/* --- what each model file (body.c, gravity.c) defines -------------------------------------- */
extern const char *const SPLIT_MODEL_NAME;   /* "PendulumBody", "PendulumGravity" */
extern const char *const SPLIT_TOKEN;        /* the GUID / instantiation token */
extern const ValueReference SPLIT_INPUT_VR;  /* the one input */
extern const double SPLIT_INPUT_START;       /* its start value */
/* maxOutputDerivativeOrder of this FMU in FMI version 2 or 3. */
int split_model_max_output_order(int fmi_version);
/* The variable's name in the model description, or "(unknown)". */
const char *split_model_variable_name(ValueReference vr);
/* Variables other than the input and `time`: NULL, or why not. */
const char *split_model_get_real(SplitInstance *inst, ValueReference vr, double *value);
const char *split_model_set_real(SplitInstance *inst, ValueReference vr, double value);
/* At ExitInitializationMode, after the mode check: NULL, or why the values are refused. */
const char *split_model_initialize(SplitInstance *inst);
/* Moves the model's states over a step of size h with the input polynomial (before the
 * polynomial itself moves); time is moved by the caller. */
void split_model_advance(SplitInstance *inst, double h);
/* The order-th time derivative (1 <= order <= max) of output vr at the current time. */
const char *split_model_output_derivative(SplitInstance *inst, ValueReference vr, int order, double *value);
/* The 8 characters that mark a serialized FMU state of this model (split.c's StateModel). */
extern const char SPLIT_STATE_MAGIC[];
/* The model's part of the check of an FMU state (split.c), for a state past the checks both
 * FMUs share: NULL, or why the exact solution, the solver or a state variable is not one this
 * model can have. */
const char *split_model_check_state(const ModelData *data, const ModelData *reset);

/* --- shared by both FMUs (split.c), for the layers ----------------------------------------- */
/* NULL, or why an instantiation is refused (name, token). */
const char *split_refusal(const char *name, const char *token);
/* instance_setup, then the input at its start value. 0, or -1 when out of memory. */
int split_setup(SplitInstance *inst, const char *name, int fmi_version, int logging_on);
Status split_exit_initialization(SplitInstance *inst, const char *function);

/* Whether the experiment's tolerance is passed on to the core: the split FMUs run no solver
 * (Body integrates its input in closed form), so a valid tolerance below the core's
 * certificate floor (INTEGRATOR_TOLERANCE_FLOOR) means nothing to them and is not passed on;
 * one outside (0, 1) is, to be refused with the core's reason. */
int split_tolerance_defined(int tolerance_defined, double tolerance);
Status split_reset(SplitInstance *inst, const char *function);
Status split_get_reals(SplitInstance *inst, const char *function, const ValueReference vr[], size_t nvr,
                       double value[]);
Status split_set_reals(SplitInstance *inst, const char *function, const ValueReference vr[], size_t nvr,
                       const double value[]);
/* fmi2SetRealInputDerivatives: order 1 or 2 of the input. */
Status split_set_input_derivatives(SplitInstance *inst, const char *function, const ValueReference vr[], size_t nvr,
                                   const int order[], const double value[]);
Status split_output_derivatives(SplitInstance *inst, const char *function, const ValueReference vr[], size_t nvr,
                                const int order[], double value[]);
Status split_do_step(SplitInstance *inst, const char *function, double point, double step);
/* A refusal of a function the capability flags say the FMU does not provide (partial
 * derivatives, ...), after the calling-sequence check. */
Status split_not_provided(SplitInstance *inst, const char *function, const char *reason);

#endif
