/* instance/calls.c: the life cycle (setup, initialization, termination, reset) and the
 * variable access of an instance, shared by both FMI versions. */
#include <limits.h>
#include <math.h>

#include "instance.h"
#include "pendulum_vrs.h"

/* FMI 3.0 requires an independent variable: `time`, value reference 0 (not in FMI 2.0). */
#define VR_TIME_FMI3 0u

/* The end of an instance's life: its FMU states (instance/state.c), then its name. */
void instance_release(Instance *inst) {
    instance_release_states(inst);
    if (inst->name != NULL) {
        inst->host.release(inst, inst->name);
        inst->name = NULL;
    }
}

/* The experiment's checks and settings, after the caller's check of the mode. */
static Status take_experiment(Instance *inst, const char *function, int tolerance_defined, double tolerance,
                              double start_time, int stop_time_defined, double stop_time) {
    if (tolerance_defined && !(isfinite(tolerance) && tolerance > 0.0 && tolerance < 1.0)) {
        return instance_fail(inst, function, "tolerance %g must be in (0, 1)", tolerance);
    }
    if (!isfinite(start_time)) {
        return instance_fail(inst, function, "startTime must be finite");
    }
    if (stop_time_defined && !(stop_time >= start_time)) {
        return instance_fail(inst, function, "stopTime %g is before startTime %g", stop_time, start_time);
    }
    model_exact_forget(&inst->exact_now);
    inst->data.tolerance = tolerance_defined ? tolerance : DEFAULT_TOLERANCE;
    inst->data.start_time = start_time;
    inst->data.time = start_time;
    if (tolerance_defined && inst->type == INTERFACE_CO_SIMULATION && tolerance < INTEGRATOR_TOLERANCE_FLOOR) {
        /* The step certificate's floor (integrator.h, docs/certificate.md): below it no step can
         * be certified at the tolerance asked, so the run takes the floor, and says so. Importers
         * pass 1e-16 for "as accurate as possible": a refusal would lose the run. */
        inst->data.tolerance = INTEGRATOR_TOLERANCE_FLOOR;
        instance_log(inst, STATUS_WARNING, LOG_STATUS_WARNING,
                     "%s: tolerance %g is below %g, the smallest at which a Co-Simulation step can be certified "
                     "in double precision (the bound 100 tol must stay clear of the exact solution's own error, "
                     "%g): the run uses tolerance %g, and every step is certified at it", function, tolerance,
                     INTEGRATOR_TOLERANCE_FLOOR, CERTIFICATE_EXACT_ERROR, INTEGRATOR_TOLERANCE_FLOOR);
        return STATUS_WARNING;
    }
    return STATUS_OK;
}

Status instance_setup_experiment(Instance *inst, const char *function, int tolerance_defined, double tolerance,
                                 double start_time, int stop_time_defined, double stop_time) {
    if (!instance_call_allowed(inst, function, CALL_SETUP_EXPERIMENT)) {
        return STATUS_ERROR;
    }
    return take_experiment(inst, function, tolerance_defined, tolerance, start_time, stop_time_defined, stop_time);
}

Status instance_enter_initialization(Instance *inst, const char *function) {
    if (!instance_call_allowed(inst, function, CALL_ENTER_INITIALIZATION)) {
        return STATUS_ERROR;
    }
    inst->data.mode = MODE_INITIALIZATION;
    return STATUS_OK;
}

Status instance_enter_initialization_with(Instance *inst, const char *function, int tolerance_defined,
                                          double tolerance, double start_time, int stop_time_defined,
                                          double stop_time) {
    Status status;
    if (!instance_call_allowed(inst, function, CALL_ENTER_INITIALIZATION)) {
        return STATUS_ERROR;
    }
    status = take_experiment(inst, function, tolerance_defined, tolerance, start_time, stop_time_defined, stop_time);
    if (status == STATUS_OK || status == STATUS_WARNING) {
        inst->data.mode = MODE_INITIALIZATION;
    }
    return status;
}

Status instance_exit_initialization(Instance *inst, const char *function) {
    const char *problem;
    if (!instance_call_allowed(inst, function, CALL_EXIT_INITIALIZATION)) {
        return STATUS_ERROR;
    }
    model_exact_forget(&inst->exact_now); /* the exact solution is set up anew */
    problem = model_initialize(&inst->data, inst->type);
    if (problem != NULL) {
        return instance_fail(inst, function, "%s", problem);
    }
    inst->data.mode = inst->type == INTERFACE_MODEL_EXCHANGE ? MODE_EVENT : MODE_STEP_COMPLETE;
    return STATUS_OK;
}

Status instance_terminate(Instance *inst, const char *function) {
    if (!instance_call_allowed(inst, function, CALL_TERMINATE)) {
        return STATUS_ERROR;
    }
    inst->data.mode = MODE_TERMINATED;
    return STATUS_OK;
}

Status instance_reset(Instance *inst, const char *function) {
    if (!instance_call_allowed(inst, function, CALL_RESET)) {
        return STATUS_ERROR;
    }
    model_reset(&inst->data, inst->type);
    model_exact_forget(&inst->exact_now);
    return STATUS_OK;
}

int instance_arrays_allowed(Instance *inst, const char *function, FmiCall call, const ValueReference vr[],
                            size_t nvr, const void *values) {
    if (!instance_call_allowed(inst, function, call)) {
        return 0;
    }
    if (nvr > 0 && (vr == NULL || values == NULL)) {
        instance_fail(inst, function, "vr or value is NULL with nvr = %zu", nvr);
        return 0;
    }
    return 1;
}

Status instance_get_reals(Instance *inst, const char *function, const ValueReference vr[], size_t nvr,
                          double value[]) {
    size_t i;
    if (!instance_arrays_allowed(inst, function, CALL_GET_VARIABLES, vr, nvr, value)) {
        return STATUS_ERROR;
    }
    for (i = 0; i < nvr; i++) {
        const char *problem;
        if (inst->fmi_version == 3 && vr[i] == VR_TIME_FMI3) {
            value[i] = inst->data.time;
            continue;
        }
        problem = model_get_real(&inst->data, &inst->exact_now, vr[i], &value[i]);
        if (problem != NULL) {
            return instance_fail(inst, function, "%s (value reference %u): %s", variable_name(vr[i]), vr[i],
                                 problem);
        }
    }
    return STATUS_OK;
}

Status instance_set_reals(Instance *inst, const char *function, const ValueReference vr[], size_t nvr,
                          const double value[]) {
    size_t i;
    if (!instance_arrays_allowed(inst, function, CALL_SET_VARIABLES, vr, nvr, value)) {
        return STATUS_ERROR;
    }
    model_exact_forget(&inst->exact_now); /* a parameter or a start value may change */
    for (i = 0; i < nvr; i++) {
        const char *problem = inst->fmi_version == 3 && vr[i] == VR_TIME_FMI3
                                  ? "is the independent variable: set it with fmi3SetTime"
                                  : model_set_real(&inst->data, vr[i], value[i]);
        if (problem != NULL) {
            return instance_fail(inst, function, "%s (value reference %u) = %g: %s",
                                 vr[i] == VR_TIME_FMI3 ? "time" : variable_name(vr[i]), vr[i], value[i], problem);
        }
    }
    return STATUS_OK;
}

Status instance_get_integer(Instance *inst, const char *function, ValueReference vr, long *value) {
    int got = 0;
    const char *problem = model_get_integer(&inst->data, vr, &got);
    if (problem != NULL) {
        return instance_fail(inst, function, "%s (value reference %u): %s", variable_name(vr), vr, problem);
    }
    *value = got;
    return STATUS_OK;
}

Status instance_set_integer(Instance *inst, const char *function, ValueReference vr, long value) {
    /* a value beyond int is no item of Solver either: narrowed, it is refused as such */
    int narrowed = value > INT_MAX ? INT_MAX : value < INT_MIN ? INT_MIN : (int)value;
    const char *problem;
    model_exact_forget(&inst->exact_now);
    problem = model_set_integer(&inst->data, vr, narrowed);
    if (problem != NULL) {
        return instance_fail(inst, function, "%s (value reference %u) = %ld: %s", variable_name(vr), vr, value,
                             problem);
    }
    return STATUS_OK;
}

Status instance_no_variables(Instance *inst, const char *function, FmiCall call, const ValueReference vr[],
                             size_t nvr, const void *values) {
    if (!instance_arrays_allowed(inst, function, call, vr, nvr, values)) {
        return STATUS_ERROR;
    }
    if (nvr > 0) {
        return instance_fail(inst, function, "unknown value reference %u: the model has no variable of this type",
                             vr[0]);
    }
    return STATUS_OK;
}
