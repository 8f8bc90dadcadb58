/* fuzz_api.h: the FMI calls the API fuzzer makes, behind one table per FMI version, so that
 * the same program of calls drives an FMI 2.0 and an FMI 3.0 instance in lockstep (their
 * statuses and outputs must agree bit for bit). Each entry returns the FMI status as an int.
 * Where the versions differ in shape, the entry does what both can: setup_and_enter is
 * fmi2SetupExperiment + fmi2EnterInitializationMode or fmi3EnterInitializationMode; do_step
 * also reports the last successful time. */
#ifndef PENDULUM_FUZZ_API_H
#define PENDULUM_FUZZ_API_H

#include <stddef.h>

typedef struct {
    void *(*instantiate)(int co_simulation, int logging_on);
    void (*free_instance)(void *c);
    int (*setup_and_enter)(void *c, int tolerance_defined, double tolerance);
    int (*enter_initialization)(void *c);
    int (*exit_initialization)(void *c);
    int (*set_real)(void *c, unsigned vr, double value);
    int (*get_real)(void *c, unsigned vr, double *value);
    int (*set_integer)(void *c, unsigned vr, int value);
    int (*get_integer)(void *c, unsigned vr, int *value);
    int (*do_step)(void *c, double point, double step, double *reached);
    int (*terminate)(void *c);
    int (*reset)(void *c);
    int (*get_state)(void *c, void **state);
    int (*set_state)(void *c, void *state);
    int (*free_state)(void *c, void **state);
    int (*state_size)(void *c, void *state, size_t *size);
    int (*serialize)(void *c, void *state, unsigned char *bytes, size_t size);
    int (*deserialize)(void *c, const unsigned char *bytes, size_t size, void **state);
    int (*set_time)(void *c, double time);
    int (*set_states)(void *c, const double *x, size_t n);
    int (*get_derivatives)(void *c, double *dx, size_t n);
    int (*enter_continuous_time)(void *c);
    int (*update_and_enter_event)(void *c);
    int (*directional)(void *c, unsigned unknown, unsigned known, double *value);
    int (*output_derivative)(void *c, unsigned vr, int order, double *value);
} FuzzApi;

extern const FuzzApi FUZZ_FMI2;
#ifdef PENDULUM_FUZZ_FMI3
extern const FuzzApi FUZZ_FMI3;
#endif

/* Prints the FMU's messages when FUZZ_VERBOSE is set (fuzz_fmi_api.c). */
void fuzz_report(const char *message);

#endif
