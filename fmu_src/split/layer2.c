/* layer2.c: the FMI 2.0 Co-Simulation layer of PendulumBody and PendulumGravity (split.h):
 * it only translates FMI 2.0 types onto split.c and the shared instance (instance.h). The
 * FMUs have Co-Simulation only; FMU states and directional derivatives are not provided
 * (canGetAndSetFMUstate, providesDirectionalDerivative false) and are refused with a reason. */
#include "fmi2_api.h"
#include "split.h"

typedef struct {
    SplitInstance split; /* first: an fmi2Component is a SplitInstance and an Instance */
    fmi2CallbackFunctions callbacks;
} Split2;

static void host_log(const Instance *inst, Status status, const char *category, const char *message) {
    const fmi2CallbackFunctions *callbacks = &((const Split2 *)inst)->callbacks;
    callbacks->logger(callbacks->componentEnvironment, inst->name, (fmi2Status)status, category, "%s", message);
}

static void *host_allocate(const Instance *inst, size_t size) {
    return ((const Split2 *)inst)->callbacks.allocateMemory(1, size);
}

static void host_release(const Instance *inst, void *memory) {
    ((const Split2 *)inst)->callbacks.freeMemory(memory);
}

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    Split2 *inst;
    const char *refusal = split_refusal(instanceName, fmuGUID);
    (void)fmuResourceLocation, (void)visible;
    if (functions == NULL || functions->allocateMemory == NULL || functions->freeMemory == NULL ||
        functions->logger == NULL) {
        return NULL;
    }
    if (refusal == NULL && fmuType != fmi2CoSimulation) {
        refusal = "fmuType must be fmi2CoSimulation: the FMU has no Model Exchange interface";
    }
    if (refusal != NULL) {
        functions->logger(functions->componentEnvironment, instanceName != NULL && instanceName[0] != '\0'
                          ? instanceName : SPLIT_MODEL_NAME, fmi2Error, "logStatusError", "fmi2Instantiate: %s",
                          refusal);
        return NULL;
    }
    inst = functions->allocateMemory(1, sizeof *inst);
    if (inst != NULL) {
        inst->callbacks = *functions;
        inst->split.core.host.log = host_log;
        inst->split.core.host.allocate = host_allocate;
        inst->split.core.host.release = host_release;
    }
    if (inst == NULL || split_setup(&inst->split, instanceName, 2, loggingOn) != 0) {
        if (inst != NULL) {
            functions->freeMemory(inst);
        }
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error, "logStatusError",
                          "fmi2Instantiate: out of memory");
        return NULL;
    }
    return inst;
}

void fmi2FreeInstance(fmi2Component c) {
    Split2 *inst = c;
    if (inst != NULL) {
        fmi2CallbackFreeMemory release = inst->callbacks.freeMemory;
        instance_release(&inst->split.core);
        release(inst);
    }
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    return (fmi2Status)instance_set_debug_logging(c, "fmi2SetDebugLogging", loggingOn, nCategories, categories);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return (fmi2Status)instance_setup_experiment(c, "fmi2SetupExperiment",
                                                 split_tolerance_defined(toleranceDefined, tolerance), tolerance,
                                                 startTime, stopTimeDefined, stopTime);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    return (fmi2Status)instance_enter_initialization(c, "fmi2EnterInitializationMode");
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return (fmi2Status)split_exit_initialization(c, "fmi2ExitInitializationMode");
}

fmi2Status fmi2Terminate(fmi2Component c) { return (fmi2Status)instance_terminate(c, "fmi2Terminate"); }

fmi2Status fmi2Reset(fmi2Component c) { return (fmi2Status)split_reset(c, "fmi2Reset"); }

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    return (fmi2Status)split_get_reals(c, "fmi2GetReal", vr, nvr, value);
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    return (fmi2Status)split_set_reals(c, "fmi2SetReal", vr, nvr, value);
}

/* No Integer, Boolean or String variables: any value reference is unknown. */
#define NO_VARIABLES_OF_TYPE(Name, Type)                                                                       \
    fmi2Status fmi2Get##Name(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, Type value[]) {       \
        return (fmi2Status)instance_no_variables(c, "fmi2Get" #Name, GET_MODES, vr, nvr, value);              \
    }                                                                                                          \
    fmi2Status fmi2Set##Name(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const Type value[]) { \
        return (fmi2Status)instance_no_variables(c, "fmi2Set" #Name, SET_MODES, vr, nvr, value);              \
    }
NO_VARIABLES_OF_TYPE(Integer, fmi2Integer)
NO_VARIABLES_OF_TYPE(Boolean, fmi2Boolean)
NO_VARIABLES_OF_TYPE(String, fmi2String)

#define NO_FMU_STATES "canGetAndSetFMUstate is false: the FMU provides no FMU states"

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state) {
    (void)state;
    return (fmi2Status)split_not_provided(c, "fmi2GetFMUstate", NO_FMU_STATES);
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
    (void)state;
    return (fmi2Status)split_not_provided(c, "fmi2SetFMUstate", NO_FMU_STATES);
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state) {
    (void)state;
    return (fmi2Status)split_not_provided(c, "fmi2FreeFMUstate", NO_FMU_STATES);
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t *size) {
    (void)state, (void)size;
    return (fmi2Status)split_not_provided(c, "fmi2SerializedFMUstateSize", NO_FMU_STATES);
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
    (void)state, (void)bytes, (void)size;
    return (fmi2Status)split_not_provided(c, "fmi2SerializeFMUstate", NO_FMU_STATES);
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate *state) {
    (void)bytes, (void)size, (void)state;
    return (fmi2Status)split_not_provided(c, "fmi2DeSerializeFMUstate", NO_FMU_STATES);
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
    (void)noSetFMUStatePriorToCurrentPoint; /* no FMU states */
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

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    fmi2Status status = status_call(c, "fmi2GetStatus", value);
    if (status != fmi2OK) {
        return status;
    }
    if (s != fmi2DoStepStatus) {
        return not_provided(c, "fmi2GetStatus", s);
    }
    *value = ((Instance *)c)->data.mode == MODE_ERROR ? fmi2Error : fmi2OK;
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    fmi2Status status = status_call(c, "fmi2GetRealStatus", value);
    if (status != fmi2OK) {
        return status;
    }
    if (s != fmi2LastSuccessfulTime) {
        return not_provided(c, "fmi2GetRealStatus", s);
    }
    *value = ((Instance *)c)->data.time;
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    fmi2Status status = status_call(c, "fmi2GetIntegerStatus", value);
    return status != fmi2OK ? status : not_provided(c, "fmi2GetIntegerStatus", s);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    fmi2Status status = status_call(c, "fmi2GetBooleanStatus", value);
    if (status != fmi2OK) {
        return status;
    }
    if (s != fmi2Terminated) {
        return not_provided(c, "fmi2GetBooleanStatus", s);
    }
    *value = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    fmi2Status status = status_call(c, "fmi2GetStringStatus", value);
    return status != fmi2OK ? status : not_provided(c, "fmi2GetStringStatus", s);
}
