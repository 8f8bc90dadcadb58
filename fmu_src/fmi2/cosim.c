/* fmi2/cosim.c: the FMI 2.0 Co-Simulation functions (section 4.2), translated onto the shared
 * instance (instance/motion.c, instance/derivatives.c); the status calls are 2.0's own. */
#include "fmi2_api.h"
#include "instance.h"

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint; /* the solver state is plain data: nothing to drop */
    return (fmi2Status)instance_do_step(c, "fmi2DoStep", currentCommunicationPoint, communicationStepSize);
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    Instance *inst = c;
    (void)vr, (void)nvr, (void)order, (void)value;
    if (!instance_call_allowed(inst, "fmi2SetRealInputDerivatives", CALL_SET_INPUT_DERIVATIVES)) {
        return fmi2Error;
    }
    return (fmi2Status)instance_fail(inst, "fmi2SetRealInputDerivatives", "the model has no inputs");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    return (fmi2Status)instance_output_derivatives(c, "fmi2GetRealOutputDerivatives", vr, nvr, order, value);
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    Instance *inst = c;
    if (!instance_call_allowed(inst, "fmi2CancelStep", CALL_CANCEL_STEP)) {
        return fmi2Error;
    }
    return (fmi2Status)instance_fail(inst, "fmi2CancelStep", "fmi2DoStep never returns fmi2Pending: nothing to cancel");
}

/* 4.2.3: a status that the FMU does not provide is answered with fmi2Discard. */
static fmi2Status status_not_provided(Instance *inst, const char *function, fmi2StatusKind kind) {
    instance_log(inst, STATUS_DISCARD, LOG_STATUS_WARNING, "%s: status kind %d is not provided", function, (int)kind);
    return fmi2Discard;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    Instance *inst = c;
    if (!instance_call_allowed(inst, "fmi2GetStatus", CALL_GET_STATUS)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return (fmi2Status)instance_fail(inst, "fmi2GetStatus", "value is NULL");
    }
    if (s != fmi2DoStepStatus) {
        return status_not_provided(inst, "fmi2GetStatus", s);
    }
    *value = inst->data.mode == MODE_ERROR ? fmi2Error : fmi2OK;
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    Instance *inst = c;
    if (!instance_call_allowed(inst, "fmi2GetRealStatus", CALL_GET_STATUS)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return (fmi2Status)instance_fail(inst, "fmi2GetRealStatus", "value is NULL");
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
    if (!instance_call_allowed(inst, "fmi2GetIntegerStatus", CALL_GET_STATUS)) {
        return fmi2Error;
    }
    return status_not_provided(inst, "fmi2GetIntegerStatus", s);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    Instance *inst = c;
    if (!instance_call_allowed(inst, "fmi2GetBooleanStatus", CALL_GET_STATUS)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return (fmi2Status)instance_fail(inst, "fmi2GetBooleanStatus", "value is NULL");
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
    if (!instance_call_allowed(inst, "fmi2GetStringStatus", CALL_GET_STATUS)) {
        return fmi2Error;
    }
    return status_not_provided(inst, "fmi2GetStringStatus", s);
}
