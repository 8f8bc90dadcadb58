/* host2.h: what every FMI 2.0 layer of the project shares, Pendulum's (fmi2/common.c) and the
 * split FMUs' (split/layer2.c): the host's callbacks behind InstanceHost, fmi2Instantiate's
 * checks and allocation, and fmi2FreeInstance's work; each layer writes out its FMI functions
 * itself, each defined by its name. A layer's instance starts with an Instance and holds a
 * copy of the host's callbacks, which InstanceHost.context points at. Included by one source
 * of each FMU. */
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

/* fmi2FreeInstance: the core's release, then the instance itself, with the host's freeMemory
 * read before its copy inside the instance is freed. */
static inline void host2_free(Instance *inst) {
    if (inst != NULL) {
        fmi2CallbackFreeMemory release = host2_callbacks(inst)->freeMemory;
        instance_release(inst);
        release(inst);
    }
}

#endif
