# The reference result of the default experiment, the exact solution, in both FMUs as the
# layered standard for reference results, FMI-LS-REF 1.0.0-beta.1, lays it out:
#   extra/org.fmi-standard.fmi-ls-ref/fmi-ls-manifest.xml   names each related file, its role and its
#                                                            SHA3-256 digest (cmake/ReferenceManifest.cmake)
#   extra/org.fmi-standard.fmi-ls-ref/Pendulum_ref.csv       time and outputs on the experiment's grid (role result)
#   extra/org.fmi-standard.fmi-ls-ref/Pendulum.exp           the default experiment in the
#                                                            ma-hs-experiments format (role experiment/validation)
#   documentation/fmi-ls-ref.html                            what the files are and what to expect of a run
# Every number comes from modelDescription.xml's DefaultExperiment (the attributes in any
# order); the CSV is written at build time by fmu_src/libs/reference/write_reference_result.c
# from the FMU's exact port and the start values. The files are added to each packed FMU by re-packing its
# folder (cmake/pack_fmu.cmake), so the FMU packing rules themselves stay as they are.
# Included after the FMUs are defined.
string(REGEX MATCH "<DefaultExperiment[^>]*>" default_experiment "${md_text}")
foreach(attribute startTime stopTime tolerance stepSize)
  if(NOT default_experiment MATCHES "[ \t\r\n]${attribute}=\"([^\"]+)\"")
    message(FATAL_ERROR "modelDescription.xml: the DefaultExperiment has no ${attribute}")
  endif()
  set(REFERENCE_${attribute} ${CMAKE_MATCH_1})
endforeach()
set(REFERENCE_START ${REFERENCE_startTime})
set(REFERENCE_STOP ${REFERENCE_stopTime})
# The reference on the experiment's output grid: (stopTime - startTime) / stepSize intervals
# (20 / 0.03125; tests/fmu/test_reference_result.py checks the CSV's times against the experiment)
set(REFERENCE_INTERVALS 640)
set(REFERENCE_LS_VERSION 1.0.0-beta.1)
set(REFERENCE_DIR ${CMAKE_CURRENT_BINARY_DIR}/reference/org.fmi-standard.fmi-ls-ref)
set(REFERENCE_HTML ${CMAKE_CURRENT_BINARY_DIR}/reference/fmi-ls-ref.html)

add_executable(write_reference_result ${LIBS_DIR}/reference/write_reference_result.c)
target_include_directories(write_reference_result PRIVATE ${FMU_INCLUDE_DIRS})
target_compile_options(write_reference_result PRIVATE ${WARNING_FLAGS})
target_link_libraries(write_reference_result PRIVATE pendulum_core)

set(REFERENCE_CS_DEVIATION 1e-6)
include(${CMAKE_CURRENT_SOURCE_DIR}/cmake/SuiteReference.cmake)  # the suite's validation experiments
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/reference/Pendulum.exp.new
  "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
  "<Experiments name=\"Pendulum\"\n"
  "    description=\"The default experiment of Pendulum.fmu, with the exact solution as its reference\">\n"
  "    <Experiment name=\"DefaultExperiment\"\n"
  "        description=\"The model description's DefaultExperiment from its start values; "
  "a Co-Simulation run at this tolerance stays within ${REFERENCE_CS_DEVIATION} rad of the reference\"\n"
  "        startTime=\"${REFERENCE_startTime}\" stopTime=\"${REFERENCE_stopTime}\" "
  "stepSize=\"${REFERENCE_stepSize}\" tolerance=\"${REFERENCE_tolerance}\">\n"
  "        <References source=\"Pendulum_ref.csv\"/>\n"
  "    </Experiment>\n"
  "</Experiments>\n")
configure_file(${CMAKE_CURRENT_BINARY_DIR}/reference/Pendulum.exp.new ${REFERENCE_DIR}/Pendulum.exp COPYONLY)
configure_file(${PENDULUM_DOC_DIR}/fmi-ls-ref.html.in ${REFERENCE_HTML} @ONLY)
add_custom_command(
  OUTPUT ${REFERENCE_DIR}/Pendulum_ref.csv
  COMMAND write_reference_result ${REFERENCE_DIR}/Pendulum_ref.csv ${REFERENCE_START} ${REFERENCE_STOP}
          ${REFERENCE_INTERVALS}
  DEPENDS write_reference_result
  COMMENT "Writing the reference result of the default experiment"
  VERBATIM)
add_custom_command(
  OUTPUT ${REFERENCE_DIR}/fmi-ls-manifest.xml
  COMMAND ${CMAKE_COMMAND} -DREFERENCE_DIR=${REFERENCE_DIR} -DREFERENCE_HTML=${REFERENCE_HTML}
          -DLS_VERSION=${REFERENCE_LS_VERSION} -DSTART=${REFERENCE_START} -DSTOP=${REFERENCE_STOP}
          -DINTERVALS=${REFERENCE_INTERVALS} -DCS_DEVIATION=${REFERENCE_CS_DEVIATION}
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cmake/ReferenceManifest.cmake
  DEPENDS ${REFERENCE_DIR}/Pendulum_ref.csv ${REFERENCE_DIR}/Pendulum.exp ${REFERENCE_HTML}
          ${CMAKE_CURRENT_SOURCE_DIR}/cmake/ReferenceManifest.cmake
  COMMENT "Writing the FMI-LS-REF manifest with the files' SHA3-256 digests"
  VERBATIM)

# Adds extra/ and documentation/fmi-ls-ref.html to a packed FMU: copies them into its folder
# and zips it again; then the suite's files of the FMU's FMI version (major: 2 or 3), whose
# manifest replaces the shared one. target: the new target; fmu_target: the target that packs fmu_file. The
# dependency between the two makes fmu_target's packing run first and once (with only a file
# dependency, a parallel make would run the packing rule in both targets at the same time).
function(add_reference_result target fmu_target fmu_dir fmu_file major)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/reference/${target}.stamp)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${REFERENCE_DIR} ${fmu_dir}/extra/org.fmi-standard.fmi-ls-ref
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${SUITE_DIR_${major}} ${fmu_dir}/extra/org.fmi-standard.fmi-ls-ref
    COMMAND ${CMAKE_COMMAND} -E copy ${REFERENCE_HTML} ${fmu_dir}/documentation/fmi-ls-ref.html
    COMMAND ${CMAKE_COMMAND} -DFMU_DIR=${fmu_dir} -DFMU_FILE=${fmu_file}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cmake/pack_fmu.cmake
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${fmu_file} ${REFERENCE_DIR}/Pendulum_ref.csv ${REFERENCE_DIR}/fmi-ls-manifest.xml
            ${REFERENCE_DIR}/Pendulum.exp ${REFERENCE_HTML} ${CMAKE_CURRENT_SOURCE_DIR}/cmake/pack_fmu.cmake
            ${SUITE_FILES_${major}}
    COMMENT "Adding the reference result to ${fmu_file}"
    VERBATIM)
  add_custom_target(${target} ALL DEPENDS ${stamp})
  add_dependencies(${target} ${fmu_target})
endfunction()

add_reference_result(fmu_reference fmu ${FMU_DIR} ${FMU_FILE} 2)
if(TARGET fmu3)
  add_reference_result(fmu3_reference fmu3 ${FMI3_FMU_DIR} ${FMI3_FMU_FILE} 3)
endif()
