/* host2.h: what every FMI 2.0 layer of the project shares, Pendulum's (fmi2/common.c) and the
 * split FMUs' (split/layer2.c): the host's callbacks behind InstanceHost, fmi2Instantiate's
 * checks and allocation, and the FMI 2.0 functions that only pass a call on to the model's
 * core. A layer's instance starts with an Instance and holds a copy of the host's callbacks,
 * which InstanceHost.context points at. Included by one source of each FMU. */
#ifndef PENDULUM_FMI2_HOST2_H
#define PENDULUM_FMI2_HOST2_H

#include <stddef.h>

#include "fmi2_api.h"
#include "instance.h"

static inline const fmi2CallbackFunctions *host2_callbacks(const Instance *inst) {
    return (const fmi2CallbackFunctions *)inst->host.context;
}

static inline void host2_log(const Instance *inst, Status status, const char *category, const char *message) {
    const fmi2CallbackFunctions *callbacks = host2_callbacks(inst);
    /* The message goes through "%s": a '%' in it must not be read as a format. */
    callbacks->logger(callbacks->componentEnvironment, inst->name, (fmi2Status)status, category, "%s", message);
}

static inline void *host2_allocate(const Instance *inst, size_t size) {
    return host2_callbacks(inst)->allocateMemory(1, size);
}

static inline void host2_release(const Instance *inst, void *memory) {
    host2_callbacks(inst)->freeMemory(memory);
}

/* fmi2Instantiate's work. 2.1.5: allocateMemory and freeMemory are required; without a logger
 * no error could be reported, so it is required as well. A refusal (NULL: none) is logged
 * under the instance's name, or model_name where it has none. Then `size` zeroed bytes from
 * the host, an Instance at their start, the host's callbacks copied to `callbacks_at` bytes in
 * and wired into the Instance's host, and the model's own set-up (0, or -1 when out of
 * memory). NULL if refused or out of memory (logged). */
static inline fmi2Component host2_instantiate(const char *refusal, const char *model_name, fmi2String instanceName,
                                              fmi2Type fmuType, const fmi2CallbackFunctions *functions,
                                              fmi2Boolean loggingOn, size_t size, size_t callbacks_at,
                                              int (*setup)(Instance *inst, const char *name, fmi2Type fmuType,
                                                           int logging_on)) {
    Instance *inst;
    fmi2CallbackFunctions *callbacks;
    if (functions == NULL || functions->allocateMemory == NULL || functions->freeMemory == NULL ||
        functions->logger == NULL) {
        return NULL;
    }
    if (refusal != NULL) {
        functions->logger(functions->componentEnvironment, instanceName != NULL && instanceName[0] != '\0'
                          ? instanceName : model_name, fmi2Error, "logStatusError", "fmi2Instantiate: %s", refusal);
        return NULL;
    }
    inst = functions->allocateMemory(1, size);
    if (inst != NULL) {
        callbacks = (fmi2CallbackFunctions *)((char *)inst + callbacks_at);
        *callbacks = *functions;
        inst->host.log = host2_log;
        inst->host.allocate = host2_allocate;
        inst->host.release = host2_release;
        inst->host.context = callbacks;
    }
    if (inst == NULL || setup(inst, instanceName, fmuType, loggingOn) != 0) {
        if (inst != NULL) {
            functions->freeMemory(inst);
        }
        functions->logger(functions->componentEnvironment, instanceName, fmi2Error, "logStatusError",
                          "fmi2Instantiate: out of memory");
        return NULL;
    }
    return inst;
}

/* fmi2Instantiate of a layer whose instance type InstanceT starts with an Instance and holds
 * the host's callbacks in its member `callbacks`; the layer's refusal (name, GUID, fmuType:
 * NULL, or why not) and setup (as host2_instantiate takes it). */
#define DEFINE_FMI2_INSTANTIATE(InstanceT, model_name, refusal, setup)                                           \
    fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,                 \
                                  fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,        \
                                  fmi2Boolean visible, fmi2Boolean loggingOn) {                                  \
        (void)fmuResourceLocation, (void)visible; /* the models need no resources and show nothing */           \
        return host2_instantiate(refusal(instanceName, fmuGUID, fmuType), model_name, instanceName, fmuType,     \
                                 functions, loggingOn, sizeof(InstanceT), offsetof(InstanceT, callbacks), setup); \
    }

/* fmi2FreeInstance: the core's release, then the instance itself, with the host's freeMemory
 * read before its copy inside the instance is freed. */
static inline void host2_free(Instance *inst) {
    if (inst != NULL) {
        fmi2CallbackFreeMemory release = host2_callbacks(inst)->freeMemory;
        instance_release(inst);
        release(inst);
    }
}

/* The FMI 2.0 functions that only pass a call on: to the shared instance (instance.h), or to
 * the model's own exit_initialization, reset, get_reals and set_reals (Pendulum's are the
 * instance's, the split FMUs' those of split.h). */
#define DEFINE_FMI2_PASSING_CALLS(exit_initialization, reset, get_reals, set_reals)                          \
    const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }                                     \
    const char *fmi2GetVersion(void) { return fmi2Version; }                                                 \
    void fmi2FreeInstance(fmi2Component c) { host2_free(c); }                                                \
    fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,               \
                                   const fmi2String categories[]) {                                          \
        return (fmi2Status)instance_set_debug_logging(c, "fmi2SetDebugLogging", loggingOn, nCategories,      \
                                                      categories);                                           \
    }                                                                                                        \
    fmi2Status fmi2EnterInitializationMode(fmi2Component c) {                                                \
        return (fmi2Status)instance_enter_initialization(c, "fmi2EnterInitializationMode");                  \
    }                                                                                                        \
    fmi2Status fmi2ExitInitializationMode(fmi2Component c) {                                                 \
        return (fmi2Status)exit_initialization(c, "fmi2ExitInitializationMode");                             \
    }                                                                                                        \
    fmi2Status fmi2Terminate(fmi2Component c) { return (fmi2Status)instance_terminate(c, "fmi2Terminate"); } \
    fmi2Status fmi2Reset(fmi2Component c) { return (fmi2Status)reset(c, "fmi2Reset"); }                      \
    fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {   \
        return (fmi2Status)get_reals(c, "fmi2GetReal", vr, nvr, value);                                      \
    }                                                                                                        \
    fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,                       \
                           const fmi2Real value[]) {                                                         \
        return (fmi2Status)set_reals(c, "fmi2SetReal", vr, nvr, value);                                      \
    }

/* Get and Set of a type the model has no variable of: any value reference is unknown. */
#define DEFINE_FMI2_NO_VARIABLES_OF_TYPE(Name, Type)                                                           \
    fmi2Status fmi2Get##Name(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, Type value[]) {       \
        return (fmi2Status)instance_no_variables(c, "fmi2Get" #Name, GET_MODES, vr, nvr, value);              \
    }                                                                                                          \
    fmi2Status fmi2Set##Name(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const Type value[]) { \
        return (fmi2Status)instance_no_variables(c, "fmi2Set" #Name, SET_MODES, vr, nvr, value);              \
    }

#endif
