/* body.c: PendulumBody (split.h). Input alpha; states theta, omega with theta' = omega,
 * omega' = alpha; outputs theta, omega and the exact solution of the whole pendulum through
 * the start values (theta_exact, omega_exact, Pendulum.fmu's exact port). Within a step the
 * input is the polynomial alpha(s) = a + b s + c s^2 / 2 of split.h, so the states are
 * integrated in closed form:
 *     omega(h) = omega + a h + b h^2 / 2 + c h^3 / 6
 *     theta(h) = theta + omega h + a h^2 / 2 + b h^3 / 6 + c h^4 / 24
 * exact for that input, with no solver and no step inside. */
#include <math.h>
#include <string.h>

#include "pendulum_vrs.h"
#include "split.h"
#include "split_tokens.h"

/* The value references Body shares with Pendulum.fmu are Pendulum's: the model core serves them. */
typedef char shared_value_references[(SPLIT_VR_L == VR_L && SPLIT_VR_G == VR_G && SPLIT_VR_THETA == VR_THETA &&
                                       SPLIT_VR_OMEGA == VR_OMEGA && SPLIT_VR_THETA_EXACT == VR_THETA_EXACT &&
                                       SPLIT_VR_OMEGA_EXACT == VR_OMEGA_EXACT) ? 1 : -1];

const char *const SPLIT_MODEL_NAME = "PendulumBody";
const char *const SPLIT_TOKEN = PENDULUM_BODY_TOKEN;
const ValueReference SPLIT_INPUT_VR = SPLIT_VR_ALPHA;
const double SPLIT_INPUT_START = 0.0;
const char SPLIT_STATE_MAGIC[] = "PNDLBODY";

/* theta, omega: orders 1..3 from omega and the input polynomial; theta_exact, omega_exact: from
 * the exact solution, as Pendulum.fmu. Both FMI versions. */
int split_model_max_output_order(int fmi_version) {
    (void)fmi_version;
    return 3;
}

const char *split_model_variable_name(ValueReference vr) {
    switch (vr) {
    case SPLIT_VR_L: return "L";
    case SPLIT_VR_G: return "g";
    case SPLIT_VR_THETA: return "theta";
    case SPLIT_VR_DER_THETA: return "der(theta)";
    case SPLIT_VR_OMEGA: return "omega";
    case SPLIT_VR_DER_OMEGA: return "der(omega)";
    case SPLIT_VR_THETA_EXACT: return "theta_exact";
    case SPLIT_VR_OMEGA_EXACT: return "omega_exact";
    case SPLIT_VR_ALPHA: return "alpha";
    default: return "(unknown)";
    }
}

const char *split_model_get_real(SplitInstance *inst, ValueReference vr, double *value) {
    switch (vr) {
    case SPLIT_VR_L:
    case SPLIT_VR_G:
    case SPLIT_VR_THETA:
    case SPLIT_VR_OMEGA:
    case SPLIT_VR_THETA_EXACT:
    case SPLIT_VR_OMEGA_EXACT:
        return model_get_real(&inst->core.data, &inst->core.exact_now, vr, value);
    case SPLIT_VR_DER_THETA: *value = inst->core.data.omega; return NULL;
    case SPLIT_VR_DER_OMEGA: *value = inst->input.value; return NULL;
    default: return "unknown value reference of type Real";
    }
}

const char *split_model_set_real(SplitInstance *inst, ValueReference vr, double value) {
    switch (vr) {
    case SPLIT_VR_L:
    case SPLIT_VR_G:
    case SPLIT_VR_THETA:
    case SPLIT_VR_OMEGA:
        return model_set_real(&inst->core.data, vr, value); /* fixed after initialization, finite, L, g > 0 */
    case SPLIT_VR_DER_THETA:
    case SPLIT_VR_DER_OMEGA:
    case SPLIT_VR_THETA_EXACT:
    case SPLIT_VR_OMEGA_EXACT:
        return "is calculated by the FMU and cannot be set";
    default: return "unknown value reference of type Real";
    }
}

/* Pendulum.fmu's initialization: g / L checked, the exact solution set up from the start values. */
const char *split_model_initialize(SplitInstance *inst) {
    return model_initialize(&inst->core.data, INTERFACE_CO_SIMULATION);
}

void split_model_advance(SplitInstance *inst, double h) {
    ModelData *data = &inst->core.data;
    const double a = inst->input.value, b = inst->input.d1, c = inst->input.d2;
    const double omega = data->omega;
    data->omega = omega + h * (a + h * (b / 2.0 + h * (c / 6.0)));
    data->theta = data->theta + h * (omega + h * (a / 2.0 + h * (b / 6.0 + h * (c / 24.0))));
}

const char *split_model_output_derivative(SplitInstance *inst, ValueReference vr, int order, double *value) {
    const ModelData *data = &inst->core.data;
    const InputPolynomial *u = &inst->input;
    /* d^k/dt^k of (theta, omega): theta' = omega, then the input and its derivatives */
    const double chain[5] = {data->theta, data->omega, u->value, u->d1, u->d2};
    switch (vr) {
    case SPLIT_VR_THETA: *value = chain[order]; return NULL;
    case SPLIT_VR_OMEGA: *value = chain[order + 1]; return NULL;
    case SPLIT_VR_THETA_EXACT:
    case SPLIT_VR_OMEGA_EXACT: {
        /* the exact pendulum: theta_e' = omega_e, omega_e' = -a sin theta_e, sin and cos from the
         * elliptic functions themselves (exact.h), as Pendulum.fmu's output derivatives */
        const double a = data->g / data->L;
        double theta_e, omega_e, s, c, exact[4];
        const char *problem = model_exact_now(data, &inst->core.exact_now, &theta_e, &omega_e);
        if (problem != NULL) {
            return problem;
        }
        pendulum_exact_sin_cos(&data->exact, data->time, &s, &c);
        exact[0] = omega_e;
        exact[1] = -a * s;
        exact[2] = -a * c * omega_e;
        exact[3] = a * s * (omega_e * omega_e + a * c);
        *value = exact[(vr == SPLIT_VR_THETA_EXACT ? 0 : 1) + order - 1];
        return NULL;
    }
    default: return "is not a continuous output";
    }
}

/* Before initialization the exact solution and the solver are the reset ones; after it, what
 * ExitInitializationMode made of the start values (model_initialize), the solver never
 * stepped (Body integrates its input in closed form). */
const char *split_model_check_state(const ModelData *data, const ModelData *reset) {
    Integrator fresh;
    if ((data->mode & (MODE_INSTANTIATED | MODE_INITIALIZATION)) != 0) {
        if (memcmp(&reset->exact, &data->exact, sizeof reset->exact) != 0 ||
            memcmp(&reset->integrator, &data->integrator, sizeof reset->integrator) != 0) {
            return "the exact solution or the solver is not the one of a state before initialization";
        }
        return NULL;
    }
    if (!pendulum_exact_same(&data->exact) || !(data->exact.g == data->g) || !(data->exact.L == data->L) ||
        !(data->exact.t0 == data->start_time)) {
        return "the exact solution does not match its start values and parameters";
    }
    if (integrator_init_gl(&fresh, (SolverKind)data->solver, data->g, data->L, data->tolerance, data->start_time,
                           data->exact.theta0, data->exact.omega0) != 0) {
        return "the solver cannot be set up for the state's start values";
    }
    return integrator_check(&data->integrator, &fresh);
}
