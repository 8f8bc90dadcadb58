/* gravity.c: PendulumGravity (split.h). Input theta; output alpha = -(g/L) sin(theta), the
 * pendulum's right-hand side from the model core (model_derivatives). No states: a step only
 * moves time and the input polynomial.
 *
 * Output derivatives: alpha is a function of the input alone, so its time derivatives are
 * those of alpha(theta(t)) along the input as the FMU knows it, the polynomial theta(s) =
 * theta + theta' s + theta'' s^2 / 2 of split.h:
 *     alpha'  = -(g/L) cos(theta) theta'
 *     alpha'' = -(g/L) (cos(theta) theta'' - sin(theta) theta'^2)
 * With FMI 2.0 a master sets theta' and theta'' (fmi2SetRealInputDerivatives); FMI 3.0 has no
 * input derivatives in Co-Simulation, so the input is held, every derivative of alpha would
 * be 0, and the FMI 3.0 Gravity declares maxOutputDerivativeOrder 0 rather than hand out
 * zeros a master would extrapolate with. */
#include <math.h>
#include <string.h>

#include "pendulum_vrs.h"
#include "split.h"
#include "split_tokens.h"

typedef char shared_value_references[(SPLIT_VR_L == VR_L && SPLIT_VR_G == VR_G) ? 1 : -1];

const char *const SPLIT_MODEL_NAME = "PendulumGravity";
const char *const SPLIT_TOKEN = PENDULUM_GRAVITY_TOKEN;
const ValueReference SPLIT_INPUT_VR = SPLIT_VR_THETA;
const double SPLIT_INPUT_START = START_THETA;
const char SPLIT_STATE_MAGIC[] = "PNDLGRAV";

int split_model_max_output_order(int fmi_version) {
    return fmi_version == 2 ? 2 : 0;
}

const char *split_model_variable_name(ValueReference vr) {
    switch (vr) {
    case SPLIT_VR_L: return "L";
    case SPLIT_VR_G: return "g";
    case SPLIT_VR_THETA: return "theta";
    case SPLIT_VR_ALPHA: return "alpha";
    default: return "(unknown)";
    }
}

/* alpha = der(omega) of the pendulum at theta = the input: model_derivatives, which also
 * refuses a g / L that is not a finite number greater than 0. */
static const char *alpha_now(SplitInstance *inst, double *alpha) {
    double der_theta;
    inst->core.data.theta = inst->input.value;
    return model_derivatives(&inst->core.data, &der_theta, alpha);
}

const char *split_model_get_real(SplitInstance *inst, ValueReference vr, double *value) {
    switch (vr) {
    case SPLIT_VR_L:
    case SPLIT_VR_G:
        return model_get_real(&inst->core.data, &inst->core.exact_now, vr, value);
    case SPLIT_VR_ALPHA: return alpha_now(inst, value);
    default: return "unknown value reference of type Real";
    }
}

const char *split_model_set_real(SplitInstance *inst, ValueReference vr, double value) {
    switch (vr) {
    case SPLIT_VR_L:
    case SPLIT_VR_G:
        return model_set_real(&inst->core.data, vr, value); /* fixed after initialization, finite, > 0 */
    case SPLIT_VR_ALPHA: return "is calculated by the FMU and cannot be set";
    default: return "unknown value reference of type Real";
    }
}

const char *split_model_initialize(SplitInstance *inst) {
    double alpha;
    return alpha_now(inst, &alpha);
}

void split_model_advance(SplitInstance *inst, double h) {
    (void)inst, (void)h; /* no states */
}

const char *split_model_output_derivative(SplitInstance *inst, ValueReference vr, int order, double *value) {
    const ModelData *data = &inst->core.data;
    const InputPolynomial *u = &inst->input;
    const double a = data->g / data->L, s = sin(u->value), c = cos(u->value);
    if (vr != SPLIT_VR_ALPHA) {
        return "is not a continuous output";
    }
    *value = order == 1 ? -a * c * u->d1 : -a * (c * u->d2 - s * u->d1 * u->d1);
    return NULL;
}

/* Gravity's initialization sets up neither the exact solution nor a solver, and nothing sets
 * omega: each is its reset value in every mode. */
const char *split_model_check_state(const ModelData *data, const ModelData *reset) {
    if (memcmp(&reset->exact, &data->exact, sizeof reset->exact) != 0 ||
        memcmp(&reset->integrator, &data->integrator, sizeof reset->integrator) != 0) {
        return "the exact solution or the solver is not the reset one (Gravity sets up neither)";
    }
    if (!(data->omega == reset->omega)) {
        return "omega is not its start value (Gravity has no state omega)";
    }
    return NULL;
}
