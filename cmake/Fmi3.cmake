# Builds the FMI 3.0 Pendulum.fmu (Co-Simulation + Model Exchange) at build/fmi3/Pendulum.fmu
# from the same model core as the FMI 2.0 one (CORE_SOURCES: every source but fmu_src/fmi2/) and
# the thin FMI 3.0 layer fmu_src/fmi3/. Included by CMakeLists.txt after the FMI 2.0 FMU.
#
# The FMI 3.0 declarations are the project's own, written from the standard (fmu_src/fmi3/fmi3_api.h,
# as fmu_src/fmi2/fmi2_api.h for FMI 2.0): a plain CMake build makes both FMUs, fmpy is a test
# dependency only.
option(PENDULUM_FMI3 "Build the FMI 3.0 Pendulum.fmu" ON)
if(NOT PENDULUM_FMI3)
  return()
endif()

file(GLOB FMI3_LAYER_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/fmu_src/fmi3/*.c)
set(FMI3_SOURCES ${CORE_SOURCES} ${FMI3_LAYER_SOURCES})
set(FMI3_DIR ${CMAKE_CURRENT_BINARY_DIR}/fmi3)

add_library(Pendulum_fmi3 SHARED ${FMI3_SOURCES})
target_include_directories(Pendulum_fmi3 PRIVATE ${FMU_INCLUDE_DIRS} ${GENERATED_DIR})
target_compile_options(Pendulum_fmi3 PRIVATE ${WARNING_FLAGS})
set_target_properties(Pendulum_fmi3 PROPERTIES PREFIX "" OUTPUT_NAME Pendulum C_VISIBILITY_PRESET hidden
                      LIBRARY_OUTPUT_DIRECTORY ${FMI3_DIR}/lib)
target_link_libraries(Pendulum_fmi3 PRIVATE m)
target_link_options(Pendulum_fmi3 PRIVATE -Wl,--no-undefined)

# modelDescription.xml: the template with the FMI 2.0 description's GUID as instantiation token
set(FMI3_MODEL_DESCRIPTION_IN ${MODELS_DIR}/pendulum/FMI3.xml.in)
configure_file(${FMI3_MODEL_DESCRIPTION_IN} ${FMI3_DIR}/modelDescription.xml @ONLY)

# sources/buildDescription.xml (FMI 3.0 2.5.1): the same list of sources the binary is built from
set(build_files "")
foreach(source IN LISTS FMI3_SOURCES)
  get_filename_component(source_name ${source} NAME)
  string(APPEND build_files "        <SourceFile name=\"${source_name}\"/>\n")
endforeach()
file(WRITE ${FMI3_DIR}/buildDescription.xml.new
  "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
  "<fmiBuildDescription fmiVersion=\"3.0\">\n"
  "  <BuildConfiguration modelIdentifier=\"Pendulum\" description=\"C sources; the FMI 3.0 declarations are in fmi3_api.h\">\n"
  "    <SourceFileSet language=\"C99\">\n"
  "${build_files}"
  "    </SourceFileSet>\n"
  "    <Library name=\"m\"/>\n"
  "  </BuildConfiguration>\n"
  "</fmiBuildDescription>\n")
configure_file(${FMI3_DIR}/buildDescription.xml.new ${FMI3_DIR}/buildDescription.xml COPYONLY)

# Binaries: the host build in binaries/x86_64-linux; with PENDULUM_PLATFORMS=ON (as the FMI 2.0
# FMU, cmake/FmuPlatforms.cmake) the glibc-2.17 build there instead, and x86_64-windows,
# x86_64-darwin, aarch64-darwin and aarch64-linux (Raspberry Pi OS 64-bit, ARM servers and CI
# runners; glibc 2.17 like x86_64) beside it (FMI 3.0 names one folder per architecture, so
# no universal binary), all cross-built with zig from the same sources and flags.
set(FMI3_LINUX_BINARY $<TARGET_FILE:Pendulum_fmi3>)
set(FMI3_OTHER_BINARIES "")
set(FMI3_BINARY_DEPENDS "")
if(PENDULUM_PLATFORMS)
  set(fmi3_cross_common NAME Pendulum SOURCES ${FMI3_SOURCES}
      INCLUDES ${FMU_INCLUDE_DIRS} ${GENERATED_DIR}
      DEPENDS ${FMU_HEADERS} ${GENERATED_DIR}/pendulum_vrs.h)
  set(fmi3_cross_targets
      x86_64-linux ${ZIG_LINUX_X86_64} so
      x86_64-windows ${ZIG_WINDOWS_X86_64} dll
      x86_64-darwin ${ZIG_MACOS_X86_64} dylib
      aarch64-darwin ${ZIG_MACOS_ARM64} dylib
      aarch64-linux ${ZIG_LINUX_ARM64} so)
  while(fmi3_cross_targets)
    list(POP_FRONT fmi3_cross_targets folder zig_target ext)
    cross_shared_library(fmi3_${folder} TARGET ${zig_target} SUBDIR fmi3-${folder} ${fmi3_cross_common})
    list(APPEND FMI3_BINARY_DEPENDS ${fmi3_${folder}})
    if(folder STREQUAL "x86_64-linux")
      set(FMI3_LINUX_BINARY ${fmi3_${folder}})
    else()
      list(APPEND FMI3_OTHER_BINARIES
           COMMAND ${CMAKE_COMMAND} -E make_directory ${FMI3_DIR}/fmu/binaries/${folder}
           COMMAND ${CMAKE_COMMAND} -E copy ${fmi3_${folder}} ${FMI3_DIR}/fmu/binaries/${folder}/Pendulum.${ext})
    endif()
  endwhile()
endif()

set(FMI3_FMU_DIR ${FMI3_DIR}/fmu)
set(FMI3_FMU_FILE ${FMI3_DIR}/Pendulum.fmu)
fmu_room_headers(FMI3_HEADERS ${FMI3_SOURCES})
add_custom_command(
  OUTPUT ${FMI3_FMU_FILE}
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${FMI3_FMU_DIR}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${FMI3_FMU_DIR}/binaries/x86_64-linux ${FMI3_FMU_DIR}/sources
          ${FMI3_FMU_DIR}/documentation
  COMMAND ${CMAKE_COMMAND} -E copy ${FMI3_DIR}/modelDescription.xml ${FMI3_FMU_DIR}/modelDescription.xml
  COMMAND ${CMAKE_COMMAND} -E copy ${FMI3_LINUX_BINARY} ${FMI3_FMU_DIR}/binaries/x86_64-linux/Pendulum.so
  ${FMI3_OTHER_BINARIES}
  COMMAND ${CMAKE_COMMAND} -E copy ${FMI3_SOURCES} ${FMI3_HEADERS} ${GENERATED_DIR}/pendulum_vrs.h
          ${FMI3_DIR}/buildDescription.xml ${FMI3_FMU_DIR}/sources/
  COMMAND ${CMAKE_COMMAND} -E copy ${PENDULUM_DOC_DIR}/index.html
          ${PENDULUM_DOC_DIR}/math.html ${FMI3_FMU_DIR}/documentation/
  COMMAND ${CMAKE_COMMAND} -E rm -f ${FMI3_FMU_FILE}
  COMMAND ${CMAKE_COMMAND} -E chdir ${FMI3_FMU_DIR} ${CMAKE_COMMAND} -E tar cf ${FMI3_FMU_FILE} --format=zip
          modelDescription.xml binaries sources documentation
  DEPENDS Pendulum_fmi3 ${FMI3_BINARY_DEPENDS} ${FMI3_MODEL_DESCRIPTION_IN} ${FMI3_HEADERS} ${FMI3_DIR}/buildDescription.xml
          ${PENDULUM_DOC_DIR}/index.html
          ${PENDULUM_DOC_DIR}/math.html
  COMMENT "Packing fmi3/Pendulum.fmu"
  VERBATIM)
add_custom_target(fmu3 ALL DEPENDS ${FMI3_FMU_FILE})
