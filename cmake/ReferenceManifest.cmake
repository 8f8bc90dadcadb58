# cmake -DREFERENCE_DIR=... -DREFERENCE_HTML=... -DLS_VERSION=... -DSTART=... -DSTOP=...
#       -DINTERVALS=... -DCS_DEVIATION=... [-DSUITE_DIR=... -DSUITE_VERSION=...] -P ReferenceManifest.cmake
# Writes REFERENCE_DIR/fmi-ls-manifest.xml, the FMI-LS-REF manifest, after the files it names
# exist: each <Related> carries the SHA3-256 digest of its file (the standard's checksum
# attribute, whose checksumType defaults to SHA3-256), so an importer can verify them.
# With SUITE_DIR, the manifest goes to SUITE_DIR instead and also names the suite's
# PendulumSuite.exp and suite/*_ref.csv there (cmake/SuiteReference.cmake), after the default's
# entries, so the first experiment/validation and result are still the default experiment's.
foreach(file Pendulum.exp Pendulum_ref.csv)
  if(NOT EXISTS ${REFERENCE_DIR}/${file})
    message(FATAL_ERROR "${REFERENCE_DIR}/${file} is missing: the manifest names it")
  endif()
endforeach()
file(SHA3_256 ${REFERENCE_DIR}/Pendulum.exp exp_sum)
file(SHA3_256 ${REFERENCE_DIR}/Pendulum_ref.csv csv_sum)
file(SHA3_256 ${REFERENCE_HTML} html_sum)
set(manifest_dir ${REFERENCE_DIR})
set(suite_entries "")
if(DEFINED SUITE_DIR)
  set(manifest_dir ${SUITE_DIR})
  file(SHA3_256 ${SUITE_DIR}/PendulumSuite.exp suite_sum)
  string(APPEND suite_entries
    "    <Related type=\"application/x-ma-hs-experiments\" source=\"PendulumSuite.exp\" role=\"experiment/validation\"\n"
    "             description=\"pendulum-suite-${SUITE_VERSION}: the validation experiments that stress what importers "
    "get wrong (start time, tolerance, output interval, parameters, rotation, near the top, long runs, "
    "Model Exchange), each with its reference result\"\n"
    "             checksum=\"${suite_sum}\"/>\n")
  # the results the experiments file names, in its order (a stale file of a removed case is not named)
  file(STRINGS ${SUITE_DIR}/PendulumSuite.exp references REGEX "<References source=\"[^\"]+\"")
  set(suite_results "")
  foreach(reference IN LISTS references)
    string(REGEX REPLACE ".*<References source=\"([^\"]+)\".*" "\\1" result "${reference}")
    list(APPEND suite_results ${result})
  endforeach()
  foreach(result IN LISTS suite_results)
    if(NOT EXISTS ${SUITE_DIR}/${result})
      message(FATAL_ERROR "${SUITE_DIR}/${result} is missing: the manifest names it")
    endif()
    file(SHA3_256 ${SUITE_DIR}/${result} result_sum)
    string(REGEX REPLACE "^suite/(.*)_ref\\.csv$" "\\1" case "${result}")
    string(APPEND suite_entries
      "    <Related type=\"text/csv\" source=\"${result}\" role=\"result\"\n"
      "             description=\"Exact solution of the validation experiment ${case} at times of its output grid\"\n"
      "             checksum=\"${result_sum}\"/>\n")
  endforeach()
endif()
file(WRITE ${manifest_dir}/fmi-ls-manifest.xml.tmp
  "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
  "<fmiReferences\n"
  "    xmlns:fmi-ls=\"http://fmi-standard.org/fmi-ls-manifest\"\n"
  "    fmi-ls:fmi-ls-name=\"org.fmi-standard.fmi-ls-ref\"\n"
  "    fmi-ls:fmi-ls-version=\"${LS_VERSION}\"\n"
  "    fmi-ls:fmi-ls-description=\"Layered Standard providing information on related files included in an FMU.\">\n"
  "    <Related type=\"application/x-ma-hs-experiments\" source=\"Pendulum.exp\" role=\"experiment/validation\"\n"
  "             description=\"The default experiment (the model description's DefaultExperiment and start values) "
  "with its reference result\"\n"
  "             checksum=\"${exp_sum}\"/>\n"
  "    <Related type=\"text/csv\" source=\"Pendulum_ref.csv\" role=\"result\"\n"
  "             description=\"Exact solution (Jacobi elliptic functions) from the start values, "
  "t = ${START} .. ${STOP} s in ${INTERVALS} intervals: what the outputs are "
  "without solver error; the Co-Simulation run at the default tolerance stays within ${CS_DEVIATION} rad of it\"\n"
  "             checksum=\"${csv_sum}\"/>\n"
  "    <Related type=\"text/html\" source=\"../../documentation/fmi-ls-ref.html\" role=\"document\"\n"
  "             description=\"What the related files hold and what a correct run reproduces\"\n"
  "             checksum=\"${html_sum}\"/>\n"
  "${suite_entries}"
  "</fmiReferences>\n")
file(RENAME ${manifest_dir}/fmi-ls-manifest.xml.tmp ${manifest_dir}/fmi-ls-manifest.xml)
