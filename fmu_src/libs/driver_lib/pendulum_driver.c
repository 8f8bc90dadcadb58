/* pendulum_driver: the Co-Simulation output loop of the Python package, in C (see the header). */
#include "pendulum_driver.h"

#include <stdbool.h>
#include <string.h>

/* The FMI 2.0 and 3.0 signatures of the two calls (FMI 2.0.x 4.2.2 and 2.1.7, FMI 3.0 4.2.1
 * and 2.2.6.2), spelled with the standards' underlying C types: fmi2Status / fmi3Status are
 * enums (int), fmi2Boolean is int, fmi3Boolean is bool, value references are unsigned 32-bit. */
typedef int fmi2_do_step(void *component, double current, double step, int no_set_state_prior);
typedef int fmi2_get_real(void *component, const uint32_t *vrs, size_t nvr, double *values);
typedef int fmi3_do_step(void *instance, double current, double step, bool no_set_state_prior,
                         bool *event_handling_needed, bool *terminate, bool *early_return,
                         double *last_successful_time);
typedef int fmi3_get_float64(void *instance, const uint32_t *vrs, size_t nvr, double *values,
                             size_t nvalues);

enum { FMI_WARNING = 1 };  /* fmi2Warning == fmi3Warning; OK is 0, worse statuses are larger */

int pendulum_driver_abi(void) { return PENDULUM_DRIVER_ABI; }

static int stop(pendulum_drive_outcome *outcome, size_t done, int call, int status, double time)
{
    outcome->done = done;
    outcome->call = call;
    outcome->status = status;
    outcome->time = time;
    return call;
}

/* A function pointer from the address the caller took from the loaded FMU (as POSIX dlsym and
 * Windows GetProcAddress give it): copied bytewise, which ISO C allows where a cast is not. */
#define AS_FUNCTION(target, address) memcpy(&(target), &(address), sizeof(target))

static int drive_fmi2(const pendulum_drive_fmu *fmu, const double *times, size_t first, size_t last,
                      double *rows, size_t row_stride, pendulum_drive_outcome *outcome)
{
    fmi2_do_step *do_step;
    fmi2_get_real *get_real;
    AS_FUNCTION(do_step, fmu->do_step);
    AS_FUNCTION(get_real, fmu->get_values);
    for (size_t k = first; k < last; k++) {
        if (k > 0) {
            const double t0 = times[k - 1];
            const int status = do_step(fmu->instance, t0, times[k] - t0, 1);
            if (status > FMI_WARNING)
                return stop(outcome, k, PENDULUM_DRIVE_DO_STEP, status, t0);
        }
        const int status = get_real(fmu->instance, fmu->vrs, fmu->nvr, rows + k * row_stride);
        if (status > FMI_WARNING)
            return stop(outcome, k, PENDULUM_DRIVE_GET, status, times[k]);
    }
    return stop(outcome, last, PENDULUM_DRIVE_NONE, 0, times[last - 1]);
}

static int drive_fmi3(const pendulum_drive_fmu *fmu, const double *times, size_t first, size_t last,
                      double *rows, size_t row_stride, pendulum_drive_outcome *outcome)
{
    fmi3_do_step *do_step;
    fmi3_get_float64 *get_float64;
    AS_FUNCTION(do_step, fmu->do_step);
    AS_FUNCTION(get_float64, fmu->get_values);
    for (size_t k = first; k < last; k++) {
        if (k > 0) {
            const double t0 = times[k - 1];
            bool event = false, terminate = false, early = false;
            double reached = t0;
            const int status = do_step(fmu->instance, t0, times[k] - t0, true, &event, &terminate, &early, &reached);
            if (status > FMI_WARNING)
                return stop(outcome, k, PENDULUM_DRIVE_DO_STEP, status, t0);
            if (terminate)
                return stop(outcome, k, PENDULUM_DRIVE_TERMINATE, status, reached);
            if (early)
                return stop(outcome, k, PENDULUM_DRIVE_EARLY, status, reached);
        }
        const int status = get_float64(fmu->instance, fmu->vrs, fmu->nvr, rows + k * row_stride, fmu->nvr);
        if (status > FMI_WARNING)
            return stop(outcome, k, PENDULUM_DRIVE_GET, status, times[k]);
    }
    return stop(outcome, last, PENDULUM_DRIVE_NONE, 0, times[last - 1]);
}

int pendulum_drive(const pendulum_drive_fmu *fmu, const double *times, size_t first, size_t last,
                   double *rows, size_t row_stride, pendulum_drive_outcome *outcome)
{
    if (outcome == NULL)
        return PENDULUM_DRIVE_BAD_ARGS;
    if (fmu == NULL || times == NULL || rows == NULL || fmu->instance == NULL || fmu->do_step == NULL
        || fmu->get_values == NULL || (fmu->vrs == NULL && fmu->nvr > 0) || first > last)
        return stop(outcome, first, PENDULUM_DRIVE_BAD_ARGS, 0, 0.0);
    if (first == last)
        return stop(outcome, first, PENDULUM_DRIVE_NONE, 0, first > 0 ? times[first - 1] : 0.0);
    if (fmu->fmi_version == 2)
        return drive_fmi2(fmu, times, first, last, rows, row_stride, outcome);
    if (fmu->fmi_version == 3)
        return drive_fmi3(fmu, times, first, last, rows, row_stride, outcome);
    return stop(outcome, first, PENDULUM_DRIVE_BAD_ARGS, 0, 0.0);
}
