/* fmi3/modelex.c: the FMI 3.0 Model Exchange functions (section 3.2), translated onto the
 * shared instance (instance/motion.c). */
#include "layer.h"

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
    (void)resourcePath; /* the model needs no resources */
    (void)visible;
    return fmi3_instantiate("fmi3InstantiateModelExchange", instanceName, instantiationToken,
                            INTERFACE_MODEL_EXCHANGE, loggingOn, instanceEnvironment, logMessage);
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance) {
    return (fmi3Status)instance_enter_event_mode(instance, "fmi3EnterEventMode");
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation, fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged, fmi3Boolean *nextEventTimeDefined,
                                    fmi3Float64 *nextEventTime) {
    Status status = instance_new_discrete_states(
        instance, "fmi3UpdateDiscreteStates",
        discreteStatesNeedUpdate == NULL || terminateSimulation == NULL || nominalsOfContinuousStatesChanged == NULL ||
            valuesOfContinuousStatesChanged == NULL || nextEventTimeDefined == NULL || nextEventTime == NULL);
    if (status == STATUS_OK) {
        *discreteStatesNeedUpdate = fmi3False;
        *terminateSimulation = fmi3False;
        *nominalsOfContinuousStatesChanged = fmi3False;
        *valuesOfContinuousStatesChanged = fmi3False;
        *nextEventTimeDefined = fmi3False;
        *nextEventTime = 0.0;
    }
    return (fmi3Status)status;
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
    return (fmi3Status)instance_enter_continuous_time_mode(instance, "fmi3EnterContinuousTimeMode");
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *enterEventMode, fmi3Boolean *terminateSimulation) {
    int enter = 0, terminate = 0;
    Status status = instance_completed_integrator_step(instance, "fmi3CompletedIntegratorStep",
                                                       enterEventMode == NULL ? NULL : &enter,
                                                       terminateSimulation == NULL ? NULL : &terminate);
    (void)noSetFMUStatePriorToCurrentPoint;
    if (status == STATUS_OK) {
        *enterEventMode = enter != 0;
        *terminateSimulation = terminate != 0;
    }
    return (fmi3Status)status;
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time) {
    return (fmi3Status)instance_set_time(instance, "fmi3SetTime", time);
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[],
                                   size_t nContinuousStates) {
    return (fmi3Status)instance_set_states(instance, "fmi3SetContinuousStates", continuousStates, nContinuousStates);
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[],
                                             size_t nContinuousStates) {
    return (fmi3Status)instance_get_state_derivatives(instance, "fmi3GetContinuousStateDerivatives", derivatives,
                                                      nContinuousStates);
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 eventIndicators[], size_t nEventIndicators) {
    return (fmi3Status)instance_get_event_indicators(instance, "fmi3GetEventIndicators", eventIndicators,
                                                     nEventIndicators);
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[], size_t nContinuousStates) {
    return (fmi3Status)instance_get_states(instance, "fmi3GetContinuousStates", continuousStates, nContinuousStates);
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[],
                                             size_t nContinuousStates) {
    return (fmi3Status)instance_get_nominals(instance, "fmi3GetNominalsOfContinuousStates", nominals,
                                             nContinuousStates);
}

/* FMI 3.0 3.2.3: the sizes of the state vector and the event indicators, in any mode. */
static fmi3Status report_count(fmi3Instance instance, const char *function, size_t *count, size_t value) {
    if (!instance_call_allowed(instance, function, CALL_GET_NUMBER_OF)) {
        return fmi3Error;
    }
    if (count == NULL) {
        return (fmi3Status)instance_fail(instance, function, "the output argument is NULL");
    }
    *count = value;
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t *nEventIndicators) {
    return report_count(instance, "fmi3GetNumberOfEventIndicators", nEventIndicators, 0);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t *nContinuousStates) {
    return report_count(instance, "fmi3GetNumberOfContinuousStates", nContinuousStates, N_STATES);
}
