/* fmu_state_calls.h: the six FMU-state functions of an FMI layer, defined once for both
 * versions: each forwards to instance/state.c with its own name for the messages. FMI 2.0
 * and 3.0 differ only in names and types (fmi2GetFMUstate / fmi3GetFMUState, ...). */
#ifndef PENDULUM_FMU_STATE_CALLS_H
#define PENDULUM_FMU_STATE_CALLS_H

#include "instance.h"

#define DEFINE_FMU_STATE_CALLS(StatusT, InstanceT, StateT, ByteT, Get, Set, Free, Size, Serialize, Deserialize) \
    StatusT Get(InstanceT instance, StateT *state) {                                                      \
        return (StatusT)instance_get_state(instance, #Get, state);                                        \
    }                                                                                                     \
    StatusT Set(InstanceT instance, StateT state) {                                                       \
        return (StatusT)instance_set_state(instance, #Set, state);                                        \
    }                                                                                                     \
    StatusT Free(InstanceT instance, StateT *state) {                                                     \
        return (StatusT)instance_free_state(instance, #Free, state);                                      \
    }                                                                                                     \
    StatusT Size(InstanceT instance, StateT state, size_t *size) {                                        \
        return (StatusT)instance_serialized_state_size(instance, #Size, state, size);                     \
    }                                                                                                     \
    StatusT Serialize(InstanceT instance, StateT state, ByteT bytes[], size_t size) {                     \
        return (StatusT)instance_serialize_state(instance, #Serialize, state, (char *)bytes, size);       \
    }                                                                                                     \
    StatusT Deserialize(InstanceT instance, const ByteT bytes[], size_t size, StateT *state) {            \
        return (StatusT)instance_deserialize_state(instance, #Deserialize, (const char *)bytes, size, state); \
    }

#endif
