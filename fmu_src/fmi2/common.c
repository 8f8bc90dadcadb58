/* fmi2/common.c: the FMI 2.0 functions shared by Model Exchange and Co-Simulation (FMI 2.0
 * section 2.1), translated onto the shared instance (instance.h): instantiation with the
 * host's callbacks, life cycle, variables, FMU states and directional derivatives. */
#include <stddef.h>

#include "host2.h"

/* The FMI 2.0 instance: the shared one first, then the host's callbacks (host2.h). */
typedef struct {
    Instance core;
    fmi2CallbackFunctions callbacks;
} Fmi2Instance;

/* NULL, or why fmi2Instantiate refuses. */
static const char *refusal(fmi2String instanceName, fmi2String fmuGUID, fmi2Type fmuType) {
    const char *why = instance_refusal(instanceName, fmuGUID);
    if (why == NULL && fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation) {
        why = "fmuType must be fmi2ModelExchange or fmi2CoSimulation";
    }
    return why;
}

static int setup(Instance *inst, const char *name, fmi2Type fmuType, int logging_on) {
    return instance_setup(inst, name, (InterfaceType)fmuType, 2, logging_on);
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    (void)fmuResourceLocation, (void)visible; /* the model needs no resources and shows nothing */
    return host2_instantiate(refusal(instanceName, fmuGUID, fmuType), "Pendulum", instanceName, fmuType, functions,
                             loggingOn, sizeof(Fmi2Instance), offsetof(Fmi2Instance, callbacks), setup);
}

const char *fmi2GetTypesPlatform(void) {
    return fmi2TypesPlatform;
}

const char *fmi2GetVersion(void) {
    return fmi2Version;
}

void fmi2FreeInstance(fmi2Component c) {
    host2_free(c);
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    return (fmi2Status)instance_set_debug_logging(c, "fmi2SetDebugLogging", loggingOn, nCategories, categories);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    return (fmi2Status)instance_enter_initialization(c, "fmi2EnterInitializationMode");
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return (fmi2Status)instance_exit_initialization(c, "fmi2ExitInitializationMode");
}

fmi2Status fmi2Terminate(fmi2Component c) {
    return (fmi2Status)instance_terminate(c, "fmi2Terminate");
}

fmi2Status fmi2Reset(fmi2Component c) {
    return (fmi2Status)instance_reset(c, "fmi2Reset");
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    return (fmi2Status)instance_get_reals(c, "fmi2GetReal", vr, nvr, value);
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    return (fmi2Status)instance_set_reals(c, "fmi2SetReal", vr, nvr, value);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return (fmi2Status)instance_setup_experiment(c, "fmi2SetupExperiment", toleranceDefined, tolerance, startTime,
                                                 stopTimeDefined, stopTime);
}

/* Integer and Enumeration variables share fmi2Integer (FMI 2.0 2.1.7). */
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    size_t i;
    if (!instance_arrays_allowed(c, "fmi2GetInteger", CALL_GET_VARIABLES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        long got = 0;
        if (instance_get_integer(c, "fmi2GetInteger", vr[i], &got) != STATUS_OK) {
            return fmi2Error;
        }
        value[i] = (fmi2Integer)got;
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    size_t i;
    if (!instance_arrays_allowed(c, "fmi2SetInteger", CALL_SET_VARIABLES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        if (instance_set_integer(c, "fmi2SetInteger", vr[i], value[i]) != STATUS_OK) {
            return fmi2Error;
        }
    }
    return fmi2OK;
}

/* The model has no Boolean or String variables: any value reference is unknown. */
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    return (fmi2Status)instance_no_variables(c, "fmi2GetBoolean", CALL_GET_VARIABLES, vr, nvr, value);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    return (fmi2Status)instance_no_variables(c, "fmi2SetBoolean", CALL_SET_VARIABLES, vr, nvr, value);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    return (fmi2Status)instance_no_variables(c, "fmi2GetString", CALL_GET_VARIABLES, vr, nvr, value);
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    return (fmi2Status)instance_no_variables(c, "fmi2SetString", CALL_SET_VARIABLES, vr, nvr, value);
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state) {
    return (fmi2Status)instance_get_state(c, "fmi2GetFMUstate", state);
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
    return (fmi2Status)instance_set_state(c, "fmi2SetFMUstate", state);
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state) {
    return (fmi2Status)instance_free_state(c, "fmi2FreeFMUstate", state);
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t *size) {
    return (fmi2Status)instance_serialized_state_size(c, "fmi2SerializedFMUstateSize", state, size);
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte serializedState[], size_t size) {
    return (fmi2Status)instance_serialize_state(c, "fmi2SerializeFMUstate", state, (char *)serializedState, size);
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *state) {
    return (fmi2Status)instance_deserialize_state(c, "fmi2DeSerializeFMUstate", (const char *)serializedState, size,
                                                  state);
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    return (fmi2Status)instance_partials(c, "fmi2GetDirectionalDerivative", 0, vUnknown_ref, nUnknown, vKnown_ref,
                                         nKnown, dvKnown, dvUnknown);
}
