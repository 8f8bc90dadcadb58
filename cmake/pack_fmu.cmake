# cmake -DFMU_DIR=... -DFMU_FILE=... -P pack_fmu.cmake: zips every top-level entry of FMU_DIR
# (modelDescription.xml, binaries/, sources/, documentation/, extra/, whatever is there) into
# FMU_FILE, the entries at the archive's root.
file(GLOB entries RELATIVE ${FMU_DIR} ${FMU_DIR}/*)
list(SORT entries)
file(REMOVE ${FMU_FILE})
execute_process(COMMAND ${CMAKE_COMMAND} -E tar cf ${FMU_FILE} --format=zip ${entries}
                WORKING_DIRECTORY ${FMU_DIR} RESULT_VARIABLE packed)
if(NOT packed EQUAL 0)
  message(FATAL_ERROR "packing ${FMU_FILE} failed")
endif()
