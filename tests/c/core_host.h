/* core_host.h: for C tests that link the model core directly (no FMI layer): the memory half
 * of an InstanceHost (zeroed memory from calloc, returned with free), and a Co-Simulation
 * instance started from given values. */
#ifndef PENDULUM_TESTS_CORE_HOST_H
#define PENDULUM_TESTS_CORE_HOST_H

#include <stdlib.h>
#include <string.h>

#include "instance.h"
#include "pendulum_vrs.h"

static void *host_allocate(const Instance *inst, size_t size)
{
    (void)inst;
    return calloc(1, size);
}

static void host_release(const Instance *inst, void *memory)
{
    (void)inst;
    free(memory);
}

/* A pendulum's start values. */
typedef struct {
    double theta0, omega0, L, g;
} Start;

typedef void (*CoreLog)(const Instance *inst, Status status, const char *category, const char *message);

/* Sets up *inst as an instance of interface `type` named `name`, logging through `log`:
 * 0, or -1 when out of memory. */
static inline int core_instance(Instance *inst, const char *name, CoreLog log, InterfaceType type)
{
    memset(inst, 0, sizeof *inst);
    inst->host.log = log;
    inst->host.allocate = host_allocate;
    inst->host.release = host_release;
    return instance_setup(inst, name, type, 2, 0);
}

/* Sets up *inst as a Co-Simulation instance named `name`, logging through `log`, with
 * certificate_off (instance.h), and initializes it at startTime t0 with the start values, the
 * solver and the tolerance. 0, or -1 (the instance released) when a call refused. */
static inline int core_start(Instance *inst, const char *name, CoreLog log, int certificate_off, const Start *s,
                             int solver, double tol, double t0)
{
    const ValueReference vrs[] = {VR_L, VR_G, VR_THETA, VR_OMEGA};
    const double values[] = {s->L, s->g, s->theta0, s->omega0};
    if (core_instance(inst, name, log, INTERFACE_CO_SIMULATION) != 0) {
        return -1;
    }
    inst->certificate_off = certificate_off;
    if (instance_setup_experiment(inst, "setup", 1, tol, t0, 0, 0.0) != STATUS_OK ||
        instance_enter_initialization(inst, "enter") != STATUS_OK ||
        instance_set_reals(inst, "set", vrs, 4, values) != STATUS_OK ||
        instance_set_integer(inst, "set", VR_SOLVER, solver) != STATUS_OK ||
        instance_exit_initialization(inst, "exit") != STATUS_OK) {
        instance_release(inst);
        return -1;
    }
    return 0;
}

#endif
