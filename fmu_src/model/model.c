/* model.c: the variables of the model, their checks, the equations and FMU-state validation,
 * shared by the FMI 2.0 and FMI 3.0 layers. */
#include "model.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <string.h>

#include "pendulum_vrs.h"
#include "trig.h"

const char *mode_name(Mode mode, int fmi_version) {
    switch (mode) {
    case MODE_INSTANTIATED: return "Instantiated";
    case MODE_INITIALIZATION: return "InitializationMode";
    case MODE_EVENT: return "EventMode";
    case MODE_CONTINUOUS_TIME: return "ContinuousTimeMode";
    case MODE_STEP_COMPLETE: return fmi_version == 3 ? "StepMode" : "StepComplete";
    case MODE_TERMINATED: return "Terminated";
    case MODE_ERROR: return "Error";
    }
    return "unknown state";
}

void model_reset(ModelData *data, InterfaceType type) {
    memset(data, 0, sizeof *data);   /* padding too: states are compared and checksummed bytewise */
    data->mode = MODE_INSTANTIATED;
    data->interface = (int)type;
    data->hard_case_reported = 0;
    data->L = START_L;
    data->g = START_G;
    data->solver = START_SOLVER;
    data->tolerance = DEFAULT_TOLERANCE;
    data->start_time = 0.0;
    data->time = 0.0;
    data->theta = START_THETA;
    data->omega = START_OMEGA;
    pendulum_exact_init_gl(&data->exact, START_THETA, START_OMEGA, START_G, START_L, 0.0);
    integrator_init(&data->integrator, START_SOLVER, START_G / START_L, DEFAULT_TOLERANCE,
                    0.0, START_THETA, START_OMEGA);
}

/* Modes an instance of each interface can be in (FMI 2.0 3.2.3 and 4.2.4). */
#define ME_MODES (MODE_INSTANTIATED | MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME | \
                  MODE_TERMINATED | MODE_ERROR)
#define CS_MODES (MODE_INSTANTIATED | MODE_INITIALIZATION | MODE_STEP_COMPLETE | MODE_TERMINATED | MODE_ERROR)

/* Parameters are checked when set; this re-checks the combination (g / L must stay finite). */
static const char *check_parameters(const ModelData *data) {
    double w0sq = data->g / data->L;
    if (!(data->L > 0.0) || !(data->g > 0.0) || !isfinite(w0sq) || !(w0sq > 0.0)) {
        return "g / L must be a finite number greater than 0";
    }
    return NULL;
}

const char *model_initialize(ModelData *data, InterfaceType type) {
    const char *problem = check_parameters(data);
    if (problem != NULL) {
        return problem;
    }
    if (pendulum_exact_init_gl(&data->exact, data->theta, data->omega, data->g, data->L, data->time) != 0 ||
        isnan(pendulum_exact_period(&data->exact))) {
        return "the exact solution cannot be set up for these start values";
    }
    if (type == INTERFACE_CO_SIMULATION &&
        integrator_init_gl(&data->integrator, (SolverKind)data->solver, data->g, data->L, data->tolerance,
                        data->time, data->theta, data->omega) != 0) {
        return "the solver cannot be set up for these start values";
    }
    return NULL;
}

const char *model_check_state(const ModelData *data, InterfaceType type) {
    ModelData reset;
    const unsigned modes = type == INTERFACE_MODEL_EXCHANGE ? ME_MODES : CS_MODES;
    const unsigned mode = (unsigned)data->mode;
    if (data->interface != (int)type) {
        return data->interface == INTERFACE_MODEL_EXCHANGE || data->interface == INTERFACE_CO_SIMULATION
                   ? "the state is of an instance of the other interface (Model Exchange / Co-Simulation)"
                   : "the interface type is out of range";
    }
    if (mode == 0 || (mode & (mode - 1)) != 0 || (mode & modes) == 0) {
        return "the mode is not one this interface can be in";
    }
    if (data->hard_case_reported != 0 && data->hard_case_reported != 1) {
        return "the hard-case flag is out of range";
    }
    if (!(data->certificate_logged == 0.0 || (data->certificate_logged > 1.0 && data->certificate_logged <= DBL_MAX)) ||
        (data->certificate_logged != 0.0 &&
         (type == INTERFACE_MODEL_EXCHANGE || (data->mode & (MODE_INSTANTIATED | MODE_INITIALIZATION)) != 0))) {
        return "the certificate's last logged departure is out of range (0, or above 1 after a Co-Simulation "
               "initialization)";
    }
    if (!(isfinite(data->L) && data->L > 0.0 && isfinite(data->g) && data->g > 0.0)) {
        return "L or g out of range (finite, greater than 0)";
    }
    if (integrator_solver_name(data->solver) == NULL) {
        return "the solver is not an item of the enumeration Solver";
    }
    if (!(isfinite(data->tolerance) && data->tolerance > 0.0 && data->tolerance < 1.0)) {
        return "the tolerance is out of range (0, 1)";
    }
    if (type == INTERFACE_CO_SIMULATION && !(data->tolerance >= INTEGRATOR_TOLERANCE_FLOOR)) {
        return "the tolerance is below the smallest a Co-Simulation step can be certified at "
               "(INTEGRATOR_TOLERANCE_FLOOR)";
    }
    if (!isfinite(data->start_time) || !isfinite(data->time) || !isfinite(data->theta) || !isfinite(data->omega)) {
        return "a time or a state is not finite";
    }
    model_reset(&reset, type);
    if ((mode & (MODE_INSTANTIATED | MODE_INITIALIZATION)) != 0) {
        /* before initialization the exact solution and the solver are the reset ones */
        if (memcmp(&reset.exact, &data->exact, sizeof reset.exact) != 0 ||
            memcmp(&reset.integrator, &data->integrator, sizeof reset.integrator) != 0) {
            return "the exact solution or the solver is not the one of a state before initialization";
        }
        return NULL;
    }
    if (mode == MODE_ERROR) {
        /* the error state may come from any mode, also half-way through an initialization or
         * a failed step; of its contents only variables are read again (the solver only its
         * counts), so the exact solution must be a consistent one, the reset one or another */
        if (memcmp(&reset.exact, &data->exact, sizeof reset.exact) != 0 && !pendulum_exact_same(&data->exact)) {
            return "the exact solution does not match its own start values";
        }
        return NULL;
    }
    if (check_parameters(data) != NULL) {
        return "g / L is not a finite number greater than 0 after initialization";
    }
    if (!pendulum_exact_same(&data->exact) || !(data->exact.g == data->g) || !(data->exact.L == data->L) ||
        !(data->exact.t0 == data->start_time)) {
        return "the exact solution does not match its start values and parameters";
    }
    if (type == INTERFACE_MODEL_EXCHANGE) {
        if (memcmp(&reset.integrator, &data->integrator, sizeof reset.integrator) != 0) {
            return "a Model Exchange state carries a solver state";
        }
        return NULL;
    }
    {
        Integrator fresh;
        const char *problem;
        if (integrator_init_gl(&fresh, (SolverKind)data->solver, data->g, data->L, data->tolerance, data->start_time,
                            data->exact.theta0, data->exact.omega0) != 0) {
            return "the solver cannot be set up for the state's start values";
        }
        problem = integrator_check(&data->integrator, &fresh);
        if (problem != NULL) {
            return problem;
        }
        if (!(data->time >= data->start_time) || !(data->time <= data->integrator.t) ||
            (data->integrator.h_last > 0.0 && !(data->time >= data->integrator.t_prev))) {
            return "the communication time does not lie in the solver's last step";
        }
    }
    return NULL;
}

const char *model_derivatives(const ModelData *data, double *der_theta, double *der_omega) {
    const char *problem = check_parameters(data);
    if (problem != NULL) {
        return problem;
    }
    *der_theta = data->omega;
    *der_omega = -(data->g / data->L) * sin(data->theta);
    return NULL;
}

/* The exact solution as of now: during initialization it follows the values set so far. */
static const char *current_exact(const ModelData *data, PendulumExact *exact) {
    const char *problem;
    if (data->mode != MODE_INITIALIZATION && data->mode != MODE_INSTANTIATED) {
        *exact = data->exact;
        return NULL;
    }
    problem = check_parameters(data);
    if (problem != NULL) {
        return problem;
    }
    if (pendulum_exact_init_gl(exact, data->theta, data->omega, data->g, data->L, data->time) != 0) {
        return "the exact solution cannot be set up for these start values";
    }
    return NULL;
}

void model_exact_forget(ExactCache *cache) {
    cache->valid = 0;
}

#define UNRESOLVED "the exact solution is not representable in double precision at this time: more than " \
                   "2^60 quarter periods from the start time, the phase is not resolved (rate held to 104 bits)"

const char *model_exact_now(const ModelData *data, ExactCache *cache, double *theta, double *omega) {
    PendulumExact fresh;
    const PendulumExact *exact = &data->exact;
    const int fixed = data->mode != MODE_INITIALIZATION && data->mode != MODE_INSTANTIATED;
    if (fixed && cache->valid && cache->time == data->time) {
        *theta = cache->theta;
        *omega = cache->omega;
        return NULL;
    }
    if (!fixed) {
        const char *problem = current_exact(data, &fresh);
        if (problem != NULL) {
            return problem;
        }
        exact = &fresh;
    }
    if (!pendulum_exact_resolvable(exact, data->time)) {
        return UNRESOLVED;
    }
    pendulum_exact_eval(exact, data->time, theta, omega);
    cache->evaluations++;
    if (fixed) {
        /* before initialization the exact solution follows every value set: nothing is kept */
        cache->valid = 1;
        cache->time = data->time;
        cache->theta = *theta;
        cache->omega = *omega;
    }
    return NULL;
}

const char *model_get_real(const ModelData *data, ExactCache *cache, ValueReference vr, double *value) {
    PendulumExact exact;
    double unused;
    const char *problem = NULL;
    switch (vr) {
    case VR_L: *value = data->L; break;
    case VR_G: *value = data->g; break;
    case VR_THETA: *value = data->theta; break;
    case VR_OMEGA: *value = data->omega; break;
    case VR_DER_THETA: return model_derivatives(data, value, &unused);
    case VR_DER_OMEGA: return model_derivatives(data, &unused, value);
    case VR_X:
    case VR_Y: {   /* trig.h: inline, within 1 ulp of libm */
        double sin_theta, cos_theta;
        trig_sincos(data->theta, &sin_theta, &cos_theta);
        *value = vr == VR_X ? data->L * sin_theta : -data->L * cos_theta;
        break;
    }
    case VR_PERIOD:
        problem = current_exact(data, &exact);
        if (problem != NULL) {
            return problem;
        }
        *value = pendulum_exact_period(&exact); /* +inf on the separatrix */
        if (isnan(*value)) {
            return "the exact solution is not representable in double precision at this time and these values";
        }
        break;
    case VR_THETA_EXACT:
    case VR_OMEGA_EXACT: {
        double theta, omega;
        problem = model_exact_now(data, cache, &theta, &omega);
        if (problem != NULL) {
            return problem;
        }
        *value = vr == VR_THETA_EXACT ? theta : omega;
        /* Never hand out a silent NaN: extreme parameters or times (|theta| beyond what a
         * double holds with any accuracy) are reported instead. */
        if (!isfinite(*value)) {
            return "the exact solution is not representable in double precision at this time and these values";
        }
        break;
    }
    default: return "unknown value reference of type Real";
    }
    return NULL;
}

const char *model_set_real(ModelData *data, ValueReference vr, double value) {
    const unsigned before_init = MODE_INSTANTIATED | MODE_INITIALIZATION;
    switch (vr) {
    case VR_L:
    case VR_G:
    case VR_THETA:
    case VR_OMEGA:
        if (((unsigned)data->mode & before_init) == 0) {
            return "is fixed after initialization (set it before ExitInitializationMode)";
        }
        if (!isfinite(value)) {
            return "must be a finite number";
        }
        if ((vr == VR_L || vr == VR_G) && !(value > 0.0)) {
            return "must be greater than 0";
        }
        break;
    case VR_DER_THETA:
    case VR_DER_OMEGA:
    case VR_THETA_EXACT:
    case VR_OMEGA_EXACT:
    case VR_PERIOD:
    case VR_X:
    case VR_Y:
        return "is calculated by the FMU and cannot be set";
    default: return "unknown value reference of type Real";
    }
    switch (vr) {
    case VR_L: data->L = value; break;
    case VR_G: data->g = value; break;
    case VR_THETA: data->theta = value; break;
    default: data->omega = value; break;
    }
    return NULL;
}

static int clamp_count(long count) {
    return count > INT_MAX ? INT_MAX : (int)count;
}

const char *model_get_integer(const ModelData *data, ValueReference vr, int *value) {
    switch (vr) {
    case VR_SOLVER: *value = data->solver; break;
    case VR_STATS_STEPS: *value = clamp_count(data->integrator.stats.steps); break;
    case VR_STATS_REJECTED_STEPS: *value = clamp_count(data->integrator.stats.rejected); break;
    case VR_STATS_RHS_EVALUATIONS: *value = clamp_count(data->integrator.stats.rhs_evals); break;
    default: return "unknown value reference of type Integer or Enumeration";
    }
    return NULL;
}

const char *model_set_integer(ModelData *data, ValueReference vr, int value) {
    switch (vr) {
    case VR_SOLVER:
        if (((unsigned)data->mode & (MODE_INSTANTIATED | MODE_INITIALIZATION)) == 0) {
            return "is fixed after initialization (set it before ExitInitializationMode)";
        }
        if (integrator_solver_name(value) == NULL) {
            return "must be one of the items of the enumeration Solver";
        }
        data->solver = value;
        return NULL;
    case VR_STATS_STEPS:
    case VR_STATS_REJECTED_STEPS:
    case VR_STATS_RHS_EVALUATIONS:
        return "is calculated by the FMU and cannot be set";
    default: return "unknown value reference of type Integer or Enumeration";
    }
}

const char *variable_name(ValueReference vr) {
#define VARIABLE(ref, name) if (vr == (ref)) return name;
    PENDULUM_VARIABLES
#undef VARIABLE
    return "(unknown)";
}
