/* fmi3/common.c: the FMI 3.0 functions of every interface (FMI 3.0 section 2.3), translated
 * onto the shared instance (instance.h): instantiation, life cycle, variables of each type,
 * FMU states, directional and adjoint derivatives, and the refusals of what this model
 * does not have (clocks, Configuration Mode, variable dependencies at run time).
 * The FMI 3.0 declarations are the project's own, written from the standard (fmi3_api.h). */
#include <stdio.h>
#include <stdlib.h>

#include "layer.h"
#include "fmu_state_calls.h"
#include "pendulum_vrs.h"

static void host_log(const Instance *inst, Status status, const char *category, const char *message) {
    const Fmi3Instance *self = (const Fmi3Instance *)inst;
    if (self->log_message != NULL) {
        self->log_message(self->environment, (fmi3Status)status, category, message);
    }
}

/* FMI 3.0 hands the FMU no allocator: the C library's. */
static void *host_allocate(const Instance *inst, size_t size) {
    (void)inst;
    return calloc(1, size);
}

static void host_release(const Instance *inst, void *memory) {
    (void)inst;
    free(memory);
}

fmi3Instance fmi3_instantiate(const char *function, fmi3String instanceName, fmi3String instantiationToken,
                              InterfaceType type, fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                              fmi3LogMessageCallback logMessage) {
    Fmi3Instance *inst;
    const char *refusal = instance_refusal(instanceName, instantiationToken);
    if (refusal != NULL) {
        if (logMessage != NULL) {
            char message[256];
            snprintf(message, sizeof message, "%s: %s", function, refusal);
            logMessage(environment, fmi3Error, "logStatusError", message);
        }
        return NULL;
    }
    inst = calloc(1, sizeof *inst);
    if (inst != NULL) {
        inst->environment = environment;
        inst->log_message = logMessage;
        inst->core.host.log = host_log;
        inst->core.host.allocate = host_allocate;
        inst->core.host.release = host_release;
        if (instance_setup(&inst->core, instanceName, type, 3, loggingOn) != 0) {
            free(inst);
            inst = NULL;
        }
    }
    if (inst == NULL && logMessage != NULL) {
        logMessage(environment, fmi3Error, "logStatusError", "out of memory");
    }
    return inst;
}

const char *fmi3GetVersion(void) { return fmi3Version; }

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName, fmi3String instantiationToken,
                                               fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
                                               fmi3LockPreemptionCallback lockPreemption,
                                               fmi3UnlockPreemptionCallback unlockPreemption) {
    (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible, (void)loggingOn;
    (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;
    if (logMessage != NULL) {
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "fmi3InstantiateScheduledExecution: the FMU has no Scheduled Execution interface");
    }
    return NULL;
}

void fmi3FreeInstance(fmi3Instance instance) {
    Fmi3Instance *inst = instance;
    if (inst != NULL) {
        instance_release(&inst->core);
        free(inst);
    }
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
    return (fmi3Status)instance_set_debug_logging(instance, "fmi3SetDebugLogging", loggingOn, nCategories,
                                                  categories);
}

/* FMI 3.0 folds 2.0's fmi2SetupExperiment into fmi3EnterInitializationMode: one call, one check. */
fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
                                       fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    return (fmi3Status)instance_enter_initialization_with(instance, "fmi3EnterInitializationMode", toleranceDefined,
                                                          tolerance, startTime, stopTimeDefined, stopTime);
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    return (fmi3Status)instance_exit_initialization(instance, "fmi3ExitInitializationMode");
}

fmi3Status fmi3Terminate(fmi3Instance instance) { return (fmi3Status)instance_terminate(instance, "fmi3Terminate"); }

fmi3Status fmi3Reset(fmi3Instance instance) { return (fmi3Status)instance_reset(instance, "fmi3Reset"); }

/* Scalar variables only: a Get/Set call has one value per value reference. The mode (and
 * the call's logCalls line) is checked once, by the instance_* call that does the work. */
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
    return (fmi3Status)instance_get_reals(instance, "fmi3GetFloat64", vr, nvr, values);
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t nValues) {
    if (!scalar_counts(instance, "fmi3SetFloat64", nvr, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)instance_set_reals(instance, "fmi3SetFloat64", vr, nvr, values);
}

/* The statistics are Int32 variables, the Enumeration `solver` is accessed as Int64 (FMI 3.0
 * 2.4.7.5): each call takes only value references of its own type. */
static int of_type(fmi3Instance instance, const char *function, fmi3ValueReference vr, int enumeration) {
    const int is_solver = vr == VR_SOLVER;
    const int is_stat = vr == VR_STATS_STEPS || vr == VR_STATS_REJECTED_STEPS || vr == VR_STATS_RHS_EVALUATIONS;
    if (enumeration ? is_solver : is_stat) {
        return 1;
    }
    instance_fail(instance, function, "unknown value reference %u for this type (solver is Int64, stats.* Int32)", vr);
    return 0;
}

/* The shared checks of the integer calls: counts, arrays, and each value reference's type. */
static int integers_allowed(fmi3Instance instance, const char *function, unsigned modes, const fmi3ValueReference vr[],
                            size_t nvr, const void *values, size_t n_values, int enumeration) {
    size_t i;
    if (!scalar_counts(instance, function, nvr, n_values) ||
        !instance_arrays_allowed(instance, function, modes, vr, nvr, values)) {
        return 0;
    }
    for (i = 0; i < nvr; i++) {
        if (!of_type(instance, function, vr[i], enumeration)) {
            return 0;
        }
    }
    return 1;
}

/* Int32 (enumeration = 0: the statistics) or Int64 (1: the solver) values, read or written. */
static fmi3Status get_integers(fmi3Instance instance, const char *function, const fmi3ValueReference vr[], size_t nvr,
                               void *values, size_t n_values, int enumeration) {
    size_t i;
    long got = 0;
    if (!integers_allowed(instance, function, GET_MODES, vr, nvr, values, n_values, enumeration)) {
        return fmi3Error;
    }
    for (i = 0; i < nvr; i++) {
        if (instance_get_integer(instance, function, vr[i], &got) != STATUS_OK) {
            return fmi3Error;
        }
        if (enumeration) {
            ((fmi3Int64 *)values)[i] = got;
        } else {
            ((fmi3Int32 *)values)[i] = (fmi3Int32)got;
        }
    }
    return fmi3OK;
}

static fmi3Status set_integers(fmi3Instance instance, const char *function, const fmi3ValueReference vr[], size_t nvr,
                               const void *values, size_t n_values, int enumeration) {
    size_t i;
    if (!integers_allowed(instance, function, SET_MODES, vr, nvr, values, n_values, enumeration)) {
        return fmi3Error;
    }
    for (i = 0; i < nvr; i++) {
        /* an Int64 beyond a 32-bit long is no item of Solver either: narrowed, it is refused as such */
        fmi3Int64 wide = enumeration ? ((const fmi3Int64 *)values)[i] : ((const fmi3Int32 *)values)[i];
        long value = wide > 2147483647 ? 2147483647L : wide < -2147483647 ? -2147483647L : (long)wide;
        if (instance_set_integer(instance, function, vr[i], value) != STATUS_OK) {
            return fmi3Error;
        }
    }
    return fmi3OK;
}

fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int32 values[],
                        size_t nValues) {
    return get_integers(instance, "fmi3GetInt32", vr, nvr, values, nValues, 0);
}

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int32 values[],
                        size_t nValues) {
    return set_integers(instance, "fmi3SetInt32", vr, nvr, values, nValues, 0);
}

fmi3Status fmi3GetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int64 values[],
                        size_t nValues) {
    return get_integers(instance, "fmi3GetInt64", vr, nvr, values, nValues, 1);
}

fmi3Status fmi3SetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int64 values[],
                        size_t nValues) {
    return set_integers(instance, "fmi3SetInt64", vr, nvr, values, nValues, 1);
}

/* Types the model has no variable of: any value reference is unknown. */
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
NO_VARIABLES_OF_TYPE(UInt32, fmi3UInt32)
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

DEFINE_FMU_STATE_CALLS(fmi3Status, fmi3Instance, fmi3FMUState, fmi3Byte, fmi3GetFMUState, fmi3SetFMUState,
                       fmi3FreeFMUState, fmi3SerializedFMUStateSize, fmi3SerializeFMUState, fmi3DeserializeFMUState)

/* Seed and sensitivity lengths: one entry per known (directional: per unknown) and back. */
static fmi3Status partials(fmi3Instance instance, const char *function, int adjoint, const fmi3ValueReference u[],
                           size_t nu, const fmi3ValueReference k[], size_t nk, const fmi3Float64 seed[],
                           size_t n_seed, fmi3Float64 sensitivity[], size_t n_sensitivity) {
    if (instance != NULL && (n_seed != (adjoint ? nu : nk) || n_sensitivity != (adjoint ? nk : nu))) {
        return (fmi3Status)instance_fail(instance, function, "nSeed %zu or nSensitivity %zu do not match %zu unknowns "
                                         "and %zu knowns of scalar variables", n_seed, n_sensitivity, nu, nk);
    }
    return (fmi3Status)instance_partials(instance, function, adjoint, u, nu, k, nk, seed, sensitivity);
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                        const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[],
                                        size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity) {
    return partials(instance, "fmi3GetDirectionalDerivative", 0, unknowns, nUnknowns, knowns, nKnowns, seed, nSeed,
                    sensitivity, nSensitivity);
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[],
                                    size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity) {
    return partials(instance, "fmi3GetAdjointDerivative", 1, unknowns, nUnknowns, knowns, nKnowns, seed, nSeed,
                    sensitivity, nSensitivity);
}
