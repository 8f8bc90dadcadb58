/* layer2.c: the FMI 2.0 Co-Simulation layer of PendulumBody and PendulumGravity (split.h):
 * it only translates FMI 2.0 types onto split.c and the shared instance (instance.h). The
 * FMUs have Co-Simulation only, with FMU states for a master that rolls a step back;
 * directional derivatives are not provided (providesDirectionalDerivative false) and are
 * refused with a reason. What every FMU of the project passes on unchanged (freeing, logging,
 * FMU states, Boolean and String variables) is Pendulum.fmu's fmi2/shared.c, linked as it is. */
#include <stddef.h>

#include "host2.h"
#include "split.h"

typedef struct {
    SplitInstance split; /* first: an fmi2Component is a SplitInstance and an Instance */
    fmi2CallbackFunctions callbacks; /* host2.h */
} Split2;

/* NULL, or why fmi2Instantiate refuses. */
static const char *refusal(fmi2String instanceName, fmi2String fmuGUID, fmi2Type fmuType) {
    const char *why = split_refusal(instanceName, fmuGUID);
    return why == NULL && fmuType != fmi2CoSimulation
           ? "fmuType must be fmi2CoSimulation: the FMU has no Model Exchange interface" : why;
}

static int setup(Instance *inst, const char *name, fmi2Type fmuType, int logging_on) {
    (void)fmuType; /* Co-Simulation: refusal() refuses any other */
    return split_setup((SplitInstance *)inst, name, 2, logging_on);
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    (void)fmuResourceLocation, (void)visible; /* the models need no resources and show nothing */
    return host2_instantiate(refusal(instanceName, fmuGUID, fmuType), SPLIT_MODEL_NAME, instanceName, fmuType,
                             functions, loggingOn, sizeof(Split2), offsetof(Split2, callbacks), setup);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return (fmi2Status)split_exit_initialization(c, "fmi2ExitInitializationMode");
}

fmi2Status fmi2Reset(fmi2Component c) {
    return (fmi2Status)split_reset(c, "fmi2Reset");
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    return (fmi2Status)split_get_reals(c, "fmi2GetReal", vr, nvr, value);
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    return (fmi2Status)split_set_reals(c, "fmi2SetReal", vr, nvr, value);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return (fmi2Status)instance_setup_experiment(c, "fmi2SetupExperiment",
                                                 split_tolerance_defined(toleranceDefined, tolerance), tolerance,
                                                 startTime, stopTimeDefined, stopTime);
}

/* No Integer variables (nor Boolean or String ones, fmi2/shared.c): any value reference is unknown. */
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    return (fmi2Status)instance_no_variables(c, "fmi2GetInteger", CALL_GET_VARIABLES, vr, nvr, value);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    return (fmi2Status)instance_no_variables(c, "fmi2SetInteger", CALL_SET_VARIABLES, vr, nvr, value);
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    (void)vUnknown_ref, (void)nUnknown, (void)vKnown_ref, (void)nKnown, (void)dvKnown, (void)dvUnknown;
    return (fmi2Status)split_not_provided(c, "fmi2GetDirectionalDerivative",
                                          "providesDirectionalDerivative is false");
}

/* --- Co-Simulation (FMI 2.0 section 4.2) ------------------------------------------------- */

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    return (fmi2Status)split_set_input_derivatives(c, "fmi2SetRealInputDerivatives", vr, nvr, order, value);
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    return (fmi2Status)split_output_derivatives(c, "fmi2GetRealOutputDerivatives", vr, nvr, order, value);
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint; /* a state is a copy: nothing kept for a rollback to free */
    return (fmi2Status)split_do_step(c, "fmi2DoStep", currentCommunicationPoint, communicationStepSize);
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    return (fmi2Status)split_not_provided(c, "fmi2CancelStep", "fmi2DoStep never returns fmi2Pending: nothing to cancel");
}

/* 4.2.3: a status kind the FMU does not provide is answered with fmi2Discard. */
static fmi2Status status_call(fmi2Component c, const char *function, const void *value) {
    if (!instance_call_allowed(c, function, CALL_GET_STATUS)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return (fmi2Status)instance_fail(c, function, "value is NULL");
    }
    return fmi2OK;
}

static fmi2Status not_provided(fmi2Component c, const char *function, fmi2StatusKind kind) {
    instance_log(c, STATUS_DISCARD, LOG_STATUS_WARNING, "%s: status kind %d is not provided", function, (int)kind);
    return fmi2Discard;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    fmi2Status status = status_call(c, "fmi2GetStatus", value);
    if (status == fmi2OK && s != fmi2DoStepStatus) {
        return not_provided(c, "fmi2GetStatus", s);
    }
    if (status == fmi2OK) {
        *value = ((Instance *)c)->data.mode == MODE_ERROR ? fmi2Error : fmi2OK;
    }
    return status;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    fmi2Status status = status_call(c, "fmi2GetRealStatus", value);
    if (status == fmi2OK && s != fmi2LastSuccessfulTime) {
        return not_provided(c, "fmi2GetRealStatus", s);
    }
    if (status == fmi2OK) {
        *value = ((Instance *)c)->data.time;
    }
    return status;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    fmi2Status status = status_call(c, "fmi2GetBooleanStatus", value);
    if (status == fmi2OK && s != fmi2Terminated) {
        return not_provided(c, "fmi2GetBooleanStatus", s);
    }
    if (status == fmi2OK) {
        *value = fmi2False;
    }
    return status;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    fmi2Status status = status_call(c, "fmi2GetIntegerStatus", value);
    return status != fmi2OK ? status : not_provided(c, "fmi2GetIntegerStatus", s);
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    fmi2Status status = status_call(c, "fmi2GetStringStatus", value);
    return status != fmi2OK ? status : not_provided(c, "fmi2GetStringStatus", s);
}
