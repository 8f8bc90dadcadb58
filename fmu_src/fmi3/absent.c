/* fmi3/absent.c: the FMI 3.0 functions of features this model does not have (clocks,
 * Scheduled Execution, Configuration Mode, run-time variable dependencies, discrete-state
 * evaluation): each is refused with its reason, as the capability flags declare; and the
 * Get/Set of the variable types no FMU of the project has. */
#include "layer.h"

static fmi3Status absent(fmi3Instance instance, const char *function, const char *reason) {
    if (!instance_call_allowed(instance, function, CALL_NOT_PROVIDED)) {
        return fmi3Error;
    }
    return (fmi3Status)instance_fail(instance, function, "%s", reason);
}

#define NO_CLOCKS "the model has no clocks"

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference valueReference,
                                               size_t *nDependencies) {
    (void)valueReference, (void)nDependencies;
    return absent(instance, "fmi3GetNumberOfVariableDependencies", "not provided: read the ModelStructure");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[], fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[], fmi3DependencyKind dependencyKinds[],
                                       size_t nDependencies) {
    (void)dependent, (void)elementIndicesOfDependent, (void)independents, (void)elementIndicesOfIndependents;
    (void)dependencyKinds, (void)nDependencies;
    return absent(instance, "fmi3GetVariableDependencies", "not provided: read the ModelStructure");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
    return absent(instance, "fmi3EnterConfigurationMode", "the model has no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
    return absent(instance, "fmi3ExitConfigurationMode", "the model has no structural parameters");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, fmi3Float64 intervals[], fmi3IntervalQualifier qualifiers[]) {
    (void)valueReferences, (void)nValueReferences, (void)intervals, (void)qualifiers;
    return absent(instance, "fmi3GetIntervalDecimal", NO_CLOCKS);
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[]) {
    (void)valueReferences, (void)nValueReferences, (void)counters, (void)resolutions, (void)qualifiers;
    return absent(instance, "fmi3GetIntervalFraction", NO_CLOCKS);
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, fmi3Float64 shifts[]) {
    (void)valueReferences, (void)nValueReferences, (void)shifts;
    return absent(instance, "fmi3GetShiftDecimal", NO_CLOCKS);
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, fmi3UInt64 counters[], fmi3UInt64 resolutions[]) {
    (void)valueReferences, (void)nValueReferences, (void)counters, (void)resolutions;
    return absent(instance, "fmi3GetShiftFraction", NO_CLOCKS);
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, const fmi3Float64 intervals[]) {
    (void)valueReferences, (void)nValueReferences, (void)intervals;
    return absent(instance, "fmi3SetIntervalDecimal", NO_CLOCKS);
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, const fmi3UInt64 counters[],
                                   const fmi3UInt64 resolutions[]) {
    (void)valueReferences, (void)nValueReferences, (void)counters, (void)resolutions;
    return absent(instance, "fmi3SetIntervalFraction", NO_CLOCKS);
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, const fmi3Float64 shifts[]) {
    (void)valueReferences, (void)nValueReferences, (void)shifts;
    return absent(instance, "fmi3SetShiftDecimal", NO_CLOCKS);
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, const fmi3UInt64 counters[], const fmi3UInt64 resolutions[]) {
    (void)valueReferences, (void)nValueReferences, (void)counters, (void)resolutions;
    return absent(instance, "fmi3SetShiftFraction", NO_CLOCKS);
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
    return absent(instance, "fmi3EvaluateDiscreteStates", "the model has no discrete states "
                  "(providesEvaluateDiscreteStates is false)");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime) {
    (void)clockReference, (void)activationTime;
    return absent(instance, "fmi3ActivateModelPartition", "the FMU has no Scheduled Execution interface");
}

/* --- variables of the types no FMU of the project has (Pendulum, PendulumBody and
 * PendulumGravity link this file): any value reference is unknown --------------------------- */

fmi3Status fmi3GetFloat32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float32 values[],
                          size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetFloat32", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetFloat32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float32 values[], size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetFloat32", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int8 values[],
                       size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetInt8", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int8 values[],
                       size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetInt8", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetUInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt8 values[],
                        size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetUInt8", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetUInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt8 values[],
                        size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetUInt8", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int16 values[],
                        size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetInt16", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int16 values[],
                        size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetInt16", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetUInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt16 values[],
                         size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetUInt16", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetUInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt16 values[],
                         size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetUInt16", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetUInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt32 values[],
                         size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetUInt32", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetUInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt32 values[],
                         size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetUInt32", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetUInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt64 values[],
                         size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetUInt64", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetUInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt64 values[],
                         size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetUInt64", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Boolean values[],
                          size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetBoolean", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Boolean values[], size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetBoolean", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3String values[],
                         size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetString", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3String values[],
                         size_t nValues) {
    (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetString", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, size_t valueSizes[],
                         fmi3Binary values[], size_t nValues) {
    (void)valueSizes, (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3GetBinary", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const size_t valueSizes[],
                         const fmi3Binary values[], size_t nValues) {
    (void)valueSizes, (void)nValues;
    return (fmi3Status)instance_no_variables(instance, "fmi3SetBinary", CALL_SET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Clock values[]) {
    return (fmi3Status)instance_no_variables(instance, "fmi3GetClock", CALL_GET_VARIABLES, vr, nvr, values);
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Clock values[]) {
    return (fmi3Status)instance_no_variables(instance, "fmi3SetClock", CALL_SET_VARIABLES, vr, nvr, values);
}
