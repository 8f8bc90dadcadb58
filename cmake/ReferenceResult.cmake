# The reference result of the default experiment, the exact solution, in both FMUs as the
# layered standard for reference results lays it out (as the Modelica Reference FMUs do):
#   extra/org.fmi-standard.fmi-ls-ref/fmi-ls-manifest.xml   names the file and its role
#   extra/org.fmi-standard.fmi-ls-ref/Pendulum_ref.csv       time and outputs, 1000 intervals
# Generated at build time by reference/write_reference_result.c from the FMU's exact port and
# the start values; added to each packed FMU by re-packing its folder (cmake/pack_fmu.cmake),
# so the FMU packing rules themselves stay as they are. Included after the FMUs are defined.
string(REGEX MATCH "<DefaultExperiment startTime=\"([^\"]+)\" stopTime=\"([^\"]+)\"" _ "${md_text}")
set(REFERENCE_START ${CMAKE_MATCH_1})
set(REFERENCE_STOP ${CMAKE_MATCH_2})
set(REFERENCE_INTERVALS 1000)
set(REFERENCE_DIR ${CMAKE_CURRENT_BINARY_DIR}/reference/org.fmi-standard.fmi-ls-ref)

add_executable(write_reference_result reference/write_reference_result.c)
target_include_directories(write_reference_result PRIVATE ${FMU_INCLUDE_DIRS})
target_compile_options(write_reference_result PRIVATE ${WARNING_FLAGS})
target_link_libraries(write_reference_result PRIVATE pendulum_core)

file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/reference/fmi-ls-manifest.xml.new
  "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
  "<fmiReferences\n"
  "    xmlns:fmi-ls=\"http://fmi-standard.org/fmi-ls-manifest\"\n"
  "    fmi-ls:fmi-ls-name=\"org.fmi-standard.fmi-ls-ref\"\n"
  "    fmi-ls:fmi-ls-version=\"1.0.0-alpha.1\"\n"
  "    fmi-ls:fmi-ls-description=\"Reference result of the default experiment\">\n"
  "    <Related type=\"text/csv\" source=\"Pendulum_ref.csv\" role=\"result\"\n"
  "             description=\"Exact solution (Jacobi elliptic functions) from the start values, "
  "t = ${REFERENCE_START} .. ${REFERENCE_STOP} s in ${REFERENCE_INTERVALS} intervals: what the outputs are "
  "without solver error; the Co-Simulation run at the default tolerance stays within 1e-6 rad of it\"/>\n"
  "</fmiReferences>\n")
configure_file(${CMAKE_CURRENT_BINARY_DIR}/reference/fmi-ls-manifest.xml.new ${REFERENCE_DIR}/fmi-ls-manifest.xml
               COPYONLY)
add_custom_command(
  OUTPUT ${REFERENCE_DIR}/Pendulum_ref.csv
  COMMAND write_reference_result ${REFERENCE_DIR}/Pendulum_ref.csv ${REFERENCE_START} ${REFERENCE_STOP}
          ${REFERENCE_INTERVALS}
  DEPENDS write_reference_result
  COMMENT "Writing the reference result of the default experiment"
  VERBATIM)

# Adds extra/ to a packed FMU: copies the reference folder into its folder and zips it again.
# target: the new target; fmu_target: the target that packs fmu_file. The dependency between the
# two makes fmu_target's packing run first and once (with only a file dependency, a parallel
# make would run the packing rule in both targets at the same time).
function(add_reference_result target fmu_target fmu_dir fmu_file)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/reference/${target}.stamp)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${REFERENCE_DIR} ${fmu_dir}/extra/org.fmi-standard.fmi-ls-ref
    COMMAND ${CMAKE_COMMAND} -DFMU_DIR=${fmu_dir} -DFMU_FILE=${fmu_file}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cmake/pack_fmu.cmake
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${fmu_file} ${REFERENCE_DIR}/Pendulum_ref.csv ${REFERENCE_DIR}/fmi-ls-manifest.xml
            ${CMAKE_CURRENT_SOURCE_DIR}/cmake/pack_fmu.cmake
    COMMENT "Adding the reference result to ${fmu_file}"
    VERBATIM)
  add_custom_target(${target} ALL DEPENDS ${stamp})
  add_dependencies(${target} ${fmu_target})
endfunction()

add_reference_result(fmu_reference fmu ${FMU_DIR} ${FMU_FILE})
if(TARGET fmu3)
  add_reference_result(fmu3_reference fmu3 ${FMI3_FMU_DIR} ${FMI3_FMU_FILE})
endif()
