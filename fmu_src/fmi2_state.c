/* fmi2_state.c: FMU states for rollback (FMI 2.0 section 2.1.8). A state is a copy of the
 * instance's ModelData (plain data); its serialized form is a header followed by those
 * bytes. The header carries a magic text, a format version, the payload size and an
 * FNV-1a checksum, so a blob from another build, a truncated or a corrupted one is refused.
 * Byte order and layout are the platform's: a blob moves between processes and instances
 * of the same binary, not between platforms. */
#include <stdint.h>
#include <string.h>

#include "fmi2_instance.h"

#define STATE_MAGIC "PNDLSTAT"
#define STATE_FORMAT_VERSION 3u /* 2: the solver state gained fields; 3: interface, hard-case
                                   flag, exact solution from g and L */

typedef struct {
    char magic[8];
    uint32_t format_version;
    uint32_t payload_size;
    uint64_t checksum;
} StateHeader;

#define ANY_LIVE_MODE (MODE_INSTANTIATED | MODE_INITIALIZATION | MODE_EVENT | MODE_CONTINUOUS_TIME | \
                       MODE_STEP_COMPLETE | MODE_TERMINATED)

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

static ModelData *allocate_state(Instance *inst, const char *function) {
    ModelData *copy = inst->callbacks.allocateMemory(1, sizeof *copy);
    if (copy == NULL) {
        instance_fail(inst, function, "out of memory");
    }
    return copy;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state) {
    Instance *inst = c;
    ModelData *copy;
    if (!instance_allowed(inst, "fmi2GetFMUstate", ANY_LIVE_MODE)) {
        return fmi2Error;
    }
    if (state == NULL) {
        return instance_fail(inst, "fmi2GetFMUstate", "state is NULL");
    }
    /* 2.1.8: a non-NULL *state is a state of this FMU to be overwritten. */
    copy = *state != NULL ? (ModelData *)*state : allocate_state(inst, "fmi2GetFMUstate");
    if (copy == NULL) {
        return fmi2Error;
    }
    memcpy(copy, &inst->data, sizeof *copy); /* bytewise, padding included: the checksum sees it */
    *state = copy;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
    Instance *inst = c;
    const char *problem;
    if (!instance_allowed(inst, "fmi2SetFMUstate", ANY_LIVE_MODE | MODE_ERROR)) {
        return fmi2Error;
    }
    if (state == NULL) {
        return instance_fail(inst, "fmi2SetFMUstate", "state is NULL");
    }
    /* a state is memory handed back by the master: checked like a deserialized one */
    problem = model_check_state((const ModelData *)state, inst->type);
    if (problem != NULL) {
        return instance_fail(inst, "fmi2SetFMUstate", "the state is refused: %s", problem);
    }
    memcpy(&inst->data, state, sizeof inst->data);
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2FreeFMUstate", ANY_LIVE_MODE | MODE_ERROR)) {
        return fmi2Error;
    }
    if (state == NULL) {
        return instance_fail(inst, "fmi2FreeFMUstate", "state is NULL");
    }
    if (*state != NULL) {
        inst->callbacks.freeMemory(*state);
        *state = NULL;
    }
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t *size) {
    Instance *inst = c;
    if (!instance_allowed(inst, "fmi2SerializedFMUstateSize", ANY_LIVE_MODE | MODE_ERROR)) {
        return fmi2Error;
    }
    if (state == NULL || size == NULL) {
        return instance_fail(inst, "fmi2SerializedFMUstateSize", "state or size is NULL");
    }
    *size = sizeof(StateHeader) + sizeof(ModelData);
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
    Instance *inst = c;
    StateHeader header;
    if (!instance_allowed(inst, "fmi2SerializeFMUstate", ANY_LIVE_MODE | MODE_ERROR)) {
        return fmi2Error;
    }
    if (state == NULL || bytes == NULL) {
        return instance_fail(inst, "fmi2SerializeFMUstate", "state or bytes is NULL");
    }
    if (size != sizeof header + sizeof(ModelData)) {
        return instance_fail(inst, "fmi2SerializeFMUstate", "size is %zu, fmi2SerializedFMUstateSize gives %zu",
                             size, sizeof header + sizeof(ModelData));
    }
    memcpy(header.magic, STATE_MAGIC, sizeof header.magic);
    header.format_version = STATE_FORMAT_VERSION;
    header.payload_size = (uint32_t)sizeof(ModelData);
    header.checksum = fnv1a64((const unsigned char *)state, sizeof(ModelData));
    memcpy(bytes, &header, sizeof header);
    memcpy(bytes + sizeof header, state, sizeof(ModelData));
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate *state) {
    Instance *inst = c;
    StateHeader header;
    ModelData payload;
    ModelData *copy;
    const char *problem;
    const char *function = "fmi2DeSerializeFMUstate";
    if (!instance_allowed(inst, function, ANY_LIVE_MODE | MODE_ERROR)) {
        return fmi2Error;
    }
    if (bytes == NULL || state == NULL) {
        return instance_fail(inst, function, "bytes or state is NULL");
    }
    if (size != sizeof header + sizeof payload) {
        return instance_fail(inst, function, "the blob has %zu bytes, a state of this FMU has %zu", size,
                             sizeof header + sizeof payload);
    }
    memcpy(&header, bytes, sizeof header);
    memcpy(&payload, bytes + sizeof header, sizeof payload);
    if (memcmp(header.magic, STATE_MAGIC, sizeof header.magic) != 0 || header.format_version != STATE_FORMAT_VERSION ||
        header.payload_size != sizeof payload) {
        return instance_fail(inst, function, "the blob is not a state of this FMU (magic, version or size differ)");
    }
    if (header.checksum != fnv1a64((const unsigned char *)&payload, sizeof payload)) {
        return instance_fail(inst, function, "the blob is corrupted (checksum or contents do not match)");
    }
    /* the checksum only catches accidents: a forged blob with a recomputed checksum is
     * parsed like any untrusted input, every field against its range */
    problem = model_check_state(&payload, inst->type);
    if (problem != NULL) {
        return instance_fail(inst, function, "the blob is refused: %s", problem);
    }
    copy = *state != NULL ? (ModelData *)*state : allocate_state(inst, function);
    if (copy == NULL) {
        return fmi2Error;
    }
    memcpy(copy, &payload, sizeof *copy);
    *state = copy;
    return fmi2OK;
}
