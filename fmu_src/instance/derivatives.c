/* instance/derivatives.c: exact partial derivatives (directional and adjoint, FMI 2.0 3.2.1 /
 * FMI 3.0 3.2.7.2) and exact time derivatives of the outputs (FMI 2.0 4.2.1, FMI 3.0 4.2.1),
 * for both FMI versions, from the equation theta' = omega, omega' = -a sin(theta), a = g/L.
 *
 * After initialization the knowns are the states theta and omega (ModelStructure <Outputs>
 * and <Derivatives>); in Initialization Mode also L and g (<InitialUnknowns>), where time is
 * the start time, so theta_exact = theta and omega_exact = omega, and period = 4 K(m) / w0
 * (libration) or 2 K(1/m) / (sqrt(m) w0) (rotation) with m = sin^2(theta/2) + omega^2 L/(4 g). */
#include <math.h>

#include "instance.h"
#include "pendulum_vrs.h"


/* dK/dp of the complete elliptic integral K(p) = K, given p and p1 = 1 - p (accurately):
 * dK/dp = (E - p1 K) / (2 p p1) (DLMF 19.4.1), with E - p1 K = K (p/2 - sum_{n>=1} 2^(n-1) c_n^2)
 * from the AGM (DLMF 19.8.6), c_{n+1} = c_n^2 / (4 a_{n+1}) without cancellation. */
static double dK_dp(double p, double p1, double K) {
    double a = 1.0, b = sqrt(p1), c = sqrt(p), sum = 0.0, weight = 1.0; /* 2^(n-1), n = 1 */
    int n;
    if (p == 0.0) {
        return 0.39269908169872414; /* pi/8: K = pi/2 (1 + p/4 + ...) */
    }
    for (n = 0; n < 64; n++) {
        double a_next = 0.5 * (a + b);
        c = c * c / (4.0 * a_next);
        b = sqrt(a * b);
        a = a_next;
        sum += weight * c * c;
        weight *= 2.0;
        if (weight * c * c <= 1e-18 * sum) {
            break;
        }
    }
    return K * (0.5 * p - sum) / (2.0 * p * p1);
}

/* Partial derivatives of the period by (L, g, theta, omega) in Initialization Mode, each
 * written as a sum of terms of one sign wherever the derivative itself has no zero, so that
 * each keeps its relative accuracy (docs/derivatives.md). With a = g/L = w0^2, T depends on
 * L and g only through a: dT/dL = -(a/L) dT/da, dT/dg = (1/L) dT/da.
 *   Libration, T = 4 K(m) / w0, m = s^2 + q^2, q^2 = omega^2 / (4 a), s = sin(theta/2):
 *     a dT/da = -T (q^2 K'(m) / K + 1/2)                (both terms of one sign)
 *   Rotation, T = 2 K(p) / R, R = sqrt(m) w0 = sqrt(a s^2 + omega^2/4), p = 1/m = a / R^2:
 *     a dT/da = (p / R) (2 K'(p) (omega/2)^2 / R^2 - K s^2)
 *   (dT/dm dm/dL + T/(2L) cancelled there: both terms ~T/L, their sum ~p T/L, so in fast
 *   rotation it lost digits in proportion to m = (omega/(2 w0))^2). The two rotation terms
 *   differ in sign; they meet where K s^2 = 2 K'(p) (omega/2)^2 / R^2, near theta = +-pi/2
 *   in fast rotation (K'/K -> 1/4): a true zero of dT/da as theta0 varies, where only the
 *   absolute accuracy ~1e-16 (p/R) K is to be had. */
static const char *period_partials(const ModelData *data, double d_period[4]) {
    PendulumExact ex;
    double K, a_dT_da, dm[2];
    if (pendulum_exact_init_gl(&ex, data->theta, data->omega, data->g, data->L, data->time) != 0) {
        return "the exact solution cannot be set up for these start values";
    }
    if (ex.regime == PENDULUM_SEPARATRIX || !isfinite(ex.period)) {
        return "the period is infinite on the separatrix: it has no derivative";
    }
    K = ex.K_hi + ex.K_lo;
    if (ex.regime == PENDULUM_LIBRATION) {
        const double w0 = sqrt(data->g / data->L), dK = dK_dp(ex.m, ex.m1, K), dT_dm = 4.0 / w0 * dK;
        const double q2 = data->omega * data->omega * data->L / (4.0 * data->g);
        a_dT_da = -ex.period * (q2 * dK / K + 0.5);
        /* dm by theta and omega */
        dm[0] = 0.5 * sin(data->theta);
        dm[1] = data->omega * data->L / (2.0 * data->g);
        d_period[2] = dT_dm * dm[0];
        d_period[3] = dT_dm * dm[1];
    } else {
        /* R = ex.scale, p = k^2 of the parameter 1/m, 1 - p = k'^2 */
        const double R = ex.scale, p = ex.k * ex.k, p1 = ex.kc * ex.kc, dK = dK_dp(p, p1, K);
        const double half_omega = 0.5 * fabs(data->omega), s = sin(0.5 * data->theta);
        const double share = (half_omega / R) * (half_omega / R); /* (omega/2)^2 / R^2 = 1 - p s^2 */
        const double common = dK * p + 0.5 * K;                  /* K'(p) p + K/2 > 0 */
        a_dT_da = p / R * (2.0 * dK * share - K * s * s);
        /* dT/dtheta = -(sin theta p / R) (K' p + K/2), dT/domega = -(omega / R^3) (K' p + K/2) */
        d_period[2] = -(sin(data->theta) * p / R) * common;
        d_period[3] = -(data->omega / R / R / R) * common;
    }
    d_period[0] = -a_dT_da / data->L;
    d_period[1] = a_dT_da / data->g;
    return NULL;
}

/* The partial derivative of `unknown` by `known`; NULL or why the pair is not one. */
static const char *partial(const ModelData *data, ValueReference unknown, ValueReference known, double *value) {
    const int initial = data->mode == MODE_INITIALIZATION;
    const double a = data->g / data->L, s = sin(data->theta), c = cos(data->theta);
    /* index of the known: 0 L, 1 g, 2 theta, 3 omega */
    int k;
    double row[4] = {0.0, 0.0, 0.0, 0.0};
    switch (known) {
    case VR_L: k = 0; break;
    case VR_G: k = 1; break;
    case VR_THETA: k = 2; break;
    case VR_OMEGA: k = 3; break;
    default: return "is not a known of the Jacobian (a state, or in Initialization Mode also L or g)";
    }
    if (k < 2 && !initial) {
        return "is fixed after initialization: L and g are knowns only in Initialization Mode";
    }
    switch (unknown) {
    case VR_THETA: row[2] = 1.0; break;
    case VR_OMEGA: row[3] = 1.0; break;
    case VR_DER_THETA: row[3] = 1.0; break;                  /* der(theta) = omega */
    case VR_DER_OMEGA:                                       /* der(omega) = -(g/L) sin(theta) */
        row[0] = a * s / data->L;
        row[1] = -s / data->L;
        row[2] = -a * c;
        break;
    case VR_X: row[0] = s; row[2] = data->L * c; break;      /* x = L sin(theta) */
    case VR_Y: row[0] = -c; row[2] = data->L * s; break;     /* y = -L cos(theta) */
    case VR_THETA_EXACT: row[2] = initial ? 1.0 : 0.0; break; /* at the start time: theta */
    case VR_OMEGA_EXACT: row[3] = initial ? 1.0 : 0.0; break;
    case VR_PERIOD:
        if (initial) {
            const char *problem = period_partials(data, row);
            if (problem != NULL) {
                return problem;
            }
        }
        break;
    default: return "is not an unknown of the Jacobian (a Float64 output, derivative or calculated parameter)";
    }
    *value = row[k];
    return NULL;
}

/* No made-up value with OK: a derivative that overflows double precision (extreme g and L, or
 * a seed that is not finite) is refused with its reason, never handed out. */
static Status all_finite(Instance *inst, const char *function, const char *what, const double value[], size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (!isfinite(value[i])) {
            return instance_fail(inst, function, "%s %zu is %g: beyond double precision at L = %g, g = %g "
                                 "(or a seed that is not finite)", what, i, value[i], inst->data.L, inst->data.g);
        }
    }
    return STATUS_OK;
}

Status instance_partials(Instance *inst, const char *function, int adjoint, const ValueReference unknowns[],
                         size_t n_unknowns, const ValueReference knowns[], size_t n_knowns, const double seed[],
                         double sensitivity[]) {
    const ModelData *data;
    const double w0sq = inst == NULL ? 0.0 : inst->data.g / inst->data.L;
    size_t i, j, n_out;
    if (!instance_call_allowed(inst, function, CALL_PARTIAL_DERIVATIVES)) {
        return STATUS_ERROR;
    }
    data = &inst->data;
    if ((n_unknowns > 0 && unknowns == NULL) || (n_knowns > 0 && knowns == NULL) ||
        ((adjoint ? n_unknowns : n_knowns) > 0 && seed == NULL) ||
        ((adjoint ? n_knowns : n_unknowns) > 0 && sensitivity == NULL)) {
        return instance_fail(inst, function, "an array is NULL while its length is not 0");
    }
    if (!(isfinite(w0sq) && w0sq > 0.0)) {
        return instance_fail(inst, function, "g / L must be a finite number greater than 0");
    }
    n_out = adjoint ? n_knowns : n_unknowns;
    for (i = 0; i < n_out; i++) {
        sensitivity[i] = 0.0;
    }
    /* directional: sensitivity_i = sum_j J(u_i, k_j) seed_j; adjoint: sensitivity_j = sum_i seed_i J(u_i, k_j) */
    for (i = 0; i < n_unknowns; i++) {
        for (j = 0; j < n_knowns; j++) {
            double entry = 0.0;
            const char *problem = partial(data, unknowns[i], knowns[j], &entry);
            if (problem != NULL) {
                return instance_fail(inst, function, "d %s (value reference %u) / d %s (value reference %u): %s",
                                     variable_name(unknowns[i]), unknowns[i], variable_name(knowns[j]), knowns[j],
                                     problem);
            }
            if (adjoint) {
                sensitivity[j] += seed[i] * entry;
            } else {
                sensitivity[i] += entry * seed[j];
            }
        }
    }
    return all_finite(inst, function, "sensitivity", sensitivity, n_out);
}

/* Derivatives 1..3 of theta along the equation at (theta, omega), a = g/L:
 * theta' = omega, theta'' = -a sin, theta''' = -a cos omega. */
static void theta_derivatives(double a, double theta, double omega, double d[4]) {
    d[0] = theta;
    d[1] = omega;
    d[2] = -a * sin(theta);
    d[3] = -a * cos(theta) * omega;
}

/* d^n/dt^n of sin(theta) or cos(theta) (n = 1..3) from theta's derivatives (Faa di Bruno). */
static double sin_derivative(const double d[4], int n) {
    double s = sin(d[0]), c = cos(d[0]);
    switch (n) {
    case 1: return c * d[1];
    case 2: return -s * d[1] * d[1] + c * d[2];
    default: return -c * d[1] * d[1] * d[1] - 3.0 * s * d[1] * d[2] + c * d[3];
    }
}

static double cos_derivative(const double d[4], int n) {
    double s = sin(d[0]), c = cos(d[0]);
    switch (n) {
    case 1: return -s * d[1];
    case 2: return -c * d[1] * d[1] - s * d[2];
    default: return s * d[1] * d[1] * d[1] - 3.0 * c * d[1] * d[2] - s * d[3];
    }
}

Status instance_output_derivatives(Instance *inst, const char *function, const ValueReference vr[], size_t nvr,
                                   const int order[], double value[]) {
    ModelData *data;
    double a, d[4], d_exact[4], theta_exact = 0.0, omega_exact = 0.0, sin_exact = 0.0, cos_exact = 1.0;
    int have_exact;
    size_t i;
    if (!instance_call_allowed(inst, function, CALL_GET_OUTPUT_DERIVATIVES)) {
        return STATUS_ERROR;
    }
    if (nvr > 0 && (vr == NULL || order == NULL || value == NULL)) {
        return instance_fail(inst, function, "vr, order or value is NULL with nvr = %zu", nvr);
    }
    data = &inst->data;
    a = data->g / data->L;
    theta_derivatives(a, data->theta, data->omega, d);
    /* theta_exact and omega_exact at this time: the instance's cached ones (model.h) */
    have_exact = model_exact_now(data, &inst->exact_now, &theta_exact, &omega_exact) == NULL;
    if (have_exact) {
        /* sin and cos of theta_exact from the elliptic functions themselves: -(g/L) sin of the
         * rounded theta_exact is only absolutely accurate near the top and after many turns */
        pendulum_exact_sin_cos(&data->exact, data->time, &sin_exact, &cos_exact);
    }
    d_exact[0] = theta_exact;
    d_exact[1] = omega_exact;
    d_exact[2] = -a * sin_exact;
    d_exact[3] = -a * cos_exact * omega_exact;
    for (i = 0; i < nvr; i++) {
        const int n = order[i];
        if (n < 1 || n > MAX_OUTPUT_DERIVATIVE_ORDER) {
            return instance_fail(inst, function, "order %d of %s is not in 1..%d (maxOutputDerivativeOrder)", n,
                                 variable_name(vr[i]), MAX_OUTPUT_DERIVATIVE_ORDER);
        }
        switch (vr[i]) {
        case VR_THETA: value[i] = d[n]; break;
        case VR_OMEGA: value[i] = n < 3 ? d[n + 1] : a * sin(d[0]) * (d[1] * d[1] + a * cos(d[0])); break;
        case VR_X: value[i] = data->L * sin_derivative(d, n); break;
        case VR_Y: value[i] = -data->L * cos_derivative(d, n); break;
        case VR_THETA_EXACT:
        case VR_OMEGA_EXACT:
            if (!have_exact) {
                return instance_fail(inst, function, "the exact solution is not representable at this time");
            }
            value[i] = vr[i] == VR_THETA_EXACT ? d_exact[n]
                       : n < 3                 ? d_exact[n + 1]
                                               : a * sin_exact * (omega_exact * omega_exact + a * cos_exact);
            break;
        default:
            return instance_fail(inst, function, "%s (value reference %u) is not a continuous output",
                                 variable_name(vr[i]), vr[i]);
        }
    }
    return all_finite(inst, function, "output derivative", value, nvr);
}
