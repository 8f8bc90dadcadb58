/* fmi2/shared.c: the FMI 2.0 functions that every FMU of the project, Pendulum.fmu and the split
 * FMUs (split/layer2.c), passes to the shared instance unchanged (FMI 2.0 section 2.1): the
 * platform and version strings, freeing, logging, entering initialization, terminating, FMU
 * states (instance/state.c; a split FMU's model bytes through its StateModel), and the
 * Boolean and String variables, which no FMU of the project has. Linked by each FMI 2.0 FMU;
 * the functions whose work differs by model are in each one's own layer. */
#include "host2.h"

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

fmi2Status fmi2Terminate(fmi2Component c) {
    return (fmi2Status)instance_terminate(c, "fmi2Terminate");
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

/* No FMU of the project has Boolean or String variables: any value reference is unknown. */
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
