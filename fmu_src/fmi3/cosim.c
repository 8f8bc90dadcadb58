/* fmi3/cosim.c: the FMI 3.0 Co-Simulation functions (section 4.2), translated onto the shared
 * instance (instance/motion.c, instance/derivatives.c). The FMU has no event mode in
 * Co-Simulation, no intermediate update and no early return (README, FMI 3.0). */
#include "layer.h"

DEFINE_FMI3_INSTANTIATE_CO_SIMULATION

fmi3Status fmi3EnterStepMode(fmi3Instance instance) {
    if (!instance_allowed_for(instance, "fmi3EnterStepMode", INTERFACE_CO_SIMULATION, 0)) {
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

DEFINE_FMI3_DO_STEP(instance_do_step)
