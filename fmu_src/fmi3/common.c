/* fmi3/common.c: Pendulum's FMI 3.0 functions of every interface (FMI 3.0 section 2.3),
 * translated onto the shared instance (instance.h): instantiation, life cycle, variables of
 * each type, directional and adjoint derivatives. What every FMU of the project passes on
 * unchanged (freeing, logging, FMU states) is in shared.c; the refusals of what this model does not
 * have (variables of the other types, clocks, Configuration Mode, variable dependencies at
 * run time) are in fmi3/absent.c.
 * The FMI 3.0 declarations are the project's own, written from the standard (fmi3_api.h). */
#include <stddef.h>

#include "layer.h"
#include "pendulum_vrs.h"

static int setup(Instance *inst, const char *name, InterfaceType type, int logging_on) {
    return instance_setup(inst, name, type, 3, logging_on);
}

fmi3Instance fmi3_instantiate(const char *function, fmi3String instanceName, fmi3String instantiationToken,
                              InterfaceType type, fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                              fmi3LogMessageCallback logMessage) {
    /* out of memory: the reason alone, without the function */
    return fmi3_new_instance(function, instance_refusal(instanceName, instantiationToken), sizeof(Fmi3Instance),
                             offsetof(Fmi3Instance, host3), setup, instanceName, type, loggingOn, environment,
                             logMessage, NULL);
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    return (fmi3Status)instance_exit_initialization(instance, "fmi3ExitInitializationMode");
}

fmi3Status fmi3Reset(fmi3Instance instance) {
    return (fmi3Status)instance_reset(instance, "fmi3Reset");
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],
                          size_t nValues) {
    if (!fmi3_scalar_counts(instance, "fmi3GetFloat64", nvr, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)instance_get_reals(instance, "fmi3GetFloat64", vr, nvr, values);
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 values[],
                          size_t nValues) {
    if (!fmi3_scalar_counts(instance, "fmi3SetFloat64", nvr, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)instance_set_reals(instance, "fmi3SetFloat64", vr, nvr, values);
}

/* FMI 3.0 folds 2.0's fmi2SetupExperiment into fmi3EnterInitializationMode: one call, one check. */
fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
                                       fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    return (fmi3Status)instance_enter_initialization_with(instance, "fmi3EnterInitializationMode", toleranceDefined,
                                                          tolerance, startTime, stopTimeDefined, stopTime);
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
static int integers_allowed(fmi3Instance instance, const char *function, FmiCall call, const fmi3ValueReference vr[],
                            size_t nvr, const void *values, size_t n_values, int enumeration) {
    size_t i;
    if (!fmi3_scalar_counts(instance, function, nvr, n_values) ||
        !instance_arrays_allowed(instance, function, call, vr, nvr, values)) {
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
    if (!integers_allowed(instance, function, CALL_GET_VARIABLES, vr, nvr, values, n_values, enumeration)) {
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
    if (!integers_allowed(instance, function, CALL_SET_VARIABLES, vr, nvr, values, n_values, enumeration)) {
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
