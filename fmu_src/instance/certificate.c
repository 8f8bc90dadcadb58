/* instance/certificate.c: every Co-Simulation step that returns OK is a certificate. After
 * each DoStep (FMI 2.0 and 3.0 alike) the numerical state is compared with the exact solution
 * at the new time; OK means both
 *     |theta - theta_exact| <= (100 tol - e) max(1, |theta_exact|)        (rad)
 *     |omega - omega_exact| <= (100 tol - e) max(w0, |omega_exact|)       (rad/s)
 * hold, e = 5e-14 the exact port's own error bound (CERTIFICATE_EXACT_ERROR), so that the
 * true error is within 100 tol of the same scales (the omega scale w0 = sqrt(g/L): omega in
 * units of the motion's own rate, so the bound is the same dimensionless statement at every L
 * and g). Otherwise the step returns Warning,
 * every step that stays beyond the bound, and logs (logStatusWarning) when the bound is first
 * crossed and again each time the departure, in units of the bound, has grown tenfold since
 * the last message.
 *
 * The certificate only reads the exact solution: the solver never sees it, so the numbers a
 * step returns are the same, bit for bit, with the certificate on or off (Instance's
 * certificate_off, set only by C tests that link the core; tests/c/test_certificate.c).
 *
 * It also carries the hard case (a libration carried over the top, a rotation reversed):
 * that qualitative miss is named once per run, in the same message when both fall on one
 * step. */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "instance.h"

/* The solver's name for the messages (the solver table's, integrator.c). */
static const char *solver_name(int solver) {
    const char *name = integrator_solver_name(solver);
    return name == NULL ? "?" : name;
}

double certificate_factor(double tolerance) {
    /* the bound on the distance to the exact port that leaves room for the port's own error
     * (instance.h): |x - x_true| <= |x - x_exact| + |x_exact - x_true| */
    return CERTIFICATE_FACTOR * tolerance - CERTIFICATE_EXACT_ERROR;
}

double certificate_ratio(double w0, double tolerance, double theta, double omega, double theta_exact,
                         double omega_exact) {
    /* fmax(1, |theta_exact|) and fmax(w0, |omega_exact|) written out (fmax is a library call
     * on x86-64): the same value for every argument, NaN included (the other operand) */
    const double abs_theta = fabs(theta_exact), abs_omega = fabs(omega_exact);
    const double factor = certificate_factor(tolerance);
    const double bound_theta = factor * (abs_theta > 1.0 ? abs_theta : 1.0);
    const double bound_omega = factor * (abs_omega > w0 ? abs_omega : w0);
    const double dev_theta = fabs(theta - theta_exact) / bound_theta;
    const double dev_omega = fabs(omega - omega_exact) / bound_omega;
    if (!(factor > 0.0) || !(dev_theta <= DBL_MAX) || !(dev_omega <= DBL_MAX)) {
        return INFINITY; /* no room beside the port's error, NaN or overflow: nothing is certified */
    }
    return dev_theta > dev_omega ? dev_theta : dev_omega; /* both finite: fmax's value */
}

int certificate_reachable(int solver, double tolerance, double m1, double m) {
    /* near the separatrix an energy error dm1 moves the period by ~dm1 / m1 of itself
     * (dK/dm ~ 1/(2 m1)): the accuracy a solver needs over ten periods is about tol |1 - m|,
     * and each method holds it down to its measured line (integrator.h) */
    return tolerance * fabs(m1) / fmax(1.0, m) >= integrator_reach((SolverKind)solver);
}

/* The end of the message: what would hold the bound. */
static void remedy(const ModelData *data, char *text, size_t size) {
    const double need = data->tolerance * fabs(data->exact.m1) / fmax(1.0, data->exact.m);
    if (certificate_reachable(data->solver, data->tolerance, data->exact.m1, data->exact.m)) {
        snprintf(text, size, "A smaller tolerance would hold it; theta_exact and omega_exact are exact.");
    } else if (certificate_reachable(SOLVER_RKN, data->tolerance, data->exact.m1, data->exact.m)) {
        snprintf(text, size, "%s cannot hold it this close to the separatrix (tol |1 - m| = %.2g, below its "
                 "%.0e); rkn, dopri5 or symplectic at this tolerance can.", solver_name(data->solver), need,
                 integrator_reach((SolverKind)data->solver));
    } else {
        snprintf(text, size, "No double-precision solver can hold it this close to the separatrix "
                 "(tol |1 - m| = %.2g, below %.0e: the rounding of the state alone moves the period by more); "
                 "read theta_exact and omega_exact.", need, INTEGRATOR_REACH);
    }
}

Status instance_check_step(Instance *inst) {
    ModelData *data = &inst->data;
    const char *miss = NULL;
    double ratio = 0.0, theta_exact = NAN, omega_exact = NAN;
    int beyond = 0, log_certificate = 0;
    char certificate[640], hold[256];

    certificate[0] = '\0';
    if (!data->hard_case_reported && pendulum_exact_resolvable(&data->exact, data->time)) {
        miss = pendulum_exact_qualitative_miss(&data->exact, data->theta, data->omega);
    }
    if (!inst->certificate_off) {
        /* the exact state at the new time, evaluated here once and kept for the GetReals of
         * theta_exact and omega_exact that usually follow (inst->exact_now, model.h) */
        if (model_exact_now(data, &inst->exact_now, &theta_exact, &omega_exact) == NULL) {
            ratio = certificate_ratio(data->exact.w0, data->tolerance, data->theta, data->omega, theta_exact,
                                      omega_exact);
        } else {
            theta_exact = NAN; /* not resolvable at this time: nothing is certified */
            omega_exact = NAN;
            ratio = INFINITY;
        }
        beyond = !(ratio <= 1.0);
        /* first crossing, then each tenfold growth since the last message (an unresolvable time
         * or a state that is not finite counts as DBL_MAX: logged once) */
        log_certificate = beyond && (data->certificate_logged == 0.0 ||
                                     (ratio >= 10.0 * data->certificate_logged && data->certificate_logged < DBL_MAX));
        if (log_certificate) {
            remedy(data, hold, sizeof hold);
            data->certificate_logged = fmin(ratio, DBL_MAX);
            snprintf(certificate, sizeof certificate,
                     "certificate: at t = %.9g the step is %.3g times beyond its bound "
                     "(|theta - theta_exact| = %.3g rad, bound %.3g rad; |omega - omega_exact| = %.3g rad/s, "
                     "bound %.3g rad/s; solver %s, tolerance %g, 1 - m = %.3g). %s",
                     data->time, ratio, fabs(data->theta - theta_exact),
                     certificate_factor(data->tolerance) * fmax(1.0, fabs(theta_exact)),
                     fabs(data->omega - omega_exact),
                     certificate_factor(data->tolerance) * fmax(data->exact.w0, fabs(omega_exact)),
                     solver_name(data->solver), data->tolerance, data->exact.m1, hold);
        }
    } else if (miss != NULL && model_exact_now(data, &inst->exact_now, &theta_exact, &omega_exact) != NULL) {
        theta_exact = NAN; /* not reached: a miss is looked for only where the time is resolvable */
        omega_exact = NAN;
    }
    if (miss != NULL) {
        data->hard_case_reported = 1;
        instance_log(inst, STATUS_WARNING, LOG_STATUS_WARNING,
                     "hard case: by t = %.9g the numerical solution (solver %s, tolerance %g) %s: theta = %.9g rad, "
                     "omega = %.9g rad/s, the exact solution theta_exact = %.9g rad, omega_exact = %.9g rad/s. "
                     "Use a tighter tolerance or another solver, or read theta_exact.%s%s",
                     data->time, solver_name(data->solver), data->tolerance, miss, data->theta, data->omega,
                     theta_exact, omega_exact, log_certificate ? " " : "", certificate);
        return STATUS_WARNING;
    }
    if (log_certificate) {
        instance_log(inst, STATUS_WARNING, LOG_STATUS_WARNING, "%s", certificate);
    }
    return beyond ? STATUS_WARNING : STATUS_OK;
}
