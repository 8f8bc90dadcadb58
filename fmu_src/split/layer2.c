/* layer2.c: the FMI 2.0 Co-Simulation layer of PendulumBody and PendulumGravity (split.h):
 * it only translates FMI 2.0 types onto split.c and the shared instance (instance.h). The
 * FMUs have Co-Simulation only, with FMU states for a master that rolls a step back;
 * directional derivatives are not provided (providesDirectionalDerivative false) and are
 * refused with a reason. */
#include <stddef.h>

#include "fmu_state_calls.h"
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

DEFINE_FMI2_INSTANTIATE(Split2, SPLIT_MODEL_NAME, refusal, setup)

DEFINE_FMI2_PASSING_CALLS(split_exit_initialization, split_reset, split_get_reals, split_set_reals)

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return (fmi2Status)instance_setup_experiment(c, "fmi2SetupExperiment",
                                                 split_tolerance_defined(toleranceDefined, tolerance), tolerance,
                                                 startTime, stopTimeDefined, stopTime);
}

/* FMU states (canGetAndSetFMUstate, canSerializeFMUstate): ModelData and the input polynomial
 * (split.c), through the shared instance/state.c as Pendulum.fmu's. */
DEFINE_FMU_STATE_CALLS(fmi2Status, fmi2Component, fmi2FMUstate, fmi2Byte, fmi2GetFMUstate, fmi2SetFMUstate,
                       fmi2FreeFMUstate, fmi2SerializedFMUstateSize, fmi2SerializeFMUstate, fmi2DeSerializeFMUstate)

/* No Integer, Boolean or String variables. */
DEFINE_FMI2_NO_VARIABLES_OF_TYPE(Integer, fmi2Integer)
DEFINE_FMI2_NO_VARIABLES_OF_TYPE(Boolean, fmi2Boolean)
DEFINE_FMI2_NO_VARIABLES_OF_TYPE(String, fmi2String)

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

#define STATUS_MODES (MODE_STEP_COMPLETE | MODE_TERMINATED | MODE_ERROR)

/* 4.2.3: a status kind the FMU does not provide is answered with fmi2Discard. */
static fmi2Status status_call(fmi2Component c, const char *function, const void *value) {
    if (!instance_allowed(c, function, STATUS_MODES)) {
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

/* A status call that provides one status kind, `provided`, whose value is `answer`. */
#define STATUS_CALL(Name, Type, provided, answer)                                 \
    fmi2Status fmi2Get##Name(fmi2Component c, const fmi2StatusKind s, Type *value) { \
        fmi2Status status = status_call(c, "fmi2Get" #Name, value);               \
        if (status == fmi2OK && s != provided) {                                  \
            return not_provided(c, "fmi2Get" #Name, s);                           \
        }                                                                         \
        if (status == fmi2OK) {                                                   \
            *value = answer;                                                      \
        }                                                                         \
        return status;                                                            \
    }
STATUS_CALL(Status, fmi2Status, fmi2DoStepStatus, ((Instance *)c)->data.mode == MODE_ERROR ? fmi2Error : fmi2OK)
STATUS_CALL(RealStatus, fmi2Real, fmi2LastSuccessfulTime, ((Instance *)c)->data.time)
STATUS_CALL(BooleanStatus, fmi2Boolean, fmi2Terminated, fmi2False)

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    fmi2Status status = status_call(c, "fmi2GetIntegerStatus", value);
    return status != fmi2OK ? status : not_provided(c, "fmi2GetIntegerStatus", s);
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    fmi2Status status = status_call(c, "fmi2GetStringStatus", value);
    return status != fmi2OK ? status : not_provided(c, "fmi2GetStringStatus", s);
}
