/* fmi3/cosim.c: the FMI 3.0 Co-Simulation functions (section 4.2), translated onto the shared
 * instance (instance/motion.c, instance/derivatives.c). The FMU has no event mode in
 * Co-Simulation, no intermediate update and no early return (README, FMI 3.0). */
#include "layer.h"

fmi3Status fmi3EnterStepMode(fmi3Instance instance) {
    if (!instance_call_allowed(instance, "fmi3EnterStepMode", CALL_ENTER_STEP_MODE)) {
        return fmi3Error;
    }
    return fmi3OK;
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues) {
    if (instance != NULL && nValues != nValueReferences) {
        return (fmi3Status)instance_fail(instance, "fmi3GetOutputDerivatives",
                                         "nValues %zu differs from nValueReferences %zu", nValues, nValueReferences);
    }
    return (fmi3Status)instance_output_derivatives(instance, "fmi3GetOutputDerivatives", valueReferences,
                                                   nValueReferences, orders, values);
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation, fmi3Boolean *earlyReturn,
                      fmi3Float64 *lastSuccessfulTime) {
    Status status;
    (void)noSetFMUStatePriorToCurrentPoint; /* the solver state is plain data: nothing to drop */
    if (fmi3_step_outputs_missing(instance, eventHandlingNeeded, terminateSimulation, earlyReturn,
                                  lastSuccessfulTime)) {
        return fmi3Error;
    }
    status = instance_do_step(instance, "fmi3DoStep", currentCommunicationPoint, communicationStepSize);
    fmi3_step_outputs(instance, status, eventHandlingNeeded, terminateSimulation, earlyReturn, lastSuccessfulTime);
    return (fmi3Status)status;
}
