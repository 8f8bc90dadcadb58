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

/* Groups of modes the table below uses. */
#define STATE_READ_MODES (MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME | MODE_TERMINATED | MODE_ERROR)
#define ANY_MODE (MODE_INSTANTIATED | MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME | MODE_STEP_COMPLETE | \
                  MODE_TERMINATED | MODE_ERROR)
#define ANY_LIVE_MODE (ANY_MODE & ~MODE_ERROR)
#define NEVER 0u

/* The interfaces that have a call: bits 1 << InterfaceType. */
#define ME (1u << INTERFACE_MODEL_EXCHANGE)
#define CS (1u << INTERFACE_CO_SIMULATION)
#define ME_CS (ME | CS)

typedef struct {
    unsigned modes;      /* the modes (Mode bits) in which the call is allowed */
    unsigned interfaces; /* ME, CS or both: an instance of another interface refuses the call */
} CallRule;

/* Which call is allowed in which state: the state machines of FMI 2.0 (sections 3.2.3 and 4.2.4)
 * and FMI 3.0 (3.2 and 4.2), the two versions' states being the same modes (model.h; 3.0's Step
 * Mode is 2.0's StepComplete). The FMI functions of each row, 2.0 then 3.0 (the split FMUs'
 * layers in split/; a function of a feature the FMU lacks is refused as not provided). */
static const CallRule CALL_RULES[CALL_COUNT] = {
    /* fmi2SetDebugLogging, fmi3SetDebugLogging */
    [CALL_SET_DEBUG_LOGGING] = {ANY_MODE, ME_CS},
    /* fmi2SetupExperiment (3.0 folds it into fmi3EnterInitializationMode) */
    [CALL_SETUP_EXPERIMENT] = {MODE_INSTANTIATED, ME_CS},
    /* fmi2EnterInitializationMode, fmi3EnterInitializationMode */
    [CALL_ENTER_INITIALIZATION] = {MODE_INSTANTIATED, ME_CS},
    /* fmi2ExitInitializationMode, fmi3ExitInitializationMode */
    [CALL_EXIT_INITIALIZATION] = {MODE_INITIALIZATION, ME_CS},
    /* fmi2Terminate, fmi3Terminate */
    [CALL_TERMINATE] = {MODE_EVENT | MODE_CONTINUOUS_TIME | MODE_STEP_COMPLETE, ME_CS},
    /* fmi2Reset, fmi3Reset */
    [CALL_RESET] = {ANY_MODE, ME_CS},
    /* fmi2GetReal, Integer, Boolean, String; fmi3GetFloat64, Int32, Int64 and every other type's Get */
    [CALL_GET_VARIABLES] = {ANY_MODE & ~MODE_INSTANTIATED, ME_CS},
    /* fmi2SetReal, ...; fmi3SetFloat64, ...: parameters and start values before initialization too */
    [CALL_SET_VARIABLES] = {MODE_INSTANTIATED | MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME |
                            MODE_STEP_COMPLETE, ME_CS},
    /* fmi2GetFMUstate, fmi3GetFMUState */
    [CALL_GET_FMU_STATE] = {ANY_LIVE_MODE, ME_CS},
    /* fmi2SetFMUstate, fmi3SetFMUState (and the three below: in the Error state too) */
    [CALL_SET_FMU_STATE] = {ANY_MODE, ME_CS},
    /* fmi2FreeFMUstate, fmi3FreeFMUState */
    [CALL_FREE_FMU_STATE] = {ANY_MODE, ME_CS},
    /* fmi2SerializedFMUstateSize, fmi3SerializedFMUStateSize */
    [CALL_SERIALIZED_FMU_STATE_SIZE] = {ANY_MODE, ME_CS},
    /* fmi2SerializeFMUstate, fmi3SerializeFMUState */
    [CALL_SERIALIZE_FMU_STATE] = {ANY_MODE, ME_CS},
    /* fmi2DeSerializeFMUstate, fmi3DeserializeFMUState */
    [CALL_DESERIALIZE_FMU_STATE] = {ANY_MODE, ME_CS},
    /* fmi2GetDirectionalDerivative; fmi3GetDirectionalDerivative, fmi3GetAdjointDerivative */
    [CALL_PARTIAL_DERIVATIVES] = {MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME | MODE_STEP_COMPLETE |
                                  MODE_TERMINATED, ME_CS},
    /* what the FMU does not have, refused with its reason in any mode: fmi3/absent.c's clocks,
     * Configuration Mode, ...; the split FMUs' FMU states, partial derivatives, fmi2CancelStep
     * and fmi3EnterStepMode */
    [CALL_NOT_PROVIDED] = {ANY_MODE, ME_CS},

    /* Model Exchange. fmi2EnterEventMode, fmi3EnterEventMode */
    [CALL_ENTER_EVENT_MODE] = {MODE_EVENT | MODE_CONTINUOUS_TIME, ME},
    /* fmi2EnterContinuousTimeMode, fmi3EnterContinuousTimeMode */
    [CALL_ENTER_CONTINUOUS_TIME_MODE] = {MODE_EVENT, ME},
    /* fmi2NewDiscreteStates, fmi3UpdateDiscreteStates */
    [CALL_UPDATE_DISCRETE_STATES] = {MODE_EVENT, ME},
    /* fmi2CompletedIntegratorStep, fmi3CompletedIntegratorStep */
    [CALL_COMPLETED_INTEGRATOR_STEP] = {MODE_CONTINUOUS_TIME, ME},
    /* fmi2SetTime, fmi3SetTime */
    [CALL_SET_TIME] = {MODE_EVENT | MODE_CONTINUOUS_TIME, ME},
    /* fmi2SetContinuousStates, fmi3SetContinuousStates */
    [CALL_SET_CONTINUOUS_STATES] = {MODE_CONTINUOUS_TIME, ME},
    /* fmi2GetDerivatives, fmi3GetContinuousStateDerivatives */
    [CALL_GET_DERIVATIVES] = {STATE_READ_MODES, ME},
    /* fmi2GetEventIndicators, fmi3GetEventIndicators */
    [CALL_GET_EVENT_INDICATORS] = {STATE_READ_MODES, ME},
    /* fmi2GetContinuousStates, fmi3GetContinuousStates */
    [CALL_GET_CONTINUOUS_STATES] = {STATE_READ_MODES, ME},
    /* fmi2GetNominalsOfContinuousStates, fmi3GetNominalsOfContinuousStates */
    [CALL_GET_NOMINALS] = {MODE_INSTANTIATED | STATE_READ_MODES, ME},
    /* fmi3GetNumberOfContinuousStates, fmi3GetNumberOfEventIndicators */
    [CALL_GET_NUMBER_OF] = {ANY_MODE, ME},

    /* Co-Simulation. fmi2DoStep, fmi3DoStep */
    [CALL_DO_STEP] = {MODE_STEP_COMPLETE, CS},
    /* fmi2SetRealInputDerivatives (3.0 has none) */
    [CALL_SET_INPUT_DERIVATIVES] = {MODE_INITIALIZATION | MODE_STEP_COMPLETE, CS},
    /* fmi2GetRealOutputDerivatives, fmi3GetOutputDerivatives */
    [CALL_GET_OUTPUT_DERIVATIVES] = {MODE_STEP_COMPLETE, CS},
    /* fmi2CancelStep (3.0 has none) */
    [CALL_CANCEL_STEP] = {MODE_STEP_COMPLETE, CS},
    /* fmi2GetStatus, GetRealStatus, GetIntegerStatus, GetBooleanStatus, GetStringStatus (3.0 has none) */
    [CALL_GET_STATUS] = {MODE_STEP_COMPLETE | MODE_TERMINATED | MODE_ERROR, CS},
    /* fmi3EnterStepMode: never, as the FMU has no Event Mode in Co-Simulation to leave */
    [CALL_ENTER_STEP_MODE] = {NEVER, CS},
};

int instance_call_allowed(Instance *inst, const char *function, FmiCall call) {
    const CallRule *rule = &CALL_RULES[call];
    if (inst == NULL) {
        return 0;
    }
    if ((rule->interfaces & (1u << inst->type)) == 0) {
        instance_fail(inst, function, "is a %s function; this instance was instantiated for %s",
                      rule->interfaces == ME ? "Model Exchange" : "Co-Simulation",
                      inst->type == INTERFACE_MODEL_EXCHANGE ? "Model Exchange" : "Co-Simulation");
        return 0;
    }
    if (((unsigned)inst->data.mode & rule->modes) == 0) {
        instance_fail(inst, function, "not allowed in state %s", mode_name(inst->data.mode, inst->fmi_version));
        return 0;
    }
    if (inst->log_enabled[LOG_CALLS]) {   /* the variadic call only when tracing: every FMI call passes here */
        instance_log(inst, STATUS_OK, LOG_CALLS, "%s", function);
    }
    return 1;
}

Status instance_set_debug_logging(Instance *inst, const char *function, int logging_on, size_t n,
                                  const char *const categories[]) {
    size_t i;
    int category;
    if (!instance_call_allowed(inst, function, CALL_SET_DEBUG_LOGGING)) {
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
