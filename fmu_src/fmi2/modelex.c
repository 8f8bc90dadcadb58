/* fmi2/modelex.c: the FMI 2.0 Model Exchange functions (section 3.2), translated onto the
 * shared instance (instance/motion.c). */
#include "fmi2_api.h"
#include "instance.h"

fmi2Status fmi2EnterEventMode(fmi2Component c) {
    return (fmi2Status)instance_enter_event_mode(c, "fmi2EnterEventMode");
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo) {
    Status status = instance_new_discrete_states(c, "fmi2NewDiscreteStates", eventInfo == NULL);
    if (status == STATUS_OK) {
        eventInfo->newDiscreteStatesNeeded = fmi2False;
        eventInfo->terminateSimulation = fmi2False;
        eventInfo->nominalsOfContinuousStatesChanged = fmi2False;
        eventInfo->valuesOfContinuousStatesChanged = fmi2False;
        eventInfo->nextEventTimeDefined = fmi2False;
        eventInfo->nextEventTime = 0.0;
    }
    return (fmi2Status)status;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
    return (fmi2Status)instance_enter_continuous_time_mode(c, "fmi2EnterContinuousTimeMode");
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode, fmi2Boolean *terminateSimulation) {
    (void)noSetFMUStatePriorToCurrentPoint;
    return (fmi2Status)instance_completed_integrator_step(c, "fmi2CompletedIntegratorStep", enterEventMode,
                                                          terminateSimulation);
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
    return (fmi2Status)instance_set_time(c, "fmi2SetTime", time);
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {
    return (fmi2Status)instance_set_states(c, "fmi2SetContinuousStates", x, nx);
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    return (fmi2Status)instance_get_state_derivatives(c, "fmi2GetDerivatives", derivatives, nx);
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni) {
    return (fmi2Status)instance_get_event_indicators(c, "fmi2GetEventIndicators", eventIndicators, ni);
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
    return (fmi2Status)instance_get_states(c, "fmi2GetContinuousStates", x, nx);
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx) {
    return (fmi2Status)instance_get_nominals(c, "fmi2GetNominalsOfContinuousStates", x_nominal, nx);
}
