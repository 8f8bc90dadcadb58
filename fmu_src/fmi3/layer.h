/* fmi3/layer.h: the FMI 3.0 instance, the shared one (instance.h) plus the host's logger,
 * and the instantiation shared by Model Exchange and Co-Simulation. */
#ifndef PENDULUM_FMI3_LAYER_H
#define PENDULUM_FMI3_LAYER_H

#include "fmi3_api.h"
#include "instance.h"

typedef struct {
    Instance core; /* first: an fmi3Instance is also an Instance */
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log_message;
} Fmi3Instance;

/* Checks the name and the token, allocates and sets up an instance of interface `type`;
 * NULL (with the reason logged when there is a logger) if refused. */
fmi3Instance fmi3_instantiate(const char *function, fmi3String instanceName, fmi3String instantiationToken,
                              InterfaceType type, fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                              fmi3LogMessageCallback logMessage);

#endif
