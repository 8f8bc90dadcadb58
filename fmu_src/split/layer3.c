/* layer3.c: the FMI 3.0 Co-Simulation layer of PendulumBody and PendulumGravity (split.h):
 * it only translates FMI 3.0 types onto split.c and the shared instance (instance.h). Linked
 * with fmi3/modelex.c and fmi3/absent.c, Pendulum.fmu's own refusals of Model Exchange (every
 * call refused by the instance's interface check; fmi3InstantiateModelExchange by
 * fmi3_instantiate below) and of the features neither FMU has (clocks, Configuration Mode,
 * Scheduled Execution).
 *
 * FMI 3.0 defines no input derivatives in Co-Simulation (FMI 2.0's
 * fmi2SetRealInputDerivatives has no 3.0 counterpart; a 3.0 FMU that wants to see its inputs
 * within a step asks for them by intermediate update, which these FMUs do not provide): the
 * input is held over every FMI 3.0 step. Output derivatives are fmi3GetOutputDerivatives's. */
#include <stdio.h>
#include <stdlib.h>

#include "layer.h"
#include "split.h"

typedef struct {
    SplitInstance split; /* first: an fmi3Instance is a SplitInstance and an Instance */
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log_message;
} Split3;

static void host_log(const Instance *inst, Status status, const char *category, const char *message) {
    const Split3 *self = (const Split3 *)inst;
    if (self->log_message != NULL) {
        self->log_message(self->environment, (fmi3Status)status, category, message);
    }
}

static void *host_allocate(const Instance *inst, size_t size) {
    (void)inst;
    return calloc(1, size);
}

static void host_release(const Instance *inst, void *memory) {
    (void)inst;
    free(memory);
}

static void refuse(fmi3InstanceEnvironment environment, fmi3LogMessageCallback logMessage, const char *function,
                   const char *reason) {
    if (logMessage != NULL) {
        char message[256];
        snprintf(message, sizeof message, "%s: %s", function, reason);
        logMessage(environment, fmi3Error, "logStatusError", message);
    }
}

/* layer.h's instantiation, called by fmi3InstantiateCoSimulation below and by fmi3/modelex.c's
 * fmi3InstantiateModelExchange, which it refuses. */
fmi3Instance fmi3_instantiate(const char *function, fmi3String instanceName, fmi3String instantiationToken,
                              InterfaceType type, fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                              fmi3LogMessageCallback logMessage) {
    Split3 *inst;
    const char *refusal = split_refusal(instanceName, instantiationToken);
    if (refusal == NULL && type != INTERFACE_CO_SIMULATION) {
        refusal = "the FMU has Co-Simulation only";
    }
    if (refusal != NULL) {
        refuse(environment, logMessage, function, refusal);
        return NULL;
    }
    inst = calloc(1, sizeof *inst);
    if (inst != NULL) {
        inst->environment = environment;
        inst->log_message = logMessage;
        inst->split.core.host.log = host_log;
        inst->split.core.host.allocate = host_allocate;
        inst->split.core.host.release = host_release;
        if (split_setup(&inst->split, instanceName, 3, loggingOn) != 0) {
            free(inst);
            inst = NULL;
        }
    }
    if (inst == NULL) {
        refuse(environment, logMessage, function, "out of memory");
    }
    return inst;
}

const char *fmi3GetVersion(void) { return fmi3Version; }

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
    if (eventModeUsed || nRequiredIntermediateVariables > 0) {
        refuse(instanceEnvironment, logMessage, "fmi3InstantiateCoSimulation",
               eventModeUsed ? "eventModeUsed, but hasEventMode is false" : "the model has no intermediate variables");
        return NULL;
    }
    return fmi3_instantiate("fmi3InstantiateCoSimulation", instanceName, instantiationToken,
                            INTERFACE_CO_SIMULATION, loggingOn, instanceEnvironment, logMessage);
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName, fmi3String instantiationToken,
                                               fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
                                               fmi3LockPreemptionCallback lockPreemption,
                                               fmi3UnlockPreemptionCallback unlockPreemption) {
    (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible, (void)loggingOn;
    (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;
    refuse(instanceEnvironment, logMessage, "fmi3InstantiateScheduledExecution", "the FMU has Co-Simulation only");
    return NULL;
}

void fmi3FreeInstance(fmi3Instance instance) {
    Split3 *inst = instance;
    if (inst != NULL) {
        instance_release(&inst->split.core);
        free(inst);
    }
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
    return (fmi3Status)instance_set_debug_logging(instance, "fmi3SetDebugLogging", loggingOn, nCategories,
                                                  categories);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
                                       fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    return (fmi3Status)instance_enter_initialization_with(instance, "fmi3EnterInitializationMode",
                                                          split_tolerance_defined(toleranceDefined, tolerance),
                                                          tolerance, startTime, stopTimeDefined, stopTime);
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    return (fmi3Status)split_exit_initialization(instance, "fmi3ExitInitializationMode");
}

fmi3Status fmi3Terminate(fmi3Instance instance) { return (fmi3Status)instance_terminate(instance, "fmi3Terminate"); }

fmi3Status fmi3Reset(fmi3Instance instance) { return (fmi3Status)split_reset(instance, "fmi3Reset"); }

/* Scalars only: one value per value reference. */
static int scalar_counts(fmi3Instance instance, const char *function, size_t nvr, size_t n_values) {
    if (instance != NULL && n_values != nvr) {
        instance_fail(instance, function, "nValues %zu differs from nValueReferences %zu: every variable is a scalar",
                      n_values, nvr);
        return 0;
    }
    return 1;
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],
                          size_t nValues) {
    if (!scalar_counts(instance, "fmi3GetFloat64", nvr, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)split_get_reals(instance, "fmi3GetFloat64", vr, nvr, values);
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t nValues) {
    if (!scalar_counts(instance, "fmi3SetFloat64", nvr, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)split_set_reals(instance, "fmi3SetFloat64", vr, nvr, values);
}

/* Types the FMUs have no variable of: any value reference is unknown. */
#define NO_VARIABLES_OF_TYPE(Name, Type)                                                                            \
    fmi3Status fmi3Get##Name(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, Type values[],     \
                             size_t nValues) {                                                                     \
        (void)nValues;                                                                                             \
        return (fmi3Status)instance_no_variables(instance, "fmi3Get" #Name, GET_MODES, vr, nvr, values);          \
    }                                                                                                              \
    fmi3Status fmi3Set##Name(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const Type values[], \
                             size_t nValues) {                                                                     \
        (void)nValues;                                                                                             \
        return (fmi3Status)instance_no_variables(instance, "fmi3Set" #Name, SET_MODES, vr, nvr, values);          \
    }
NO_VARIABLES_OF_TYPE(Float32, fmi3Float32)
NO_VARIABLES_OF_TYPE(Int8, fmi3Int8)
NO_VARIABLES_OF_TYPE(UInt8, fmi3UInt8)
NO_VARIABLES_OF_TYPE(Int16, fmi3Int16)
NO_VARIABLES_OF_TYPE(UInt16, fmi3UInt16)
NO_VARIABLES_OF_TYPE(Int32, fmi3Int32)
NO_VARIABLES_OF_TYPE(UInt32, fmi3UInt32)
NO_VARIABLES_OF_TYPE(Int64, fmi3Int64)
NO_VARIABLES_OF_TYPE(UInt64, fmi3UInt64)
NO_VARIABLES_OF_TYPE(Boolean, fmi3Boolean)
NO_VARIABLES_OF_TYPE(String, fmi3String)

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, size_t valueSizes[],
                         fmi3Binary values[], size_t nValues) {
    (void)valueSizes, (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetBinary", GET_MODES, vr, nvr, values);
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const size_t valueSizes[],
                         const fmi3Binary values[], size_t nValues) {
    (void)valueSizes, (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetBinary", SET_MODES, vr, nvr, values);
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Clock values[]) {
    return (fmi3Status)instance_no_variables(instance, "fmi3GetClock", GET_MODES, vr, nvr, values);
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Clock values[]) {
    return (fmi3Status)instance_no_variables(instance, "fmi3SetClock", SET_MODES, vr, nvr, values);
}

#define NO_FMU_STATES "canGetAndSetFMUState is false: the FMU provides no FMU states"

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *FMUState) {
    (void)FMUState;
    return (fmi3Status)split_not_provided(instance, "fmi3GetFMUState", NO_FMU_STATES);
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
    (void)FMUState;
    return (fmi3Status)split_not_provided(instance, "fmi3SetFMUState", NO_FMU_STATES);
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *FMUState) {
    (void)FMUState;
    return (fmi3Status)split_not_provided(instance, "fmi3FreeFMUState", NO_FMU_STATES);
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState, size_t *size) {
    (void)FMUState, (void)size;
    return (fmi3Status)split_not_provided(instance, "fmi3SerializedFMUStateSize", NO_FMU_STATES);
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size) {
    (void)FMUState, (void)serializedState, (void)size;
    return (fmi3Status)split_not_provided(instance, "fmi3SerializeFMUState", NO_FMU_STATES);
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState) {
    (void)serializedState, (void)size, (void)FMUState;
    return (fmi3Status)split_not_provided(instance, "fmi3DeserializeFMUState", NO_FMU_STATES);
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                        const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[],
                                        size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity) {
    (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed, (void)sensitivity;
    (void)nSensitivity;
    return (fmi3Status)split_not_provided(instance, "fmi3GetDirectionalDerivative",
                                          "providesDirectionalDerivatives is false");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[],
                                    size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity) {
    (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed, (void)sensitivity;
    (void)nSensitivity;
    return (fmi3Status)split_not_provided(instance, "fmi3GetAdjointDerivative", "providesAdjointDerivatives is false");
}

/* --- Co-Simulation (FMI 3.0 section 4.2) ------------------------------------------------- */

fmi3Status fmi3EnterStepMode(fmi3Instance instance) {
    /* hasEventMode is false: Step Mode follows initialization directly, never an Event Mode */
    return (fmi3Status)split_not_provided(instance, "fmi3EnterStepMode",
                                          "hasEventMode is false: there is no Event Mode to leave");
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues) {
    if (!scalar_counts(instance, "fmi3GetOutputDerivatives", nValueReferences, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)split_output_derivatives(instance, "fmi3GetOutputDerivatives", valueReferences,
                                                nValueReferences, orders, values);
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint, fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint, fmi3Boolean *eventHandlingNeeded,
                      fmi3Boolean *terminateSimulation, fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime) {
    Instance *inst = instance;
    Status status;
    (void)noSetFMUStatePriorToCurrentPoint; /* no FMU states */
    if (inst != NULL && (eventHandlingNeeded == NULL || terminateSimulation == NULL || earlyReturn == NULL ||
                         lastSuccessfulTime == NULL)) {
        return (fmi3Status)instance_fail(inst, "fmi3DoStep", "an output argument is NULL");
    }
    status = split_do_step(instance, "fmi3DoStep", currentCommunicationPoint, communicationStepSize);
    if (status == STATUS_OK) {
        *eventHandlingNeeded = fmi3False;
        *terminateSimulation = fmi3False;
        *earlyReturn = fmi3False;
        *lastSuccessfulTime = inst->data.time;
    }
    return (fmi3Status)status;
}
