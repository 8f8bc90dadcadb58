/* layer3.c: the FMI 3.0 Co-Simulation layer of PendulumBody and PendulumGravity (split.h):
 * it only translates FMI 3.0 types onto split.c and the shared instance (instance.h). Linked
 * with fmi3/shared.c (what every FMU of the project passes on unchanged: freeing, logging, FMU
 * states), fmi3/modelex.c and fmi3/absent.c, Pendulum.fmu's own refusals of Model Exchange (every
 * call refused by the instance's interface check; fmi3InstantiateModelExchange by
 * fmi3_instantiate below) and of the features neither FMU has (clocks, Configuration Mode,
 * Scheduled Execution).
 *
 * FMI 3.0 defines no input derivatives in Co-Simulation (FMI 2.0's
 * fmi2SetRealInputDerivatives has no 3.0 counterpart; a 3.0 FMU that wants to see its inputs
 * within a step asks for them by intermediate update, which these FMUs do not provide): the
 * input is held over every FMI 3.0 step. Output derivatives are fmi3GetOutputDerivatives's. */
#include <stddef.h>

#include "layer.h"
#include "split.h"

typedef struct {
    SplitInstance split; /* first: an fmi3Instance is a SplitInstance and an Instance */
    Fmi3Host host3;
} Split3;

static int setup(Instance *inst, const char *name, InterfaceType type, int logging_on) {
    (void)type; /* Co-Simulation: fmi3_instantiate refuses any other */
    return split_setup((SplitInstance *)inst, name, 3, logging_on);
}

/* layer.h's instantiation, called by fmi3InstantiateCoSimulation and by fmi3/modelex.c's
 * fmi3InstantiateModelExchange, which it refuses. */
fmi3Instance fmi3_instantiate(const char *function, fmi3String instanceName, fmi3String instantiationToken,
                              InterfaceType type, fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                              fmi3LogMessageCallback logMessage) {
    const char *refusal = split_refusal(instanceName, instantiationToken);
    if (refusal == NULL && type != INTERFACE_CO_SIMULATION) {
        refusal = "the FMU has Co-Simulation only";
    }
    return fmi3_new_instance(function, refusal, sizeof(Split3), offsetof(Split3, host3), setup, instanceName, type,
                             loggingOn, environment, logMessage, function);
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    return (fmi3Status)split_exit_initialization(instance, "fmi3ExitInitializationMode");
}

fmi3Status fmi3Reset(fmi3Instance instance) {
    return (fmi3Status)split_reset(instance, "fmi3Reset");
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],
                          size_t nValues) {
    if (!fmi3_scalar_counts(instance, "fmi3GetFloat64", nvr, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)split_get_reals(instance, "fmi3GetFloat64", vr, nvr, values);
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 values[],
                          size_t nValues) {
    if (!fmi3_scalar_counts(instance, "fmi3SetFloat64", nvr, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)split_set_reals(instance, "fmi3SetFloat64", vr, nvr, values);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
                                       fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    return (fmi3Status)instance_enter_initialization_with(instance, "fmi3EnterInitializationMode",
                                                          split_tolerance_defined(toleranceDefined, tolerance),
                                                          tolerance, startTime, stopTimeDefined, stopTime);
}

/* No Integer variables either (the other types: fmi3/absent.c): any value reference is unknown. */
fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int32 values[],
                        size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetInt32", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int32 values[],
                        size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetInt32", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int64 values[],
                        size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetInt64", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int64 values[],
                        size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetInt64", CALL_SET_VARIABLES, vr, nvr, values);
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
    if (!fmi3_scalar_counts(instance, "fmi3GetOutputDerivatives", nValueReferences, nValues)) {
        return fmi3Error;
    }
    return (fmi3Status)split_output_derivatives(instance, "fmi3GetOutputDerivatives", valueReferences,
                                                nValueReferences, orders, values);
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation, fmi3Boolean *earlyReturn,
                      fmi3Float64 *lastSuccessfulTime) {
    Status status;
    (void)noSetFMUStatePriorToCurrentPoint; /* a state is a copy: nothing kept for a rollback to free */
    if (fmi3_step_outputs_missing(instance, eventHandlingNeeded, terminateSimulation, earlyReturn,
                                  lastSuccessfulTime)) {
        return fmi3Error;
    }
    status = split_do_step(instance, "fmi3DoStep", currentCommunicationPoint, communicationStepSize);
    fmi3_step_outputs(instance, status, eventHandlingNeeded, terminateSimulation, earlyReturn, lastSuccessfulTime);
    return (fmi3Status)status;
}
