/* instance.c: creation, logging and the calling-sequence check of one instance, for both FMI
 * versions. */
#include "instance.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "pendulum_vrs.h"

static const char *const LOG_CATEGORY_NAMES[LOG_CATEGORY_COUNT] = {
    "logStatusError", "logStatusWarning", "logCalls"};

const char *instance_refusal(const char *name, const char *token) {
    if (name == NULL || name[0] == '\0') {
        return "instanceName must be a non-empty string";
    }
    if (token == NULL || strcmp(token, PENDULUM_GUID) != 0) {
        return "the GUID / instantiation token does not match this FMU's " PENDULUM_GUID;
    }
    return NULL;
}

int instance_setup(Instance *inst, const char *name, InterfaceType type, int fmi_version, int logging_on) {
    size_t length = strlen(name);
    inst->name = inst->host.allocate(inst, length + 1);
    if (inst->name == NULL) {
        return -1;
    }
    memcpy(inst->name, name, length + 1);
    inst->type = type;
    inst->fmi_version = fmi_version;
    /* Errors and warnings are always reported; call tracing only with loggingOn. */
    inst->log_enabled[LOG_STATUS_ERROR] = 1;
    inst->log_enabled[LOG_STATUS_WARNING] = 1;
    inst->log_enabled[LOG_CALLS] = logging_on ? 1 : 0;
    model_reset(&inst->data, type);
    return 0;
}

void instance_log(const Instance *inst, Status status, LogCategory category, const char *format, ...) {
    char message[1024];
    va_list args;
    if (!inst->log_enabled[category] || inst->host.log == NULL) {
        return;
    }
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    inst->host.log(inst, status, LOG_CATEGORY_NAMES[category], message);
}

Status instance_fail(Instance *inst, const char *function, const char *format, ...) {
    char reason[400];
    va_list args;
    va_start(args, format);
    vsnprintf(reason, sizeof reason, format, args);
    va_end(args);
    instance_log(inst, STATUS_ERROR, LOG_STATUS_ERROR, "%s: %s", function, reason);
    inst->data.mode = MODE_ERROR;
    return STATUS_ERROR;
}

int instance_allowed(Instance *inst, const char *function, unsigned allowed_modes) {
    if (inst == NULL) {
        return 0;
    }
    if (((unsigned)inst->data.mode & allowed_modes) == 0) {
        instance_fail(inst, function, "not allowed in state %s", mode_name(inst->data.mode, inst->fmi_version));
        return 0;
    }
    if (inst->log_enabled[LOG_CALLS]) {   /* the variadic call only when tracing: every FMI call passes here */
        instance_log(inst, STATUS_OK, LOG_CALLS, "%s", function);
    }
    return 1;
}

int instance_allowed_for(Instance *inst, const char *function, InterfaceType type, unsigned allowed_modes) {
    if (inst != NULL && inst->type != type) {
        instance_fail(inst, function, "is a %s function; this instance was instantiated for %s",
                      type == INTERFACE_MODEL_EXCHANGE ? "Model Exchange" : "Co-Simulation",
                      inst->type == INTERFACE_MODEL_EXCHANGE ? "Model Exchange" : "Co-Simulation");
        return 0;
    }
    return instance_allowed(inst, function, allowed_modes);
}

Status instance_set_debug_logging(Instance *inst, const char *function, int logging_on, size_t n,
                                  const char *const categories[]) {
    size_t i;
    int category;
    if (!instance_allowed(inst, function, ANY_MODE)) {
        return STATUS_ERROR;
    }
    if (n > 0 && categories == NULL) {
        return instance_fail(inst, function, "categories is NULL but nCategories is %zu", n);
    }
    /* FMI 2.0 2.1.5, FMI 3.0 2.3.1: with nCategories = 0, loggingOn applies to all categories. */
    if (n == 0) {
        for (category = 0; category < LOG_CATEGORY_COUNT; category++) {
            inst->log_enabled[category] = logging_on ? 1 : 0;
        }
    }
    for (i = 0; i < n; i++) {
        for (category = 0; category < LOG_CATEGORY_COUNT; category++) {
            if (categories[i] != NULL && strcmp(categories[i], LOG_CATEGORY_NAMES[category]) == 0) {
                break;
            }
        }
        if (category == LOG_CATEGORY_COUNT) {
            return instance_fail(inst, function, "unknown log category \"%s\"",
                                 categories[i] == NULL ? "(null)" : categories[i]);
        }
        inst->log_enabled[category] = logging_on ? 1 : 0;
    }
    return STATUS_OK;
}
