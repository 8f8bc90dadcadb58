/* fmi2/common.c: Pendulum's FMI 2.0 functions shared by Model Exchange and Co-Simulation (FMI
 * 2.0 section 2.1), translated onto the shared instance (instance.h): instantiation with the
 * host's callbacks, life cycle, Real and Integer variables and directional derivatives. What
 * every FMU of the project passes on unchanged (freeing, logging, FMU states) is in shared.c. */
#include <stddef.h>

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

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    (void)fmuResourceLocation, (void)visible; /* the model needs no resources and shows nothing */
    return host2_instantiate(refusal(instanceName, fmuGUID, fmuType), "Pendulum", instanceName, fmuType, functions,
                             loggingOn, sizeof(Fmi2Instance), offsetof(Fmi2Instance, callbacks), setup);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return (fmi2Status)instance_exit_initialization(c, "fmi2ExitInitializationMode");
}

fmi2Status fmi2Reset(fmi2Component c) {
    return (fmi2Status)instance_reset(c, "fmi2Reset");
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    return (fmi2Status)instance_get_reals(c, "fmi2GetReal", vr, nvr, value);
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    return (fmi2Status)instance_set_reals(c, "fmi2SetReal", vr, nvr, value);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return (fmi2Status)instance_setup_experiment(c, "fmi2SetupExperiment", toleranceDefined, tolerance, startTime,
                                                 stopTimeDefined, stopTime);
}

/* Integer and Enumeration variables share fmi2Integer (FMI 2.0 2.1.7). */
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    size_t i;
    if (!instance_arrays_allowed(c, "fmi2GetInteger", CALL_GET_VARIABLES, vr, nvr, value)) {
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
    if (!instance_arrays_allowed(c, "fmi2SetInteger", CALL_SET_VARIABLES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        if (instance_set_integer(c, "fmi2SetInteger", vr[i], value[i]) != STATUS_OK) {
            return fmi2Error;
        }
    }
    return fmi2OK;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    return (fmi2Status)instance_partials(c, "fmi2GetDirectionalDerivative", 0, vUnknown_ref, nUnknown, vKnown_ref,
                                         nKnown, dvKnown, dvUnknown);
}
