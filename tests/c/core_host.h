/* core_host.h: the memory half of an InstanceHost for C tests that link the model core
 * directly (no FMI layer): zeroed memory from calloc, returned with free. */
#ifndef PENDULUM_TESTS_CORE_HOST_H
#define PENDULUM_TESTS_CORE_HOST_H

#include <stdlib.h>

#include "instance.h"

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

#endif
