/* split.c: what PendulumBody and PendulumGravity share (split.h): instantiation checks, the
 * input polynomial, variable access, the communication step and the output derivatives, on
 * the shared instance (its calling-sequence check, logging and experiment). FMI-free. */
#include "split.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* The shared instance of a split instance: its first member, so NULL stays NULL (every
 * instance_call_allowed check refuses a NULL instance before anything is read). */
#define CORE(inst) ((Instance *)(inst))

const char *split_refusal(const char *name, const char *token) {
    if (name == NULL || name[0] == '\0') {
        return "instanceName must be a non-empty string";
    }
    if (token == NULL || strcmp(token, SPLIT_TOKEN) != 0) {
        return "the GUID / instantiation token does not match this FMU's";
    }
    return NULL;
}

static void input_reset(SplitInstance *inst) {
    inst->input.value = SPLIT_INPUT_START;
    inst->input.d1 = 0.0;
    inst->input.d2 = 0.0;
}

static const char *check_state(const Instance *inst, const ModelData *data, const void *extra);

/* An FMU state of either FMU (instance.h): the shared instance's ModelData and the input
 * polynomial, marked with the model's own magic. */
static const StateModel STATE_MODEL = {SPLIT_STATE_MAGIC, sizeof(InputPolynomial), offsetof(SplitInstance, input),
                                       check_state};
typedef char input_fits_a_state[sizeof(InputPolynomial) <= STATE_EXTRA_MAX ? 1 : -1];

int split_setup(SplitInstance *inst, const char *name, int fmi_version, int logging_on) {
    if (instance_setup(CORE(inst), name, INTERFACE_CO_SIMULATION, fmi_version, logging_on) != 0) {
        return -1;
    }
    inst->core.state_model = &STATE_MODEL;
    input_reset(inst);
    return 0;
}

/* The modes a state is taken in (GetFMUstate is refused in Error). */
#define STATE_MODES (MODE_INSTANTIATED | MODE_INITIALIZATION | MODE_STEP_COMPLETE | MODE_TERMINATED)

/* NULL, or why a state (an untrusted copy of ModelData and the input polynomial) is refused by
 * `inst`: the checks both FMUs share, then the model's own (split_model_check_state). */
static const char *check_state(const Instance *inst, const ModelData *data, const void *extra) {
    InputPolynomial u;
    ModelData reset;
    const unsigned mode = (unsigned)data->mode;
    memcpy(&u, extra, sizeof u); /* the bytes after ModelData: no alignment assumed */
    model_reset(&reset, INTERFACE_CO_SIMULATION);
    if (data->interface != INTERFACE_CO_SIMULATION) {
        return "the interface is not Co-Simulation";
    }
    if (mode == 0 || (mode & (mode - 1)) != 0 || (mode & STATE_MODES) == 0) {
        return "the mode is not one a state of this FMU is taken in";
    }
    /* no call of these FMUs changes the solver, the hard-case flag or the certificate */
    if (data->solver != reset.solver || data->hard_case_reported != 0 || data->certificate_logged != 0.0) {
        return "the solver, the hard-case flag or the certificate is not its start value";
    }
    if (!(isfinite(data->L) && data->L > 0.0 && isfinite(data->g) && data->g > 0.0)) {
        return "L or g out of range (finite, greater than 0)";
    }
    if (!(data->tolerance >= INTEGRATOR_TOLERANCE_FLOOR && data->tolerance < 1.0)) {
        return "the tolerance is out of range [INTEGRATOR_TOLERANCE_FLOOR, 1)";
    }
    if (!isfinite(data->start_time) || !isfinite(data->time) || !(data->time >= data->start_time) ||
        !isfinite(data->theta) || !isfinite(data->omega)) {
        return "a time or a state is not finite, or the time is before the start time";
    }
    if (!isfinite(u.value) || !isfinite(u.d1) || !isfinite(u.d2)) {
        return "the input or one of its derivatives is not finite";
    }
    if (inst->fmi_version == 3 && (u.d1 != 0.0 || u.d2 != 0.0)) {
        return "the input has derivatives, which FMI 3.0 Co-Simulation does not set";
    }
    return split_model_check_state(data, &reset);
}

Status split_reset(SplitInstance *inst, const char *function) {
    Status status = instance_reset(CORE(inst), function);
    if (status == STATUS_OK) {
        input_reset(inst);
    }
    return status;
}

Status split_exit_initialization(SplitInstance *inst, const char *function) {
    const char *problem;
    if (!instance_call_allowed(CORE(inst), function, CALL_EXIT_INITIALIZATION)) {
        return STATUS_ERROR;
    }
    model_exact_forget(&inst->core.exact_now);
    problem = split_model_initialize(inst);
    if (problem != NULL) {
        return instance_fail(CORE(inst), function, "%s", problem);
    }
    inst->core.data.mode = MODE_STEP_COMPLETE;
    return STATUS_OK;
}

static const char *name_of(const SplitInstance *inst, ValueReference vr) {
    return inst->core.fmi_version == 3 && vr == SPLIT_VR_TIME ? "time" : split_model_variable_name(vr);
}

Status split_get_reals(SplitInstance *inst, const char *function, const ValueReference vr[], size_t nvr,
                       double value[]) {
    size_t i;
    if (!instance_arrays_allowed(CORE(inst), function, CALL_GET_VARIABLES, vr, nvr, value)) {
        return STATUS_ERROR;
    }
    for (i = 0; i < nvr; i++) {
        const char *problem = NULL;
        if (inst->core.fmi_version == 3 && vr[i] == SPLIT_VR_TIME) {
            value[i] = inst->core.data.time;
        } else if (vr[i] == SPLIT_INPUT_VR) {
            value[i] = inst->input.value;
        } else {
            problem = split_model_get_real(inst, vr[i], &value[i]);
        }
        if (problem != NULL) {
            return instance_fail(CORE(inst), function, "%s (value reference %u): %s", name_of(inst, vr[i]), vr[i],
                                 problem);
        }
    }
    return STATUS_OK;
}

Status split_set_reals(SplitInstance *inst, const char *function, const ValueReference vr[], size_t nvr,
                       const double value[]) {
    size_t i;
    if (!instance_arrays_allowed(CORE(inst), function, CALL_SET_VARIABLES, vr, nvr, value)) {
        return STATUS_ERROR;
    }
    model_exact_forget(&inst->core.exact_now); /* a parameter or a start value may change */
    for (i = 0; i < nvr; i++) {
        const char *problem = NULL;
        if (inst->core.fmi_version == 3 && vr[i] == SPLIT_VR_TIME) {
            problem = "is the independent variable: it moves with fmi3DoStep";
        } else if (vr[i] == SPLIT_INPUT_VR) {
            if (!isfinite(value[i])) {
                problem = "must be a finite number";
            } else {
                inst->input.value = value[i];
            }
        } else {
            problem = split_model_set_real(inst, vr[i], value[i]);
        }
        if (problem != NULL) {
            return instance_fail(CORE(inst), function, "%s (value reference %u) = %g: %s", name_of(inst, vr[i]),
                                 vr[i], value[i], problem);
        }
    }
    return STATUS_OK;
}

Status split_set_input_derivatives(SplitInstance *inst, const char *function, const ValueReference vr[], size_t nvr,
                                   const int order[], const double value[]) {
    size_t i;
    if (!instance_call_allowed(CORE(inst), function, CALL_SET_INPUT_DERIVATIVES)) {
        return STATUS_ERROR;
    }
    if (nvr > 0 && (vr == NULL || order == NULL || value == NULL)) {
        return instance_fail(CORE(inst), function, "vr, order or value is NULL with nvr = %zu", nvr);
    }
    /* every entry is checked before any is taken: a refused call changes nothing */
    for (i = 0; i < nvr; i++) {
        if (vr[i] != SPLIT_INPUT_VR) {
            return instance_fail(CORE(inst), function, "%s (value reference %u) is not an input of %s",
                                 name_of(inst, vr[i]), vr[i], SPLIT_MODEL_NAME);
        }
        if (order[i] < 1 || order[i] > SPLIT_MAX_INPUT_ORDER) {
            return instance_fail(CORE(inst), function, "order %d of %s is not in 1..%d: the input is a "
                                 "polynomial of degree <= %d over a step", order[i], name_of(inst, vr[i]),
                                 SPLIT_MAX_INPUT_ORDER, SPLIT_MAX_INPUT_ORDER);
        }
        if (!isfinite(value[i])) {
            return instance_fail(CORE(inst), function, "derivative of order %d of %s must be finite, not %g",
                                 order[i], name_of(inst, vr[i]), value[i]);
        }
    }
    for (i = 0; i < nvr; i++) {
        if (order[i] == 1) {
            inst->input.d1 = value[i];
        } else {
            inst->input.d2 = value[i];
        }
    }
    return STATUS_OK;
}

Status split_output_derivatives(SplitInstance *inst, const char *function, const ValueReference vr[], size_t nvr,
                                const int order[], double value[]) {
    int max_order;
    size_t i;
    if (!instance_call_allowed(CORE(inst), function, CALL_GET_OUTPUT_DERIVATIVES)) {
        return STATUS_ERROR;
    }
    max_order = split_model_max_output_order(inst->core.fmi_version);
    if (nvr > 0 && (vr == NULL || order == NULL || value == NULL)) {
        return instance_fail(CORE(inst), function, "vr, order or value is NULL with nvr = %zu", nvr);
    }
    for (i = 0; i < nvr; i++) {
        const char *problem;
        if (order[i] < 1 || order[i] > max_order) {
            return instance_fail(CORE(inst), function, "order %d of %s is not in 1..%d (maxOutputDerivativeOrder)",
                                 order[i], name_of(inst, vr[i]), max_order);
        }
        problem = split_model_output_derivative(inst, vr[i], order[i], &value[i]);
        if (problem == NULL && !isfinite(value[i])) {
            problem = "is not finite";
        }
        if (problem != NULL) {
            return instance_fail(CORE(inst), function, "derivative of order %d of %s (value reference %u): %s",
                                 order[i], name_of(inst, vr[i]), vr[i], problem);
        }
    }
    return STATUS_OK;
}

Status split_do_step(SplitInstance *inst, const char *function, double point, double step) {
    ModelData *data;
    InputPolynomial *u;
    double t_end = 0.0, h, value, d1;
    if (!instance_call_allowed(CORE(inst), function, CALL_DO_STEP)) {
        return STATUS_ERROR;
    }
    data = &inst->core.data;
    u = &inst->input;
    /* the same rules for the communication point and step as Pendulum.fmu's (integrator.h) */
    switch (integrator_step_end(data->time, point, step, &t_end)) {
    case STEP_END_OK: break;
    case STEP_END_BAD_SIZE:
        return instance_fail(CORE(inst), function, "communicationStepSize %g must be a finite number greater than 0",
                             step);
    case STEP_END_BAD_POINT:
        return instance_fail(CORE(inst), function, "currentCommunicationPoint %.17g is not the current time %.17g "
                             "(to %g ulps)", point, data->time, INTEGRATOR_POINT_ULPS);
    case STEP_END_NOT_FINITE:
        return instance_fail(CORE(inst), function, "the step would end at a time that is not finite");
    default:
        return instance_fail(CORE(inst), function, "the step would end at %.17g, before the current time %.17g: "
                             "time never goes backwards", point + step, data->time);
    }
    h = t_end - data->time;
    /* the input at the step's end, and the states, must stay finite: checked before any change */
    value = u->value + h * (u->d1 + h * (u->d2 / 2.0));
    d1 = u->d1 + h * u->d2;
    if (!isfinite(value) || !isfinite(d1)) {
        return instance_fail(CORE(inst), function, "the input extrapolated to t = %.17g is not finite "
                             "(value %g, derivative %g)", t_end, value, d1);
    }
    split_model_advance(inst, h);
    if (!isfinite(data->theta) || !isfinite(data->omega)) {
        return instance_fail(CORE(inst), function, "the state at t = %.17g is not finite", t_end);
    }
    u->value = value;
    u->d1 = d1;
    data->time = t_end;
    model_exact_forget(&inst->core.exact_now);
    return STATUS_OK;
}

Status split_not_provided(SplitInstance *inst, const char *function, const char *reason) {
    if (!instance_call_allowed(CORE(inst), function, CALL_NOT_PROVIDED)) {
        return STATUS_ERROR;
    }
    return instance_fail(CORE(inst), function, "%s", reason);
}

int split_tolerance_defined(int tolerance_defined, double tolerance) {
    return tolerance_defined && !(tolerance > 0.0 && tolerance < INTEGRATOR_TOLERANCE_FLOOR);
}
