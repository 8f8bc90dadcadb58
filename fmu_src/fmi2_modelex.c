/* fmi2_modelex.c: the Model Exchange functions (FMI 2.0 section 3.2). The model has two
 * continuous states (theta, omega), no event indicators and no time events. */
#include <math.h>

#include "fmi2_instance.h"

#define N_STATES 2
#define STATE_READ_MODES (MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME | MODE_TERMINATED | MODE_ERROR)

fmi2Status fmi2EnterEventMode(fmi2Component c) {
    Instance *inst = c;
    if (!instance_allowed_for(inst, "fmi2EnterEventMode", fmi2ModelExchange, MODE_EVENT | MODE_CONTINUOUS_TIME)) {
        return fmi2Error;
    }
    inst->data.mode = MODE_EVENT;
    return fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo) {
    Instance *inst = c;
    if (!instance_allowed_for(inst, "fmi2NewDiscreteStates", fmi2ModelExchange, MODE_EVENT)) {
        return fmi2Error;
    }
    if (eventInfo == NULL) {
        return instance_fail(inst, "fmi2NewDiscreteStates", "eventInfo is NULL");
    }
    /* No discrete states and no events: the event iteration ends at once. */
    eventInfo->newDiscreteStatesNeeded = fmi2False;
    eventInfo->terminateSimulation = fmi2False;
    eventInfo->nominalsOfContinuousStatesChanged = fmi2False;
    eventInfo->valuesOfContinuousStatesChanged = fmi2False;
    eventInfo->nextEventTimeDefined = fmi2False;
    eventInfo->nextEventTime = 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
    Instance *inst = c;
    if (!instance_allowed_for(inst, "fmi2EnterContinuousTimeMode", fmi2ModelExchange, MODE_EVENT)) {
        return fmi2Error;
    }
    inst->data.mode = MODE_CONTINUOUS_TIME;
    return fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode, fmi2Boolean *terminateSimulation) {
    Instance *inst = c;
    (void)noSetFMUStatePriorToCurrentPoint;
    if (!instance_allowed_for(inst, "fmi2CompletedIntegratorStep", fmi2ModelExchange, MODE_CONTINUOUS_TIME)) {
        return fmi2Error;
    }
    if (enterEventMode == NULL || terminateSimulation == NULL) {
        return instance_fail(inst, "fmi2CompletedIntegratorStep", "enterEventMode or terminateSimulation is NULL");
    }
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
    Instance *inst = c;
    if (!instance_allowed_for(inst, "fmi2SetTime", fmi2ModelExchange, MODE_EVENT | MODE_CONTINUOUS_TIME)) {
        return fmi2Error;
    }
    if (!isfinite(time)) {
        return instance_fail(inst, "fmi2SetTime", "time must be finite");
    }
    inst->data.time = time;
    return fmi2OK;
}

/* Shared checks of the state-vector functions: mode, array and its length. */
static int states_allowed(Instance *inst, const char *function, unsigned modes, const void *array, size_t n,
                          size_t expected) {
    if (!instance_allowed_for(inst, function, fmi2ModelExchange, modes)) {
        return 0;
    }
    if (n != expected) {
        instance_fail(inst, function, "the array length is %zu, but the model has %zu", n, expected);
        return 0;
    }
    if (n > 0 && array == NULL) {
        instance_fail(inst, function, "the array is NULL");
        return 0;
    }
    return 1;
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {
    Instance *inst = c;
    if (!states_allowed(inst, "fmi2SetContinuousStates", MODE_CONTINUOUS_TIME, x, nx, N_STATES)) {
        return fmi2Error;
    }
    if (!isfinite(x[0]) || !isfinite(x[1])) {
        return instance_fail(inst, "fmi2SetContinuousStates", "states (%g, %g) must be finite", x[0], x[1]);
    }
    inst->data.theta = x[0];
    inst->data.omega = x[1];
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    Instance *inst = c;
    const char *problem;
    if (!states_allowed(inst, "fmi2GetDerivatives", STATE_READ_MODES, derivatives, nx, N_STATES)) {
        return fmi2Error;
    }
    problem = model_derivatives(&inst->data, &derivatives[0], &derivatives[1]);
    return problem == NULL ? fmi2OK : instance_fail(inst, "fmi2GetDerivatives", "%s", problem);
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni) {
    Instance *inst = c;
    return states_allowed(inst, "fmi2GetEventIndicators", STATE_READ_MODES, eventIndicators, ni, 0) ? fmi2OK
                                                                                                    : fmi2Error;
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
    Instance *inst = c;
    if (!states_allowed(inst, "fmi2GetContinuousStates", STATE_READ_MODES, x, nx, N_STATES)) {
        return fmi2Error;
    }
    x[0] = inst->data.theta;
    x[1] = inst->data.omega;
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx) {
    Instance *inst = c;
    if (!states_allowed(inst, "fmi2GetNominalsOfContinuousStates",
                        MODE_INSTANTIATED | STATE_READ_MODES, x_nominal, nx, N_STATES)) {
        return fmi2Error;
    }
    x_nominal[0] = 1.0; /* rad: angles of order 1 */
    x_nominal[1] = 1.0; /* rad/s */
    return fmi2OK;
}
