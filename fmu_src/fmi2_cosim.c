/* fmi2_cosim.c: the Co-Simulation functions (FMI 2.0 section 4.2). fmi2DoStep integrates
 * with the solver chosen by the parameter `solver`, at the tolerance of fmi2SetupExperiment;
 * the solver keeps its own steps, so the communication grid does not change the result. */
#include <math.h>

#include "fmi2_instance.h"

static const char *const SOLVER_NAMES[] = {"?", "dopri5", "rk4", "rkn", "symplectic"};

/* The hard case never passes silently: when the numerical solution has gone qualitatively
 * wrong against the exact one (a libration carried over the top, a rotation reversed), the
 * step returns fmi2Warning and logs it once per run (category logStatusWarning, message
 * starting with "hard case:"), with what happened and what to do. */
static fmi2Status hard_case_check(Instance *inst) {
    ModelData *data = &inst->data;
    const char *miss;
    double theta_exact, omega_exact;
    if (data->hard_case_reported || !pendulum_exact_resolvable(&data->exact, data->time)) {
        return fmi2OK;
    }
    miss = pendulum_exact_qualitative_miss(&data->exact, data->theta, data->omega);
    if (miss == NULL) {
        return fmi2OK;
    }
    pendulum_exact_eval(&data->exact, data->time, &theta_exact, &omega_exact);
    data->hard_case_reported = 1;
    instance_log(inst, fmi2Warning, LOG_STATUS_WARNING,
                 "hard case: by t = %.9g the numerical solution (solver %s, tolerance %g) %s: theta = %.9g rad, "
                 "omega = %.9g rad/s, the exact solution theta_exact = %.9g rad, omega_exact = %.9g rad/s. "
                 "Use a tighter tolerance or another solver, "
                 "or read theta_exact.",
                 data->time, SOLVER_NAMES[data->solver], data->tolerance, miss, data->theta, data->omega,
                 theta_exact, omega_exact);
    return fmi2Warning;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    Instance *inst = c;
    ModelData *data;
    double t_end = 0.0, y[2];
    (void)noSetFMUStatePriorToCurrentPoint; /* the solver state is plain data: nothing to drop */
    if (!instance_allowed_for(inst, "fmi2DoStep", fmi2CoSimulation, MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    data = &inst->data;
    switch (integrator_step_end(data->time, currentCommunicationPoint, communicationStepSize, &t_end)) {
    case STEP_END_OK: break;
    case STEP_END_BAD_SIZE:
        return instance_fail(inst, "fmi2DoStep", "communicationStepSize %g must be a finite number greater than 0",
                             communicationStepSize);
    case STEP_END_BAD_POINT:
        /* 4.2.2: currentCommunicationPoint is the time reached by the last step; a master's
         * rounding of it by a few ulps is tolerated, nothing more */
        return instance_fail(inst, "fmi2DoStep", "currentCommunicationPoint %.17g is not the current time %.17g "
                             "(to %g ulps)", currentCommunicationPoint, data->time, INTEGRATOR_POINT_ULPS);
    case STEP_END_NOT_FINITE:
        return instance_fail(inst, "fmi2DoStep", "the step would end at a time that is not finite");
    default:
        return instance_fail(inst, "fmi2DoStep", "the step would end at %.17g, before the current time %.17g: "
                             "time never goes backwards", currentCommunicationPoint + communicationStepSize,
                             data->time);
    }
    switch (integrator_advance(&data->integrator, t_end, y)) {
    case 0: break;
    case -2:
        return instance_fail(inst, "fmi2DoStep",
                             "reaching t = %.17g from t = %.17g takes more than %ld internal steps; "
                             "use shorter communication steps", t_end, data->time, INTEGRATOR_MAX_STEPS_PER_ADVANCE);
    default:
        return instance_fail(inst, "fmi2DoStep",
                             "the solver failed between t = %.17g and t = %.17g (step size underflow or non-finite state)",
                             data->time, t_end);
    }
    data->theta = y[0];
    data->omega = y[1];
    data->time = t_end;
    return hard_case_check(inst);
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    Instance *inst = c;
    (void)vr, (void)nvr, (void)order, (void)value;
    if (!instance_allowed_for(inst, "fmi2SetRealInputDerivatives", fmi2CoSimulation, MODE_INITIALIZATION | MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    return instance_fail(inst, "fmi2SetRealInputDerivatives", "the model has no inputs");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    Instance *inst = c;
    (void)vr, (void)nvr, (void)order, (void)value;
    if (!instance_allowed_for(inst, "fmi2GetRealOutputDerivatives", fmi2CoSimulation, MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    return instance_fail(inst, "fmi2GetRealOutputDerivatives", "not provided (maxOutputDerivativeOrder is 0)");
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    Instance *inst = c;
    if (!instance_allowed_for(inst, "fmi2CancelStep", fmi2CoSimulation, MODE_STEP_COMPLETE)) {
        return fmi2Error;
    }
    return instance_fail(inst, "fmi2CancelStep", "fmi2DoStep never returns fmi2Pending: nothing to cancel");
}

#define STATUS_MODES (MODE_STEP_COMPLETE | MODE_TERMINATED | MODE_ERROR)

/* 4.2.3: a status that the FMU does not provide is answered with fmi2Discard. */
static fmi2Status status_not_provided(Instance *inst, const char *function, fmi2StatusKind kind) {
    instance_log(inst, fmi2Discard, LOG_STATUS_WARNING, "%s: status kind %d is not provided", function, (int)kind);
    return fmi2Discard;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    Instance *inst = c;
    if (!instance_allowed_for(inst, "fmi2GetStatus", fmi2CoSimulation, STATUS_MODES)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return instance_fail(inst, "fmi2GetStatus", "value is NULL");
    }
    if (s != fmi2DoStepStatus) {
        return status_not_provided(inst, "fmi2GetStatus", s);
    }
    *value = inst->data.mode == MODE_ERROR ? fmi2Error : fmi2OK;
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    Instance *inst = c;
    if (!instance_allowed_for(inst, "fmi2GetRealStatus", fmi2CoSimulation, STATUS_MODES)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return instance_fail(inst, "fmi2GetRealStatus", "value is NULL");
    }
    if (s != fmi2LastSuccessfulTime) {
        return status_not_provided(inst, "fmi2GetRealStatus", s);
    }
    *value = inst->data.time;
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    Instance *inst = c;
    (void)value;
    if (!instance_allowed_for(inst, "fmi2GetIntegerStatus", fmi2CoSimulation, STATUS_MODES)) {
        return fmi2Error;
    }
    return status_not_provided(inst, "fmi2GetIntegerStatus", s);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    Instance *inst = c;
    if (!instance_allowed_for(inst, "fmi2GetBooleanStatus", fmi2CoSimulation, STATUS_MODES)) {
        return fmi2Error;
    }
    if (value == NULL) {
        return instance_fail(inst, "fmi2GetBooleanStatus", "value is NULL");
    }
    if (s != fmi2Terminated) {
        return status_not_provided(inst, "fmi2GetBooleanStatus", s);
    }
    *value = fmi2False; /* the model never asks the master to stop */
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    Instance *inst = c;
    (void)value;
    if (!instance_allowed_for(inst, "fmi2GetStringStatus", fmi2CoSimulation, STATUS_MODES)) {
        return fmi2Error;
    }
    return status_not_provided(inst, "fmi2GetStringStatus", s);
}
