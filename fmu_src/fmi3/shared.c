/* fmi3/shared.c: the FMI 3.0 functions that every FMU of the project, Pendulum.fmu and the split
 * FMUs (split/layer3.c), passes to the shared instance unchanged (FMI 3.0 section 2.3): the
 * version, instantiation in Co-Simulation (each layer's fmi3_instantiate checks its model's
 * name and token), the refused Scheduled Execution, freeing, logging, terminating and FMU states
 * (instance/state.c; a split FMU's model bytes through its StateModel). Linked by each FMI 3.0
 * FMU; the functions whose work differs by model are in each one's own layer. */
#include "layer.h"

const char *fmi3GetVersion(void) {
    return fmi3Version;
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                         fmi3Boolean eventModeUsed, fmi3Boolean earlyReturnAllowed,
                                         const fmi3ValueReference requiredIntermediateVariables[],
                                         size_t nRequiredIntermediateVariables,
                                         fmi3InstanceEnvironment instanceEnvironment,
                                         fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback intermediateUpdate) {
    (void)resourcePath, (void)visible, (void)earlyReturnAllowed, (void)requiredIntermediateVariables;
    (void)intermediateUpdate; /* providesIntermediateUpdate="false": never called */
    if (eventModeUsed || nRequiredIntermediateVariables > 0) { /* no FMU of the project has either */
        fmi3_refuse(instanceEnvironment, logMessage, "fmi3InstantiateCoSimulation",
                    eventModeUsed ? "eventModeUsed, but hasEventMode is false"
                                  : "the model has no intermediate variables");
        return NULL;
    }
    return fmi3_instantiate("fmi3InstantiateCoSimulation", instanceName, instantiationToken, INTERFACE_CO_SIMULATION,
                            loggingOn, instanceEnvironment, logMessage);
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName, fmi3String instantiationToken,
                                               fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
                                               fmi3LockPreemptionCallback lockPreemption,
                                               fmi3UnlockPreemptionCallback unlockPreemption) {
    (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible, (void)loggingOn;
    (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;
    fmi3_refuse(instanceEnvironment, logMessage, "fmi3InstantiateScheduledExecution",
                "the FMU has no Scheduled Execution interface");
    return NULL;
}

void fmi3FreeInstance(fmi3Instance instance) {
    fmi3_free_instance(instance);
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
    return (fmi3Status)instance_set_debug_logging(instance, "fmi3SetDebugLogging", loggingOn, nCategories, categories);
}

fmi3Status fmi3Terminate(fmi3Instance instance) {
    return (fmi3Status)instance_terminate(instance, "fmi3Terminate");
}

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *state) {
    return (fmi3Status)instance_get_state(instance, "fmi3GetFMUState", state);
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState state) {
    return (fmi3Status)instance_set_state(instance, "fmi3SetFMUState", state);
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *state) {
    return (fmi3Status)instance_free_state(instance, "fmi3FreeFMUState", state);
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState state, size_t *size) {
    return (fmi3Status)instance_serialized_state_size(instance, "fmi3SerializedFMUStateSize", state, size);
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState state, fmi3Byte serializedState[], size_t size) {
    return (fmi3Status)instance_serialize_state(instance, "fmi3SerializeFMUState", state, (char *)serializedState,
                                                size);
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *state) {
    return (fmi3Status)instance_deserialize_state(instance, "fmi3DeserializeFMUState", (const char *)serializedState,
                                                  size, state);
}
