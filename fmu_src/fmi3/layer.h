/* fmi3/layer.h: the FMI 3.0 instance, the shared one (instance.h) plus the host's logger, the
 * instantiation shared by Model Exchange and Co-Simulation, and what every FMI 3.0 layer of
 * the project shares, Pendulum's (fmi3/) and the split FMUs' (split/layer3.c): the host's
 * logger behind InstanceHost, the instantiation's refusals and allocation, and the FMI 3.0
 * functions that only pass a call on to the model's core. */
#ifndef PENDULUM_FMI3_LAYER_H
#define PENDULUM_FMI3_LAYER_H

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include "fmi3_api.h"
#include "instance.h"

/* The host's logger as the layer keeps it; InstanceHost.context points at it. */
typedef struct {
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log_message;
} Fmi3Host;

typedef struct {
    Instance core; /* first: an fmi3Instance is also an Instance */
    Fmi3Host host3;
} Fmi3Instance;

/* Checks the name and the token, allocates and sets up an instance of interface `type`;
 * NULL (with the reason logged when there is a logger) if refused. Defined by the layer:
 * fmi3/common.c for Pendulum, split/layer3.c for the split FMUs. */
fmi3Instance fmi3_instantiate(const char *function, fmi3String instanceName, fmi3String instantiationToken,
                              InterfaceType type, fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                              fmi3LogMessageCallback logMessage);

static inline void fmi3_host_log(const Instance *inst, Status status, const char *category, const char *message) {
    const Fmi3Host *host3 = (const Fmi3Host *)inst->host.context;
    if (host3->log_message != NULL) {
        host3->log_message(host3->environment, (fmi3Status)status, category, message);
    }
}

/* FMI 3.0 hands the FMU no allocator: the C library's. */
static inline void *fmi3_host_allocate(const Instance *inst, size_t size) {
    (void)inst;
    return calloc(1, size);
}

static inline void fmi3_host_release(const Instance *inst, void *memory) {
    (void)inst;
    free(memory);
}

/* Logs "<function>: <reason>" as an error when there is a logger (function NULL: the reason
 * alone); for the calls that have no instance to log through. */
static inline void fmi3_refuse(fmi3InstanceEnvironment environment, fmi3LogMessageCallback logMessage,
                               const char *function, const char *reason) {
    if (logMessage != NULL) {
        char message[256];
        if (function != NULL) {
            snprintf(message, sizeof message, "%s: %s", function, reason);
        }
        logMessage(environment, fmi3Error, "logStatusError", function != NULL ? message : reason);
    }
}

/* The model's own set-up of a zeroed instance (instance_setup, split_setup): 0, or -1 when
 * out of memory. */
typedef int (*Fmi3Setup)(Instance *inst, const char *name, InterfaceType type, int logging_on);

/* fmi3_instantiate's work for a layer whose instance is `size` bytes, an Instance first and
 * an Fmi3Host at `host_at` bytes in: a refusal (NULL: none) logged by fmi3_refuse; then the
 * zeroed instance, its host wired, set up by `setup`. NULL if refused or out of memory, which
 * is logged with out_of_memory_function in front (fmi3_refuse). */
static inline Instance *fmi3_new_instance(const char *function, const char *refusal, size_t size, size_t host_at,
                                          Fmi3Setup setup, fmi3String instanceName, InterfaceType type,
                                          fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                                          fmi3LogMessageCallback logMessage, const char *out_of_memory_function) {
    Instance *inst;
    if (refusal != NULL) {
        fmi3_refuse(environment, logMessage, function, refusal);
        return NULL;
    }
    inst = calloc(1, size);
    if (inst != NULL) {
        Fmi3Host *host3 = (Fmi3Host *)((char *)inst + host_at);
        host3->environment = environment;
        host3->log_message = logMessage;
        inst->host.log = fmi3_host_log;
        inst->host.allocate = fmi3_host_allocate;
        inst->host.release = fmi3_host_release;
        inst->host.context = host3;
        if (setup(inst, instanceName, type, loggingOn) != 0) {
            free(inst);
            inst = NULL;
        }
    }
    if (inst == NULL) {
        fmi3_refuse(environment, logMessage, out_of_memory_function, "out of memory");
    }
    return inst;
}

/* Scalar variables only: a Get/Set call has one value per value reference. The mode (and
 * the call's logCalls line) is checked once, by the instance_* call that does the work. */
static inline int fmi3_scalar_counts(fmi3Instance instance, const char *function, size_t nvr, size_t n_values) {
    if (instance != NULL && n_values != nvr) {
        instance_fail(instance, function, "nValues %zu differs from nValueReferences %zu: every variable is a scalar",
                      n_values, nvr);
        return 0;
    }
    return 1;
}

/* fmi3DoStep over the model's do_step (instance_do_step, split_do_step): the output
 * arguments refused if one is NULL, before the step; set after a step that succeeded. No FMU
 * of the project has an event mode or returns early; noSetFMUStatePriorToCurrentPoint
 * changes nothing, as an FMU state (where there are any) is plain data. */
#define DEFINE_FMI3_DO_STEP(do_step)                                                                                  \
    fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,                               \
                          fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,            \
                          fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,                         \
                          fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime) {                                \
        Instance *inst = instance;                                                                                    \
        Status status;                                                                                                \
        (void)noSetFMUStatePriorToCurrentPoint;                                                                       \
        if (inst != NULL && (eventHandlingNeeded == NULL || terminateSimulation == NULL || earlyReturn == NULL ||      \
                             lastSuccessfulTime == NULL)) {                                                           \
            return (fmi3Status)instance_fail(inst, "fmi3DoStep", "an output argument is NULL");                       \
        }                                                                                                             \
        status = do_step(instance, "fmi3DoStep", currentCommunicationPoint, communicationStepSize);                   \
        if (inst != NULL && (status == STATUS_OK || status == STATUS_WARNING)) {                                      \
            *eventHandlingNeeded = fmi3False;                                                                         \
            *terminateSimulation = fmi3False;                                                                         \
            *earlyReturn = fmi3False;                                                                                 \
            *lastSuccessfulTime = inst->data.time;                                                                    \
        }                                                                                                             \
        return (fmi3Status)status;                                                                                    \
    }

/* fmi3InstantiateCoSimulation: no FMU of the project has an event mode or intermediate
 * variables; the rest is the layer's fmi3_instantiate. */
#define DEFINE_FMI3_INSTANTIATE_CO_SIMULATION                                                                         \
    fmi3Instance fmi3InstantiateCoSimulation(                                                                         \
        fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath, fmi3Boolean visible,         \
        fmi3Boolean loggingOn, fmi3Boolean eventModeUsed, fmi3Boolean earlyReturnAllowed,                             \
        const fmi3ValueReference requiredIntermediateVariables[], size_t nRequiredIntermediateVariables,              \
        fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage,                               \
        fmi3IntermediateUpdateCallback intermediateUpdate) {                                                          \
        (void)resourcePath, (void)visible, (void)earlyReturnAllowed, (void)requiredIntermediateVariables;             \
        (void)intermediateUpdate; /* providesIntermediateUpdate="false": never called */                              \
        if (eventModeUsed || nRequiredIntermediateVariables > 0) {                                                    \
            fmi3_refuse(instanceEnvironment, logMessage, "fmi3InstantiateCoSimulation",                               \
                        eventModeUsed ? "eventModeUsed, but hasEventMode is false"                                    \
                                      : "the model has no intermediate variables");                                   \
            return NULL;                                                                                              \
        }                                                                                                             \
        return fmi3_instantiate("fmi3InstantiateCoSimulation", instanceName, instantiationToken,                      \
                                INTERFACE_CO_SIMULATION, loggingOn, instanceEnvironment, logMessage);                 \
    }

/* The FMI 3.0 functions that only pass a call on: to the shared instance (instance.h), or to
 * the model's own exit_initialization, reset, get_reals and set_reals (Pendulum's are the
 * instance's, the split FMUs' those of split.h); fmi3InstantiateScheduledExecution refused
 * with `scheduled_refusal`. */
#define DEFINE_FMI3_PASSING_CALLS(exit_initialization, reset, get_reals, set_reals, scheduled_refusal)                \
    const char *fmi3GetVersion(void) { return fmi3Version; }                                                          \
    fmi3Instance fmi3InstantiateScheduledExecution(                                                                   \
        fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath, fmi3Boolean visible,         \
        fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage,        \
        fmi3ClockUpdateCallback clockUpdate, fmi3LockPreemptionCallback lockPreemption,                               \
        fmi3UnlockPreemptionCallback unlockPreemption) {                                                              \
        (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible, (void)loggingOn;             \
        (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;                                              \
        fmi3_refuse(instanceEnvironment, logMessage, "fmi3InstantiateScheduledExecution", scheduled_refusal);         \
        return NULL;                                                                                                  \
    }                                                                                                                 \
    void fmi3FreeInstance(fmi3Instance instance) {                                                                    \
        if (instance != NULL) {                                                                                       \
            instance_release(instance);                                                                               \
            free(instance);                                                                                           \
        }                                                                                                             \
    }                                                                                                                 \
    fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t nCategories,                  \
                                   const fmi3String categories[]) {                                                   \
        return (fmi3Status)instance_set_debug_logging(instance, "fmi3SetDebugLogging", loggingOn, nCategories,        \
                                                      categories);                                                    \
    }                                                                                                                 \
    fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {                                                    \
        return (fmi3Status)exit_initialization(instance, "fmi3ExitInitializationMode");                               \
    }                                                                                                                 \
    fmi3Status fmi3Terminate(fmi3Instance instance) {                                                                 \
        return (fmi3Status)instance_terminate(instance, "fmi3Terminate");                                             \
    }                                                                                                                 \
    fmi3Status fmi3Reset(fmi3Instance instance) { return (fmi3Status)reset(instance, "fmi3Reset"); }                  \
    fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],  \
                              size_t nValues) {                                                                       \
        if (!fmi3_scalar_counts(instance, "fmi3GetFloat64", nvr, nValues)) {                                          \
            return fmi3Error;                                                                                         \
        }                                                                                                             \
        return (fmi3Status)get_reals(instance, "fmi3GetFloat64", vr, nvr, values);                                    \
    }                                                                                                                 \
    fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,                       \
                              const fmi3Float64 values[], size_t nValues) {                                           \
        if (!fmi3_scalar_counts(instance, "fmi3SetFloat64", nvr, nValues)) {                                          \
            return fmi3Error;                                                                                         \
        }                                                                                                             \
        return (fmi3Status)set_reals(instance, "fmi3SetFloat64", vr, nvr, values);                                    \
    }

/* Get and Set of a type the model has no variable of: any value reference is unknown. */
#define DEFINE_FMI3_NO_VARIABLES_OF_TYPE(Name, Type)                                                                \
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

/* The types no FMU of the project has a variable of, Binary and Clock among them. */
#define DEFINE_FMI3_ABSENT_TYPES                                                                                      \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(Float32, fmi3Float32)                                                            \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(Int8, fmi3Int8)                                                                  \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(UInt8, fmi3UInt8)                                                                \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(Int16, fmi3Int16)                                                                \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(UInt16, fmi3UInt16)                                                              \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(UInt32, fmi3UInt32)                                                              \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(UInt64, fmi3UInt64)                                                              \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(Boolean, fmi3Boolean)                                                            \
    DEFINE_FMI3_NO_VARIABLES_OF_TYPE(String, fmi3String)                                                              \
    fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, size_t valueSizes[],  \
                             fmi3Binary values[], size_t nValues) {                                                  \
        (void)valueSizes, (void)nValues;                                                                             \
        return (fmi3Status)instance_no_variables(instance, "fmi3GetBinary", GET_MODES, vr, nvr, values);            \
    }                                                                                                                \
    fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,                       \
                             const size_t valueSizes[], const fmi3Binary values[], size_t nValues) {                 \
        (void)valueSizes, (void)nValues;                                                                             \
        return (fmi3Status)instance_no_variables(instance, "fmi3SetBinary", SET_MODES, vr, nvr, values);            \
    }                                                                                                                \
    fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Clock values[]) { \
        return (fmi3Status)instance_no_variables(instance, "fmi3GetClock", GET_MODES, vr, nvr, values);             \
    }                                                                                                                \
    fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,                        \
                            const fmi3Clock values[]) {                                                              \
        return (fmi3Status)instance_no_variables(instance, "fmi3SetClock", SET_MODES, vr, nvr, values);             \
    }

#endif
