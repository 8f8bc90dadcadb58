/* fmi2_common.c: the FMI 2.0 functions shared by Model Exchange and Co-Simulation
 * (FMI 2.0 section 2.1): instantiation, setup, initialization, variables, logging. */
#include <math.h>
#include <string.h>

#include "fmi2_instance.h"
#include "pendulum_vrs.h"

#define ANY_MODE (MODE_INSTANTIATED | MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME | \
                  MODE_STEP_COMPLETE | MODE_TERMINATED | MODE_ERROR)
/* fmi2GetXXX: allowed everywhere but Instantiated (state-machine tables of 3.2.3 and 4.2.4). */
#define GET_MODES (ANY_MODE & ~MODE_INSTANTIATED)
/* fmi2SetXXX: parameters and start values before initialization ends; after that only
 * tunable parameters and inputs, which this model has none of (checked per variable). */
#define SET_MODES (MODE_INSTANTIATED | MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME | \
                   MODE_STEP_COMPLETE)

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

const char *fmi2GetVersion(void) { return fmi2Version; }

static void free_with(const fmi2CallbackFunctions *callbacks, void *memory) {
    if (memory != NULL) {
        callbacks->freeMemory(memory);
    }
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    Instance *inst;
    size_t name_length;
    (void)fmuResourceLocation; /* the model needs no resources */
    (void)visible;
    /* 2.1.5: allocateMemory and freeMemory are required; without a logger no error could be
     * reported, so it is required as well. */
    if (functions == NULL || functions->allocateMemory == NULL || functions->freeMemory == NULL ||
        functions->logger == NULL) {
        return NULL;
    }
    if (instanceName == NULL || instanceName[0] == '\0') {
        functions->logger(functions->componentEnvironment, "Pendulum", fmi2Error, "logStatusError",
                          "fmi2Instantiate: instanceName must be a non-empty string");
        return NULL;
    }
    if (fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation) {
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error, "logStatusError",
                          "fmi2Instantiate: fmuType must be fmi2ModelExchange or fmi2CoSimulation");
        return NULL;
    }
    if (fmuGUID == NULL || strcmp(fmuGUID, PENDULUM_GUID) != 0) {
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error, "logStatusError",
                          "fmi2Instantiate: GUID %s does not match this FMU's %s",
                          fmuGUID == NULL ? "(null)" : fmuGUID, PENDULUM_GUID);
        return NULL;
    }
    inst = functions->allocateMemory(1, sizeof *inst);
    name_length = strlen(instanceName);
    if (inst == NULL || (inst->name = functions->allocateMemory(name_length + 1, 1)) == NULL) {
        free_with(functions, inst);
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error, "logStatusError",
                          "fmi2Instantiate: out of memory");
        return NULL;
    }
    memcpy(inst->name, instanceName, name_length + 1);
    inst->type = fmuType;
    inst->callbacks = *functions;
    /* Errors and warnings are always reported; call tracing only with loggingOn. */
    inst->log_enabled[LOG_STATUS_ERROR] = 1;
    inst->log_enabled[LOG_STATUS_WARNING] = 1;
    inst->log_enabled[LOG_CALLS] = loggingOn ? 1 : 0;
    model_reset(&inst->data, fmuType);
    return inst;
}

void fmi2FreeInstance(fmi2Component c) {
    Instance *inst = c;
    fmi2CallbackFunctions callbacks;
    if (inst == NULL) {
        return;
    }
    callbacks = inst->callbacks;
    free_with(&callbacks, inst->name);
    free_with(&callbacks, inst);
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    Instance *inst = c;
    size_t i;
    int category;
    if (!instance_allowed(inst, "fmi2SetDebugLogging", ANY_MODE)) {
        return fmi2Error;
    }
    if (nCategories > 0 && categories == NULL) {
        return instance_fail(inst, "fmi2SetDebugLogging", "categories is NULL but nCategories is %zu", nCategories);
    }
    /* 2.1.5: with nCategories = 0, loggingOn applies to all categories. */
    if (nCategories == 0) {
        for (category = 0; category < LOG_CATEGORY_COUNT; category++) {
            inst->log_enabled[category] = loggingOn ? 1 : 0;
        }
    }
    for (i = 0; i < nCategories; i++) {
        category = log_category_from_name(categories[i]);
        if (category < 0) {
            return instance_fail(inst, "fmi2SetDebugLogging", "unknown log category \"%s\"",
                                 categories[i] == NULL ? "(null)" : categories[i]);
        }
        inst->log_enabled[category] = loggingOn ? 1 : 0;
    }
    return fmi2OK;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2SetupExperiment", MODE_INSTANTIATED)) {
        return fmi2Error;
    }
    if (toleranceDefined && !(isfinite(tolerance) && tolerance > 0.0 && tolerance < 1.0)) {
        return instance_fail(inst, "fmi2SetupExperiment", "tolerance %g must be in (0, 1)", tolerance);
    }
    if (!isfinite(startTime)) {
        return instance_fail(inst, "fmi2SetupExperiment", "startTime must be finite");
    }
    if (stopTimeDefined && !(stopTime >= startTime)) {
        return instance_fail(inst, "fmi2SetupExperiment", "stopTime %g is before startTime %g", stopTime, startTime);
    }
    inst->data.tolerance = toleranceDefined ? tolerance : DEFAULT_TOLERANCE;
    inst->data.start_time = startTime;
    inst->data.time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2EnterInitializationMode", MODE_INSTANTIATED)) {
        return fmi2Error;
    }
    inst->data.mode = MODE_INITIALIZATION;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    Instance *inst = c;
    const char *problem;
    if (!instance_allowed(inst, "fmi2ExitInitializationMode", MODE_INITIALIZATION)) {
        return fmi2Error;
    }
    problem = model_initialize(&inst->data, inst->type);
    if (problem != NULL) {
        return instance_fail(inst, "fmi2ExitInitializationMode", "%s", problem);
    }
    inst->data.mode = inst->type == fmi2ModelExchange ? MODE_EVENT : MODE_STEP_COMPLETE;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2Terminate", MODE_EVENT | MODE_CONTINUOUS_TIME | MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    inst->data.mode = MODE_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2Reset", ANY_MODE)) {
        return fmi2Error;
    }
    model_reset(&inst->data, inst->type);
    return fmi2OK;
}

/* Checks the arguments every fmi2Get/SetXXX shares: the state, and the arrays. */
static int variables_allowed(Instance *inst, const char *function, unsigned modes,
                             const fmi2ValueReference vr[], size_t nvr, const void *values) {
    if (!instance_allowed(inst, function, modes)) {
        return 0;
    }
    if (nvr > 0 && (vr == NULL || values == NULL)) {
        instance_fail(inst, function, "vr or value is NULL with nvr = %zu", nvr);
        return 0;
    }
    return 1;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    Instance *inst = c;
    size_t i;
    if (!variables_allowed(inst, "fmi2GetReal", GET_MODES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        const char *problem = model_get_real(&inst->data, vr[i], &value[i]);
        if (problem != NULL) {
            return instance_fail(inst, "fmi2GetReal", "%s (value reference %u): %s",
                                 variable_name(vr[i]), vr[i], problem);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    Instance *inst = c;
    size_t i;
    if (!variables_allowed(inst, "fmi2SetReal", SET_MODES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        const char *problem = model_set_real(&inst->data, vr[i], value[i]);
        if (problem != NULL) {
            return instance_fail(inst, "fmi2SetReal", "%s (value reference %u) = %g: %s",
                                 variable_name(vr[i]), vr[i], value[i], problem);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    Instance *inst = c;
    size_t i;
    if (!variables_allowed(inst, "fmi2GetInteger", GET_MODES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        const char *problem = model_get_integer(&inst->data, vr[i], &value[i]);
        if (problem != NULL) {
            return instance_fail(inst, "fmi2GetInteger", "%s (value reference %u): %s",
                                 variable_name(vr[i]), vr[i], problem);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    Instance *inst = c;
    size_t i;
    if (!variables_allowed(inst, "fmi2SetInteger", SET_MODES, vr, nvr, value)) {
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) {
        const char *problem = model_set_integer(&inst->data, vr[i], value[i]);
        if (problem != NULL) {
            return instance_fail(inst, "fmi2SetInteger", "%s (value reference %u) = %d: %s",
                                 variable_name(vr[i]), vr[i], value[i], problem);
        }
    }
    return fmi2OK;
}

/* The model has no Boolean or String variables: any value reference is unknown. */
static fmi2Status no_variables_of_type(fmi2Component c, const char *function, unsigned modes,
                                       const fmi2ValueReference vr[], size_t nvr, const void *value) {
    Instance *inst = c;
    if (!variables_allowed(inst, function, modes, vr, nvr, value)) {
        return fmi2Error;
    }
    if (nvr > 0) {
        return instance_fail(inst, function, "unknown value reference %u: the model has no variable of this type", vr[0]);
    }
    return fmi2OK;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    return no_variables_of_type(c, "fmi2GetBoolean", GET_MODES, vr, nvr, value);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    return no_variables_of_type(c, "fmi2SetBoolean", SET_MODES, vr, nvr, value);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    return no_variables_of_type(c, "fmi2GetString", GET_MODES, vr, nvr, value);
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    return no_variables_of_type(c, "fmi2SetString", SET_MODES, vr, nvr, value);
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    Instance *inst = c;
    (void)vUnknown_ref, (void)nUnknown, (void)vKnown_ref, (void)nKnown, (void)dvKnown, (void)dvUnknown;
    if (!instance_allowed(inst, "fmi2GetDirectionalDerivative", ANY_MODE)) {
        return fmi2Error;
    }
    return instance_fail(inst, "fmi2GetDirectionalDerivative",
                         "not provided (providesDirectionalDerivative is false)");
}
