/* fmi2/common.c: the FMI 2.0 functions shared by Model Exchange and Co-Simulation (FMI 2.0
 * section 2.1), translated onto the shared instance (instance.h): instantiation with the
 * host's callbacks, life cycle, variables, FMU states and directional derivatives. */
#include <string.h>

#include "fmi2_api.h"
#include "fmu_state_calls.h"
#include "instance.h"

/* The FMI 2.0 instance: the shared one first, then the host's callbacks. */
typedef struct {
    Instance core;
    fmi2CallbackFunctions callbacks;
} Fmi2Instance;

static void host_log(const Instance *inst, Status status, const char *category, const char *message) {
    const fmi2CallbackFunctions *callbacks = &((const Fmi2Instance *)inst)->callbacks;
    /* The message goes through "%s": a '%' in it must not be read as a format. */
    callbacks->logger(callbacks->componentEnvironment, inst->name, (fmi2Status)status, category, "%s", message);
}

static void *host_allocate(const Instance *inst, size_t size) {
    return ((const Fmi2Instance *)inst)->callbacks.allocateMemory(1, size);
}

static void host_release(const Instance *inst, void *memory) {
    ((const Fmi2Instance *)inst)->callbacks.freeMemory(memory);
}

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    Fmi2Instance *inst;
    const char *refusal = instance_refusal(instanceName, fmuGUID);
    (void)fmuResourceLocation; /* the model needs no resources */
    (void)visible;
    /* 2.1.5: allocateMemory and freeMemory are required; without a logger no error could be
     * reported, so it is required as well. */
    if (functions == NULL || functions->allocateMemory == NULL || functions->freeMemory == NULL ||
        functions->logger == NULL) {
        return NULL;
    }
    if (refusal == NULL && fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation) {
        refusal = "fmuType must be fmi2ModelExchange or fmi2CoSimulation";
    }
    if (refusal != NULL) {
        functions->logger(functions->componentEnvironment, instanceName != NULL && instanceName[0] != '\0'
                          ? instanceName : "Pendulum", fmi2Error, "logStatusError", "fmi2Instantiate: %s", refusal);
        return NULL;
    }
    inst = functions->allocateMemory(1, sizeof *inst);
    if (inst != NULL) {
        inst->callbacks = *functions;
        inst->core.host.log = host_log;
        inst->core.host.allocate = host_allocate;
        inst->core.host.release = host_release;
    }
    if (inst == NULL || instance_setup(&inst->core, instanceName, (InterfaceType)fmuType, 2, loggingOn) != 0) {
        if (inst != NULL) {
            functions->freeMemory(inst);
        }
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error, "logStatusError",
                          "fmi2Instantiate: out of memory");
        return NULL;
    }
    return inst;
}

void fmi2FreeInstance(fmi2Component c) {
    Fmi2Instance *inst = c;
    if (inst != NULL) {
        fmi2CallbackFreeMemory release = inst->callbacks.freeMemory;
        instance_release(&inst->core);
        release(inst);
    }
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    return (fmi2Status)instance_set_debug_logging(c, "fmi2SetDebugLogging", loggingOn, nCategories, categories);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return (fmi2Status)instance_setup_experiment(c, "fmi2SetupExperiment", toleranceDefined, tolerance, startTime,
                                                 stopTimeDefined, stopTime);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    return (fmi2Status)instance_enter_initialization(c, "fmi2EnterInitializationMode");
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return (fmi2Status)instance_exit_initialization(c, "fmi2ExitInitializationMode");
}

fmi2Status fmi2Terminate(fmi2Component c) { return (fmi2Status)instance_terminate(c, "fmi2Terminate"); }

fmi2Status fmi2Reset(fmi2Component c) { return (fmi2Status)instance_reset(c, "fmi2Reset"); }

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    return (fmi2Status)instance_get_reals(c, "fmi2GetReal", vr, nvr, value);
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    return (fmi2Status)instance_set_reals(c, "fmi2SetReal", vr, nvr, value);
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

/* The model has no Boolean or String variables: any value reference is unknown. */
#define NO_VARIABLES_OF_TYPE(Name, Type)                                                                       \
    fmi2Status fmi2Get##Name(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, Type value[]) {       \
        return (fmi2Status)instance_no_variables(c, "fmi2Get" #Name, GET_MODES, vr, nvr, value);              \
    }                                                                                                          \
    fmi2Status fmi2Set##Name(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const Type value[]) { \
        return (fmi2Status)instance_no_variables(c, "fmi2Set" #Name, SET_MODES, vr, nvr, value);              \
    }
NO_VARIABLES_OF_TYPE(Boolean, fmi2Boolean)
NO_VARIABLES_OF_TYPE(String, fmi2String)

DEFINE_FMU_STATE_CALLS(fmi2Status, fmi2Component, fmi2FMUstate, fmi2Byte, fmi2GetFMUstate, fmi2SetFMUstate,
                       fmi2FreeFMUstate, fmi2SerializedFMUstateSize, fmi2SerializeFMUstate, fmi2DeSerializeFMUstate)

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    return (fmi2Status)instance_partials(c, "fmi2GetDirectionalDerivative", 0, vUnknown_ref, nUnknown, vKnown_ref,
                                         nKnown, dvKnown, dvUnknown);
}
