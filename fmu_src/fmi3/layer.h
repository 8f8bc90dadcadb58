/* fmi3/layer.h: the FMI 3.0 instance, the shared one (instance.h) plus the host's logger, the
 * instantiation shared by Model Exchange and Co-Simulation, and what every FMI 3.0 layer of
 * the project shares, Pendulum's (fmi3/) and the split FMUs' (split/layer3.c): the host's
 * logger behind InstanceHost, the instantiation's refusals and allocation, and the work of the
 * FMI 3.0 functions that every layer writes out itself, each defined by its name. */
#ifndef PENDULUM_FMI3_LAYER_H
#define PENDULUM_FMI3_LAYER_H

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include "fmi3_api.h"
#include "instance.h"

/* The host's logger as the layer keeps it; InstanceHost.context points at it. */
typedef struct {
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log_message;
} Fmi3Host;

typedef struct {
    Instance core; /* first: an fmi3Instance is also an Instance */
    Fmi3Host host3;
} Fmi3Instance;

/* Checks the name and the token, allocates and sets up an instance of interface `type`;
 * NULL (with the reason logged when there is a logger) if refused. Defined by the layer:
 * fmi3/common.c for Pendulum, split/layer3.c for the split FMUs. */
fmi3Instance fmi3_instantiate(const char *function, fmi3String instanceName, fmi3String instantiationToken,
                              InterfaceType type, fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                              fmi3LogMessageCallback logMessage);

static inline void fmi3_host_log(const Instance *inst, Status status, const char *category, const char *message) {
    const Fmi3Host *host3 = (const Fmi3Host *)inst->host.context;
    if (host3->log_message != NULL) {
        host3->log_message(host3->environment, (fmi3Status)status, category, message);
    }
}

/* FMI 3.0 hands the FMU no allocator: the C library's. */
static inline void *fmi3_host_allocate(const Instance *inst, size_t size) {
    (void)inst;
    return calloc(1, size);
}

static inline void fmi3_host_release(const Instance *inst, void *memory) {
    (void)inst;
    free(memory);
}

/* Logs "<function>: <reason>" as an error when there is a logger (function NULL: the reason
 * alone); for the calls that have no instance to log through. */
static inline void fmi3_refuse(fmi3InstanceEnvironment environment, fmi3LogMessageCallback logMessage,
                               const char *function, const char *reason) {
    if (logMessage != NULL) {
        char message[256];
        if (function != NULL) {
            snprintf(message, sizeof message, "%s: %s", function, reason);
        }
        logMessage(environment, fmi3Error, "logStatusError", function != NULL ? message : reason);
    }
}

/* The model's own set-up of a zeroed instance (instance_setup, split_setup): 0, or -1 when
 * out of memory. */
typedef int (*Fmi3Setup)(Instance *inst, const char *name, InterfaceType type, int logging_on);

/* fmi3_instantiate's work for a layer whose instance is `size` bytes, an Instance first and
 * an Fmi3Host at `host_at` bytes in: a refusal (NULL: none) logged by fmi3_refuse; then the
 * zeroed instance, its host wired, set up by `setup`. NULL if refused or out of memory, which
 * is logged with out_of_memory_function in front (fmi3_refuse). */
static inline Instance *fmi3_new_instance(const char *function, const char *refusal, size_t size, size_t host_at,
                                          Fmi3Setup setup, fmi3String instanceName, InterfaceType type,
                                          fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                                          fmi3LogMessageCallback logMessage, const char *out_of_memory_function) {
    Instance *inst;
    if (refusal != NULL) {
        fmi3_refuse(environment, logMessage, function, refusal);
        return NULL;
    }
    inst = calloc(1, size);
    if (inst != NULL) {
        Fmi3Host *host3 = (Fmi3Host *)((char *)inst + host_at);
        host3->environment = environment;
        host3->log_message = logMessage;
        inst->host.log = fmi3_host_log;
        inst->host.allocate = fmi3_host_allocate;
        inst->host.release = fmi3_host_release;
        inst->host.context = host3;
        if (setup(inst, instanceName, type, loggingOn) != 0) {
            free(inst);
            inst = NULL;
        }
    }
    if (inst == NULL) {
        fmi3_refuse(environment, logMessage, out_of_memory_function, "out of memory");
    }
    return inst;
}

/* Scalar variables only: a Get/Set call has one value per value reference. The mode (and
 * the call's logCalls line) is checked once, by the instance_* call that does the work. */
static inline int fmi3_scalar_counts(fmi3Instance instance, const char *function, size_t nvr, size_t n_values) {
    if (instance != NULL && n_values != nvr) {
        instance_fail(instance, function, "nValues %zu differs from nValueReferences %zu: every variable is a scalar",
                      n_values, nvr);
        return 0;
    }
    return 1;
}

/* fmi3DoStep's output arguments, before the model's step (instance_do_step, split_do_step): 1
 * after refusing the call if one of them is NULL, 0 to go on. No FMU of the project has an event
 * mode or returns early. */
static inline int fmi3_step_outputs_missing(fmi3Instance instance, const fmi3Boolean *eventHandlingNeeded,
                                            const fmi3Boolean *terminateSimulation, const fmi3Boolean *earlyReturn,
                                            const fmi3Float64 *lastSuccessfulTime) {
    if (instance != NULL && (eventHandlingNeeded == NULL || terminateSimulation == NULL || earlyReturn == NULL ||
                             lastSuccessfulTime == NULL)) {
        instance_fail(instance, "fmi3DoStep", "an output argument is NULL");
        return 1;
    }
    return 0;
}

/* ... and after it: set after a step that succeeded (OK or Warning). */
static inline void fmi3_step_outputs(fmi3Instance instance, Status status, fmi3Boolean *eventHandlingNeeded,
                                     fmi3Boolean *terminateSimulation, fmi3Boolean *earlyReturn,
                                     fmi3Float64 *lastSuccessfulTime) {
    if (instance != NULL && (status == STATUS_OK || status == STATUS_WARNING)) {
        *eventHandlingNeeded = fmi3False;
        *terminateSimulation = fmi3False;
        *earlyReturn = fmi3False;
        *lastSuccessfulTime = ((Instance *)instance)->data.time;
    }
}

/* fmi3FreeInstance's work. */
static inline void fmi3_free_instance(fmi3Instance instance) {
    if (instance != NULL) {
        instance_release(instance);
        free(instance);
    }
}

#endif
