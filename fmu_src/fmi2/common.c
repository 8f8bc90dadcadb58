/* fmi2/common.c: the FMI 2.0 functions shared by Model Exchange and Co-Simulation (FMI 2.0
 * section 2.1), translated onto the shared instance (instance.h): instantiation with the
 * host's callbacks, life cycle, variables, FMU states and directional derivatives. */
#include <stddef.h>

#include "fmu_state_calls.h"
#include "host2.h"

/* The FMI 2.0 instance: the shared one first, then the host's callbacks (host2.h). */
typedef struct {
    Instance core;
    fmi2CallbackFunctions callbacks;
} Fmi2Instance;

/* NULL, or why fmi2Instantiate refuses. */
static const char *refusal(fmi2String instanceName, fmi2String fmuGUID, fmi2Type fmuType) {
    const char *why = instance_refusal(instanceName, fmuGUID);
    if (why == NULL && fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation) {
        why = "fmuType must be fmi2ModelExchange or fmi2CoSimulation";
    }
    return why;
}

static int setup(Instance *inst, const char *name, fmi2Type fmuType, int logging_on) {
    return instance_setup(inst, name, (InterfaceType)fmuType, 2, logging_on);
}

DEFINE_FMI2_INSTANTIATE(Fmi2Instance, "Pendulum", refusal, setup)

DEFINE_FMI2_PASSING_CALLS(instance_exit_initialization, instance_reset, instance_get_reals, instance_set_reals)

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return (fmi2Status)instance_setup_experiment(c, "fmi2SetupExperiment", toleranceDefined, tolerance, startTime,
                                                 stopTimeDefined, stopTime);
}

/* Integer and Enumeration variables share fmi2Integer (FMI 2.0 2.1.7). */
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    size_t i;
    if (!instance_arrays_allowed(c, "fmi2GetInteger", GET_MODES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        long got = 0;
        if (instance_get_integer(c, "fmi2GetInteger", vr[i], &got) != STATUS_OK) {
            return fmi2Error;
        }
        value[i] = (fmi2Integer)got;
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    size_t i;
    if (!instance_arrays_allowed(c, "fmi2SetInteger", SET_MODES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        if (instance_set_integer(c, "fmi2SetInteger", vr[i], value[i]) != STATUS_OK) {
            return fmi2Error;
        }
    }
    return fmi2OK;
}

/* The model has no Boolean or String variables. */
DEFINE_FMI2_NO_VARIABLES_OF_TYPE(Boolean, fmi2Boolean)
DEFINE_FMI2_NO_VARIABLES_OF_TYPE(String, fmi2String)

DEFINE_FMU_STATE_CALLS(fmi2Status, fmi2Component, fmi2FMUstate, fmi2Byte, fmi2GetFMUstate, fmi2SetFMUstate,
                       fmi2FreeFMUstate, fmi2SerializedFMUstateSize, fmi2SerializeFMUstate, fmi2DeSerializeFMUstate)

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    return (fmi2Status)instance_partials(c, "fmi2GetDirectionalDerivative", 0, vUnknown_ref, nUnknown, vKnown_ref,
                                         nKnown, dvKnown, dvUnknown);
}
