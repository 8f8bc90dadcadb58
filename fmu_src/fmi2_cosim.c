/* fmi2_cosim.c: the Co-Simulation functions (FMI 2.0 section 4.2). fmi2DoStep integrates
 * with the solver chosen by the parameter `solver`, at the tolerance of fmi2SetupExperiment;
 * the solver keeps its own steps, so the communication grid does not change the result. */
#include <math.h>

#include "fmi2_instance.h"

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    Instance *inst = c;
    ModelData *data;
    double t_end, y[2];
    (void)noSetFMUStatePriorToCurrentPoint; /* the solver state is plain data: nothing to drop */
    if (!instance_allowed(inst, "fmi2DoStep", MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    data = &inst->data;
    if (!(isfinite(communicationStepSize) && communicationStepSize > 0.0)) {
        return instance_fail(inst, "fmi2DoStep", "communicationStepSize %g must be a finite number greater than 0",
                             communicationStepSize);
    }
    /* 4.2.2: currentCommunicationPoint must be the time reached by the last step; allow
     * for a master that accumulates its time with rounding. */
    if (!isfinite(currentCommunicationPoint) ||
        fabs(currentCommunicationPoint - data->time) > 1e-9 * fmax(1.0, fabs(data->time))) {
        return instance_fail(inst, "fmi2DoStep", "currentCommunicationPoint %.17g is not the current time %.17g",
                             currentCommunicationPoint, data->time);
    }
    t_end = currentCommunicationPoint + communicationStepSize;
    if (!isfinite(t_end)) {
        return instance_fail(inst, "fmi2DoStep", "the step would end at a time that is not finite");
    }
    switch (integrator_advance(&data->integrator, t_end, y)) {
    case 0: break;
    case -2:
        return instance_fail(inst, "fmi2DoStep",
                             "reaching t = %.17g from t = %.17g takes more than %ld internal steps; "
                             "use shorter communication steps", t_end, data->time, INTEGRATOR_MAX_STEPS_PER_ADVANCE);
    default:
        return instance_fail(inst, "fmi2DoStep",
                             "the solver failed between t = %.17g and t = %.17g (step size underflow or non-finite state)",
                             data->time, t_end);
    }
    data->theta = y[0];
    data->omega = y[1];
    data->time = t_end;
    return fmi2OK;
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    Instance *inst = c;
    (void)vr, (void)nvr, (void)order, (void)value;
    if (!instance_allowed(inst, "fmi2SetRealInputDerivatives", MODE_INITIALIZATION | MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    return instance_fail(inst, "fmi2SetRealInputDerivatives", "the model has no inputs");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    Instance *inst = c;
    (void)vr, (void)nvr, (void)order, (void)value;
    if (!instance_allowed(inst, "fmi2GetRealOutputDerivatives", MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    return instance_fail(inst, "fmi2GetRealOutputDerivatives", "not provided (maxOutputDerivativeOrder is 0)");
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2CancelStep", MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    return instance_fail(inst, "fmi2CancelStep", "fmi2DoStep never returns fmi2Pending: nothing to cancel");
}

#define STATUS_MODES (MODE_STEP_COMPLETE | MODE_TERMINATED | MODE_ERROR)

/* 4.2.3: a status that the FMU does not provide is answered with fmi2Discard. */
static fmi2Status status_not_provided(Instance *inst, const char *function, fmi2StatusKind kind) {
    instance_log(inst, fmi2Discard, LOG_STATUS_WARNING, "%s: status kind %d is not provided", function, (int)kind);
    return fmi2Discard;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2GetStatus", STATUS_MODES)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return instance_fail(inst, "fmi2GetStatus", "value is NULL");
    }
    if (s != fmi2DoStepStatus) {
        return status_not_provided(inst, "fmi2GetStatus", s);
    }
    *value = inst->data.mode == MODE_ERROR ? fmi2Error : fmi2OK;
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2GetRealStatus", STATUS_MODES)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return instance_fail(inst, "fmi2GetRealStatus", "value is NULL");
    }
    if (s != fmi2LastSuccessfulTime) {
        return status_not_provided(inst, "fmi2GetRealStatus", s);
    }
    *value = inst->data.time;
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    Instance *inst = c;
    (void)value;
    if (!instance_allowed(inst, "fmi2GetIntegerStatus", STATUS_MODES)) {
        return fmi2Error;
    }
    return status_not_provided(inst, "fmi2GetIntegerStatus", s);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2GetBooleanStatus", STATUS_MODES)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return instance_fail(inst, "fmi2GetBooleanStatus", "value is NULL");
    }
    if (s != fmi2Terminated) {
        return status_not_provided(inst, "fmi2GetBooleanStatus", s);
    }
    *value = fmi2False; /* the model never asks the master to stop */
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    Instance *inst = c;
    (void)value;
    if (!instance_allowed(inst, "fmi2GetStringStatus", STATUS_MODES)) {
        return fmi2Error;
    }
    return status_not_provided(inst, "fmi2GetStringStatus", s);
}
