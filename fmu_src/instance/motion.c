/* instance/motion.c: how an instance moves in time, for both FMI versions: the Model
 * Exchange calls (two continuous states theta, omega; no event indicators, no time events)
 * and the Co-Simulation step. The step integrates with the solver chosen by the parameter
 * `solver` at the experiment's tolerance; the solver keeps its own steps, so the
 * communication grid does not change the result. */
#include <math.h>

#include "instance.h"

Status instance_enter_event_mode(Instance *inst, const char *function) {
    if (!instance_call_allowed(inst, function, CALL_ENTER_EVENT_MODE)) {
        return STATUS_ERROR;
    }
    inst->data.mode = MODE_EVENT;
    return STATUS_OK;
}

Status instance_enter_continuous_time_mode(Instance *inst, const char *function) {
    if (!instance_call_allowed(inst, function, CALL_ENTER_CONTINUOUS_TIME_MODE)) {
        return STATUS_ERROR;
    }
    inst->data.mode = MODE_CONTINUOUS_TIME;
    return STATUS_OK;
}

Status instance_new_discrete_states(Instance *inst, const char *function, int any_pointer_null) {
    if (!instance_call_allowed(inst, function, CALL_UPDATE_DISCRETE_STATES)) {
        return STATUS_ERROR;
    }
    if (any_pointer_null) {
        return instance_fail(inst, function, "an output argument is NULL");
    }
    return STATUS_OK; /* no discrete states and no events: the event iteration ends at once */
}

Status instance_completed_integrator_step(Instance *inst, const char *function, int *enter_event_mode,
                                          int *terminate_simulation) {
    if (!instance_call_allowed(inst, function, CALL_COMPLETED_INTEGRATOR_STEP)) {
        return STATUS_ERROR;
    }
    if (enter_event_mode == NULL || terminate_simulation == NULL) {
        return instance_fail(inst, function, "enterEventMode or terminateSimulation is NULL");
    }
    *enter_event_mode = 0;
    *terminate_simulation = 0;
    return STATUS_OK;
}

Status instance_set_time(Instance *inst, const char *function, double time) {
    if (!instance_call_allowed(inst, function, CALL_SET_TIME)) {
        return STATUS_ERROR;
    }
    if (!isfinite(time)) {
        return instance_fail(inst, function, "time must be finite");
    }
    inst->data.time = time;
    model_exact_forget(&inst->exact_now);
    return STATUS_OK;
}

/* Shared checks of the state-vector functions: mode, array and its length. */
static int states_allowed(Instance *inst, const char *function, FmiCall call, const void *array, size_t n,
                          size_t expected) {
    if (!instance_call_allowed(inst, function, call)) {
        return 0;
    }
    if (n != expected) {
        instance_fail(inst, function, "the array length is %zu, but the model has %zu", n, expected);
        return 0;
    }
    if (n > 0 && array == NULL) {
        instance_fail(inst, function, "the array is NULL");
        return 0;
    }
    return 1;
}

Status instance_set_states(Instance *inst, const char *function, const double x[], size_t nx) {
    if (!states_allowed(inst, function, CALL_SET_CONTINUOUS_STATES, x, nx, N_STATES)) {
        return STATUS_ERROR;
    }
    if (!isfinite(x[0]) || !isfinite(x[1])) {
        return instance_fail(inst, function, "states (%g, %g) must be finite", x[0], x[1]);
    }
    inst->data.theta = x[0];
    inst->data.omega = x[1];
    model_exact_forget(&inst->exact_now); /* the exact solution is the initial state's: kept
                                              for tidiness, the states do not enter it */
    return STATUS_OK;
}

Status instance_get_state_derivatives(Instance *inst, const char *function, double derivatives[], size_t nx) {
    const char *problem;
    if (!states_allowed(inst, function, CALL_GET_DERIVATIVES, derivatives, nx, N_STATES)) {
        return STATUS_ERROR;
    }
    problem = model_derivatives(&inst->data, &derivatives[0], &derivatives[1]);
    return problem == NULL ? STATUS_OK : instance_fail(inst, function, "%s", problem);
}

Status instance_get_event_indicators(Instance *inst, const char *function, double indicators[], size_t ni) {
    return states_allowed(inst, function, CALL_GET_EVENT_INDICATORS, indicators, ni, 0) ? STATUS_OK : STATUS_ERROR;
}

Status instance_get_states(Instance *inst, const char *function, double x[], size_t nx) {
    if (!states_allowed(inst, function, CALL_GET_CONTINUOUS_STATES, x, nx, N_STATES)) {
        return STATUS_ERROR;
    }
    x[0] = inst->data.theta;
    x[1] = inst->data.omega;
    return STATUS_OK;
}

Status instance_get_nominals(Instance *inst, const char *function, double nominals[], size_t nx) {
    if (!states_allowed(inst, function, CALL_GET_NOMINALS, nominals, nx, N_STATES)) {
        return STATUS_ERROR;
    }
    nominals[0] = 1.0; /* rad: angles of order 1 */
    nominals[1] = 1.0; /* rad/s */
    return STATUS_OK;
}

Status instance_do_step(Instance *inst, const char *function, double point, double step) {
    ModelData *data;
    double t_end = 0.0, y[2];
    if (!instance_call_allowed(inst, function, CALL_DO_STEP)) {
        return STATUS_ERROR;
    }
    data = &inst->data;
    switch (integrator_step_end(data->time, point, step, &t_end)) {
    case STEP_END_OK: break;
    case STEP_END_BAD_SIZE:
        return instance_fail(inst, function, "communicationStepSize %g must be a finite number greater than 0", step);
    case STEP_END_BAD_POINT:
        /* FMI 2.0 4.2.2, FMI 3.0 4.2.1: currentCommunicationPoint is the time reached by the
         * last step; a master's rounding of it by a few ulps is tolerated, nothing more */
        return instance_fail(inst, function, "currentCommunicationPoint %.17g is not the current time %.17g "
                             "(to %g ulps)", point, data->time, INTEGRATOR_POINT_ULPS);
    case STEP_END_NOT_FINITE:
        return instance_fail(inst, function, "the step would end at a time that is not finite");
    default:
        return instance_fail(inst, function, "the step would end at %.17g, before the current time %.17g: "
                             "time never goes backwards", point + step, data->time);
    }
    switch (integrator_advance(&data->integrator, t_end, y)) {
    case 0: break;
    case -2:
        return instance_fail(inst, function,
                             "reaching t = %.17g from t = %.17g takes more than %ld internal steps; "
                             "use shorter communication steps", t_end, data->time, INTEGRATOR_MAX_STEPS_PER_ADVANCE);
    default:
        return instance_fail(inst, function,
                             "the solver failed between t = %.17g and t = %.17g (step size underflow or non-finite state)",
                             data->time, t_end);
    }
    data->theta = y[0];
    data->omega = y[1];
    data->time = t_end;
    model_exact_forget(&inst->exact_now); /* the certificate evaluates it at t_end, once */
    return instance_check_step(inst); /* the certificate and the hard case (instance/certificate.c) */
}
