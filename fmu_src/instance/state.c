/* instance/state.c: FMU states for rollback (FMI 2.0 section 2.1.8, FMI 3.0 section 2.2.6.4),
 * shared by both versions and by every FMU built on the instance. A state is a copy of the
 * instance's ModelData (plain data) followed by the model's extra bytes (StateModel in
 * instance.h: none for Pendulum.fmu, the input polynomial for the split FMUs), one contiguous
 * payload; its serialized form is a header followed by those bytes. The header carries the
 * model's magic text, a format version, the payload size and an FNV-1a checksum, so a blob of
 * another model or build, a truncated or a corrupted one is refused. Byte order and layout are
 * the platform's: a blob moves between processes and instances of the same binary, not
 * between platforms.
 *
 * Every state an instance hands out is a node of its registry (a list through the nodes
 * themselves, so the registry costs no allocation of its own, and none in the step loop):
 * FreeFMUstate, and GetFMUstate / DeSerializeFMUstate when asked to overwrite a state, take
 * only a pointer found in it, compared by address before it is ever dereferenced. A freed
 * state, another instance's, or the state itself passed where its address belongs (as one
 * importer did) is refused with an error naming the pointer, and never freed or written. */
#include <stdint.h>
#include <string.h>

#include "instance.h"

#define STATE_FORMAT_VERSION 4u /* 2: the solver state gained fields; 3: interface, hard-case
                                   flag, exact solution from g and L; 4: the certificate's last
                                   logged departure, the solver's omega scale */

typedef struct {
    char magic[8];
    uint32_t format_version;
    uint32_t payload_size;
    uint64_t checksum;
} StateHeader;


/* FNV-1a, 64 bit: offset basis 14695981039346656037, prime 1099511628211. */
static uint64_t fnv1a64(const unsigned char *bytes, size_t size) {
    uint64_t hash = 14695981039346656037u;
    size_t i;
    for (i = 0; i < size; i++) {
        hash ^= bytes[i];
        hash *= 1099511628211u;
    }
    return hash;
}

struct StateNode {
    StateNode *next;
    ModelData data; /* what the importer holds: the address of this member; the model's extra
                       bytes follow it (a node is allocated with room for them) */
};

static const char *pendulum_check(const Instance *inst, const ModelData *data, const void *extra) {
    (void)extra;
    return model_check_state(data, inst->type);
}

/* Pendulum.fmu's states: ModelData alone. */
static const StateModel PENDULUM_STATE = {"PNDLSTAT", 0, 0, pendulum_check};

static const StateModel *model_of(const Instance *inst) {
    return inst->state_model != NULL ? inst->state_model : &PENDULUM_STATE;
}

static size_t payload_size(const Instance *inst) {
    return sizeof(ModelData) + model_of(inst)->extra_size;
}

/* Where the model's extra bytes lie in the instance, and in a state after its ModelData. */
static unsigned char *instance_extra(Instance *inst) {
    return (unsigned char *)inst + model_of(inst)->extra_offset;
}

static const unsigned char *state_extra(const void *state) {
    return (const unsigned char *)state + sizeof(ModelData);
}

/* The live node whose data is at `state`, and the link that points to it; NULL if none. */
static StateNode *find_live(Instance *inst, const void *state, StateNode ***link) {
    StateNode **at;
    for (at = &inst->states; *at != NULL; at = &(*at)->next) {
        if ((const void *)&(*at)->data == state) {
            if (link != NULL) {
                *link = at;
            }
            return *at;
        }
    }
    return NULL;
}

static Status not_live(Instance *inst, const char *function, const void *state) {
    return instance_fail(inst, function, "%p is not an FMU state of this instance that is still live (freed "
                         "already, another instance's, or not a state: pass the address of the state variable); "
                         "it is left alone", state);
}

/* The state to write: *state itself when it is a live state of this instance (FMI 2.0 2.1.8:
 * a non-NULL *state is a state to be overwritten), a new registered one when it is NULL;
 * NULL (with the error logged) otherwise. */
static ModelData *state_to_write(Instance *inst, const char *function, void *const *state) {
    StateNode *node;
    if (*state != NULL) {
        node = find_live(inst, *state, NULL);
        if (node == NULL) {
            not_live(inst, function, *state);
            return NULL;
        }
        return &node->data;
    }
    node = inst->host.allocate(inst, sizeof *node + model_of(inst)->extra_size);
    if (node == NULL) {
        instance_fail(inst, function, "out of memory");
        return NULL;
    }
    node->next = inst->states;
    inst->states = node;
    return &node->data;
}

void instance_release_states(Instance *inst) {
    while (inst->states != NULL) {
        StateNode *node = inst->states;
        inst->states = node->next;
        inst->host.release(inst, node);
    }
}

Status instance_get_state(Instance *inst, const char *function, void **state) {
    ModelData *copy;
    if (!instance_call_allowed(inst, function, CALL_GET_FMU_STATE)) {
        return STATUS_ERROR;
    }
    if (state == NULL) {
        return instance_fail(inst, function, "state is NULL");
    }
    copy = state_to_write(inst, function, state);
    if (copy == NULL) {
        return STATUS_ERROR;
    }
    memcpy(copy, &inst->data, sizeof *copy); /* bytewise, padding included: the checksum sees it */
    memcpy((unsigned char *)copy + sizeof *copy, instance_extra(inst), model_of(inst)->extra_size);
    *state = copy;
    return STATUS_OK;
}

Status instance_set_state(Instance *inst, const char *function, const void *state) {
    const char *problem;
    if (!instance_call_allowed(inst, function, CALL_SET_FMU_STATE)) {
        return STATUS_ERROR;
    }
    if (state == NULL) {
        return instance_fail(inst, function, "state is NULL");
    }
    /* a state is memory handed back by the master: checked like a deserialized one */
    problem = model_of(inst)->check(inst, (const ModelData *)state, state_extra(state));
    if (problem != NULL) {
        return instance_fail(inst, function, "the state is refused: %s", problem);
    }
    memcpy(&inst->data, state, sizeof inst->data);
    memcpy(instance_extra(inst), state_extra(state), model_of(inst)->extra_size);
    model_exact_forget(&inst->exact_now); /* not part of a state: evaluated again when needed */
    return STATUS_OK;
}

Status instance_free_state(Instance *inst, const char *function, void **state) {
    if (!instance_call_allowed(inst, function, CALL_FREE_FMU_STATE)) {
        return STATUS_ERROR;
    }
    if (state == NULL) {
        return instance_fail(inst, function, "state is NULL");
    }
    if (*state != NULL) {
        StateNode **link = NULL;
        StateNode *node = find_live(inst, *state, &link);
        if (node == NULL) {
            return not_live(inst, function, *state);
        }
        *link = node->next;
        inst->host.release(inst, node);
        *state = NULL;
    }
    return STATUS_OK;
}

Status instance_serialized_state_size(Instance *inst, const char *function, const void *state, size_t *size) {
    if (!instance_call_allowed(inst, function, CALL_SERIALIZED_FMU_STATE_SIZE)) {
        return STATUS_ERROR;
    }
    if (state == NULL || size == NULL) {
        return instance_fail(inst, function, "state or size is NULL");
    }
    *size = sizeof(StateHeader) + payload_size(inst);
    return STATUS_OK;
}

Status instance_serialize_state(Instance *inst, const char *function, const void *state, char bytes[], size_t size) {
    StateHeader header;
    if (!instance_call_allowed(inst, function, CALL_SERIALIZE_FMU_STATE)) {
        return STATUS_ERROR;
    }
    if (state == NULL || bytes == NULL) {
        return instance_fail(inst, function, "state or bytes is NULL");
    }
    if (size != sizeof header + payload_size(inst)) {
        return instance_fail(inst, function, "size is %zu, the serialized state size is %zu",
                             size, sizeof header + payload_size(inst));
    }
    memcpy(header.magic, model_of(inst)->magic, sizeof header.magic);
    header.format_version = STATE_FORMAT_VERSION;
    header.payload_size = (uint32_t)payload_size(inst);
    header.checksum = fnv1a64((const unsigned char *)state, payload_size(inst));
    memcpy(bytes, &header, sizeof header);
    memcpy(bytes + sizeof header, state, payload_size(inst));
    return STATUS_OK;
}

Status instance_deserialize_state(Instance *inst, const char *function, const char bytes[], size_t size,
                                  void **state) {
    const StateModel *model = model_of(inst);
    StateHeader header;
    ModelData payload;
    double extra[STATE_EXTRA_MAX / sizeof(double)]; /* aligned for any model's extra bytes */
    ModelData *copy;
    const char *problem;
    if (!instance_call_allowed(inst, function, CALL_DESERIALIZE_FMU_STATE)) {
        return STATUS_ERROR;
    }
    if (bytes == NULL || state == NULL) {
        return instance_fail(inst, function, "bytes or state is NULL");
    }
    if (size != sizeof header + payload_size(inst)) {
        return instance_fail(inst, function, "the blob has %zu bytes, a state of this FMU has %zu", size,
                             sizeof header + payload_size(inst));
    }
    memcpy(&header, bytes, sizeof header);
    memcpy(&payload, bytes + sizeof header, sizeof payload);
    memcpy(extra, bytes + sizeof header + sizeof payload, model->extra_size);
    if (memcmp(header.magic, model->magic, sizeof header.magic) != 0) {
        char mark[sizeof header.magic + 1];
        size_t i;
        for (i = 0; i < sizeof header.magic; i++) { /* printable in the log, whatever the blob holds */
            mark[i] = header.magic[i] >= ' ' && header.magic[i] <= '~' ? header.magic[i] : '?';
        }
        mark[sizeof header.magic] = '\0';
        return instance_fail(inst, function, "the blob is not a state of this FMU (it is marked \"%s\", a state of "
                             "this FMU \"%.8s\")", mark, model->magic);
    }
    if (header.format_version != STATE_FORMAT_VERSION || header.payload_size != payload_size(inst)) {
        return instance_fail(inst, function, "the blob is not a state of this build of the FMU (format version %u, "
                             "payload %u bytes; this build's are %u and %zu)", (unsigned)header.format_version,
                             (unsigned)header.payload_size, STATE_FORMAT_VERSION, payload_size(inst));
    }
    if (header.checksum != fnv1a64((const unsigned char *)bytes + sizeof header, payload_size(inst))) {
        return instance_fail(inst, function, "the blob is corrupted (checksum or contents do not match)");
    }
    /* the checksum only catches accidents: a forged blob with a recomputed checksum is
     * parsed like any untrusted input, every field against its range */
    problem = model->check(inst, &payload, extra);
    if (problem != NULL) {
        return instance_fail(inst, function, "the blob is refused: %s", problem);
    }
    copy = state_to_write(inst, function, state);
    if (copy == NULL) {
        return STATUS_ERROR;
    }
    memcpy(copy, &payload, sizeof *copy);
    memcpy((unsigned char *)copy + sizeof *copy, extra, model->extra_size);
    *state = copy;
    return STATUS_OK;
}
