# cmake -DREFERENCE_DIR=... -DREFERENCE_HTML=... -DLS_VERSION=... -DSTART=... -DSTOP=...
#       -DINTERVALS=... -DCS_DEVIATION=... -P ReferenceManifest.cmake
# Writes REFERENCE_DIR/fmi-ls-manifest.xml, the FMI-LS-REF manifest, after the files it names
# exist: each <Related> carries the SHA3-256 digest of its file (the standard's checksum
# attribute, whose checksumType defaults to SHA3-256), so an importer can verify them.
foreach(file Pendulum.exp Pendulum_ref.csv)
  if(NOT EXISTS ${REFERENCE_DIR}/${file})
    message(FATAL_ERROR "${REFERENCE_DIR}/${file} is missing: the manifest names it")
  endif()
endforeach()
file(SHA3_256 ${REFERENCE_DIR}/Pendulum.exp exp_sum)
file(SHA3_256 ${REFERENCE_DIR}/Pendulum_ref.csv csv_sum)
file(SHA3_256 ${REFERENCE_HTML} html_sum)
file(WRITE ${REFERENCE_DIR}/fmi-ls-manifest.xml.tmp
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
  "</fmiReferences>\n")
file(RENAME ${REFERENCE_DIR}/fmi-ls-manifest.xml.tmp ${REFERENCE_DIR}/fmi-ls-manifest.xml)
