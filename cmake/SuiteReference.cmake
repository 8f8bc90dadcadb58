# The suite's validation experiments in each FMU, as FMI-LS-REF related files beside the default
# experiment (cmake/ReferenceResult.cmake includes this file):
#   extra/org.fmi-standard.fmi-ls-ref/PendulumSuite.exp          every case of the FMU's FMI version in
#                                                                 the ma-hs-experiments format (role
#                                                                 experiment/validation, after the default's)
#   extra/org.fmi-standard.fmi-ls-ref/suite/<case>_ref.csv        each case's exact solution (role result)
# The cases come from python/pendulum_fmu/suite/cases.csv, the one list the Python registry
# (pendulum-fmu suite) reads too; this file needs no Python. Each FMU's manifest, the default's
# entries and the suite's, is written to build/reference/suite-fmi<N>/ and replaces the shared one
# when the files are copied into the FMU (add_reference_result).
set(SUITE_CASES_FILE ${CMAKE_CURRENT_SOURCE_DIR}/python/pendulum_fmu/suite/cases.csv)
set(SUITE_MAX_ROWS 200)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${SUITE_CASES_FILE})
file(STRINGS ${SUITE_CASES_FILE} suite_lines ENCODING UTF-8)
set(suite_fields name fmi interface theta omega L g startTime stopTime interval tolerance catches)
set(SUITE_VERSION "")
set(SUITE_HTML_ROWS "")
foreach(major 2 3)
  set(suite_experiments_${major} "")
  set(suite_outputs_${major} "")
endforeach()
foreach(line IN LISTS suite_lines)
  if(line MATCHES "^#" OR line STREQUAL "" OR line MATCHES "^name;")
    continue()
  endif()
  if(line MATCHES "^version;(.+)$")
    set(SUITE_VERSION ${CMAKE_MATCH_1})
    continue()
  endif()
  string(REPLACE ";" "\;" escaped "${line}")  # keep the line one item while it is split below
  string(REPLACE "\;" ";" fields "${escaped}")
  list(LENGTH fields count)
  if(NOT count EQUAL 12)
    message(FATAL_ERROR "${SUITE_CASES_FILE}: '${line}' has ${count} fields, not 12")
  endif()
  foreach(index RANGE 11)
    list(GET suite_fields ${index} key)
    list(GET fields ${index} case_${key})
  endforeach()
  string(SUBSTRING "${case_fmi}" 0 1 major)
  set(interface_words "Co-Simulation")
  if(case_interface STREQUAL "me")
    set(interface_words "Model Exchange")
  endif()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/reference/suite-fmi${major})
  string(APPEND suite_experiments_${major}
    "    <Experiment name=\"${case_name}\"\n"
    "        description=\"${interface_words}: ${case_catches}\"\n"
    "        startTime=\"${case_startTime}\" stopTime=\"${case_stopTime}\" stepSize=\"${case_interval}\" "
    "tolerance=\"${case_tolerance}\">\n"
    "        <Parameters>\n"
    "            <Parameter name=\"theta\" value=\"${case_theta}\"/>\n"
    "            <Parameter name=\"omega\" value=\"${case_omega}\"/>\n"
    "            <Parameter name=\"L\" value=\"${case_L}\"/>\n"
    "            <Parameter name=\"g\" value=\"${case_g}\"/>\n"
    "        </Parameters>\n"
    "        <References source=\"suite/${case_name}_ref.csv\"/>\n"
    "    </Experiment>\n")
  string(APPEND SUITE_HTML_ROWS "<tr><td><code>${case_name}</code></td><td>${case_fmi}</td><td>${interface_words}</td>"
    "<td>${case_catches}</td></tr>\n")
  add_custom_command(
    OUTPUT ${dir}/suite/${case_name}_ref.csv
    COMMAND ${CMAKE_COMMAND} -E make_directory ${dir}/suite
    COMMAND write_reference_result ${dir}/suite/${case_name}_ref.csv ${case_startTime} ${case_stopTime}
            ${case_interval} ${case_theta} ${case_omega} ${case_L} ${case_g} ${SUITE_MAX_ROWS}
    DEPENDS write_reference_result ${SUITE_CASES_FILE}
    COMMENT "Writing the reference result of the validation experiment ${case_name}"
    VERBATIM)
  list(APPEND suite_outputs_${major} ${dir}/suite/${case_name}_ref.csv)
endforeach()
if(SUITE_VERSION STREQUAL "")
  message(FATAL_ERROR "${SUITE_CASES_FILE}: no 'version;N' line")
endif()

foreach(major 2 3)
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/reference/suite-fmi${major})
  set(SUITE_DIR_${major} ${dir})
  file(WRITE ${dir}/PendulumSuite.exp.new
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<Experiments name=\"PendulumSuite\"\n"
    "    description=\"pendulum-suite-${SUITE_VERSION}, FMI ${major}.0: the hard cases of Pendulum.fmu, each "
    "stressing one thing importers get wrong, with the exact solution as reference; "
    "'pendulum-fmu suite run' runs and judges them\">\n"
    "${suite_experiments_${major}}"
    "</Experiments>\n")
  configure_file(${dir}/PendulumSuite.exp.new ${dir}/PendulumSuite.exp COPYONLY)
  file(REMOVE ${dir}/PendulumSuite.exp.new)
  add_custom_command(
    OUTPUT ${dir}/fmi-ls-manifest.xml
    COMMAND ${CMAKE_COMMAND} -DREFERENCE_DIR=${REFERENCE_DIR} -DREFERENCE_HTML=${REFERENCE_HTML}
            -DLS_VERSION=${REFERENCE_LS_VERSION} -DSTART=${REFERENCE_START} -DSTOP=${REFERENCE_STOP}
            -DINTERVALS=${REFERENCE_INTERVALS} -DCS_DEVIATION=${REFERENCE_CS_DEVIATION}
            -DSUITE_DIR=${dir} -DSUITE_VERSION=${SUITE_VERSION}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cmake/ReferenceManifest.cmake
    DEPENDS ${REFERENCE_DIR}/Pendulum_ref.csv ${REFERENCE_DIR}/Pendulum.exp ${REFERENCE_HTML}
            ${dir}/PendulumSuite.exp ${suite_outputs_${major}}
            ${CMAKE_CURRENT_SOURCE_DIR}/cmake/ReferenceManifest.cmake
    COMMENT "Writing the FMI ${major}.0 FMU's FMI-LS-REF manifest with the suite's files"
    VERBATIM)
  set(SUITE_FILES_${major} ${dir}/fmi-ls-manifest.xml ${dir}/PendulumSuite.exp ${suite_outputs_${major}})
endforeach()
