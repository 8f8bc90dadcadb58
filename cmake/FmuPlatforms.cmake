# PENDULUM_PLATFORMS=ON: the FMU's binaries for linux64, win64 and darwin64, all cross-built
# with zig (cmake/CrossLibrary.cmake), and the extra builds the platform tests run.
# In: FMU_SOURCES, FMU_HEADERS, GENERATED_DIR. Out: FMU_LINUX64 (the binary packed as
# binaries/linux64/Pendulum.so), FMU_OTHER_BINARIES (COMMAND lists that copy the rest into
# ${FMU_DIR}), FMU_BINARY_DEPENDS.

set(PENDULUM_ZIG "" CACHE FILEPATH "zig executable (default: zig on PATH, else the ziglang package of python3)")
set(PENDULUM_PYTHON "" CACHE FILEPATH "Python that runs cmake/fat_macho.py (default: python3 on PATH)")

# Resolved at every configure, so a path cached by a build environment that is gone since
# (pip's isolated wheel build) does not stick.
set(CROSS_PYTHON "${PENDULUM_PYTHON}")
if(NOT EXISTS "${CROSS_PYTHON}")
  unset(CROSS_PYTHON)
  find_program(CROSS_PYTHON NAMES python3 python NO_CACHE REQUIRED)
endif()
set(CROSS_ZIG "${PENDULUM_ZIG}")
if(NOT EXISTS "${CROSS_ZIG}")
  unset(CROSS_ZIG)
  find_program(CROSS_ZIG zig NO_CACHE)
endif()
if(NOT CROSS_ZIG)
  execute_process(
    COMMAND ${CROSS_PYTHON} -c "import pathlib, ziglang; print(pathlib.Path(ziglang.__file__).with_name('zig'))"
    OUTPUT_VARIABLE CROSS_ZIG OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE no_ziglang)
  if(no_ziglang OR NOT EXISTS "${CROSS_ZIG}")
    message(FATAL_ERROR "PENDULUM_PLATFORMS=ON needs zig: pip install ziglang==0.17.0 "
                        "(python/requirements.lock; scripts/build-fmu.sh sets it up), or -DPENDULUM_ZIG=PATH")
  endif()
endif()
execute_process(COMMAND ${CROSS_ZIG} version OUTPUT_VARIABLE zig_version OUTPUT_STRIP_TRAILING_WHITESPACE)
message(STATUS "Cross-building the FMU binaries with zig ${zig_version}: ${CROSS_ZIG}")

include(${CMAKE_CURRENT_LIST_DIR}/CrossLibrary.cmake)

# The floors: glibc 2.17 (manylinux2014: CentOS 7 and every later distribution), macOS 10.13
# on x86_64 and 11.0 (the first release for Apple silicon) on arm64. Windows x86_64 with the
# UCRT (part of Windows 10 and later, an update on 7 and 8.1), see the README. These zig
# targets are the one place the floors are set: the FMI 2.0 and 3.0 FMUs (cmake/Fmi3.cmake)
# and the exact library all build with them.
set(ZIG_LINUX_X86_64 x86_64-linux-gnu.2.17)
set(ZIG_LINUX_ARM64 aarch64-linux-gnu.2.17)
set(ZIG_WINDOWS_X86_64 x86_64-windows-gnu)
set(ZIG_MACOS_X86_64 x86_64-macos.10.13)
set(ZIG_MACOS_ARM64 aarch64-macos.11.0)
set(FMU_CROSS_TARGETS
    linux64 ${ZIG_LINUX_X86_64}
    win64 ${ZIG_WINDOWS_X86_64}
    darwin-x86_64 ${ZIG_MACOS_X86_64}
    darwin-arm64 ${ZIG_MACOS_ARM64}
    # for the tests only: the arm64 code (flags as darwin-arm64) on Linux, run under qemu,
    aarch64-linux ${ZIG_LINUX_ARM64})
set(fmu_cross_common NAME Pendulum SOURCES ${FMU_SOURCES} INCLUDES ${FMU_INCLUDE_DIRS} ${GENERATED_DIR}
    DEPENDS ${FMU_HEADERS} ${GENERATED_DIR}/pendulum_vrs.h)
set(FMU_BINARY_DEPENDS "")
while(FMU_CROSS_TARGETS)
  list(POP_FRONT FMU_CROSS_TARGETS subdir zig_target)
  cross_shared_library(lib_${subdir} TARGET ${zig_target} SUBDIR ${subdir} ${fmu_cross_common})
  list(APPEND FMU_BINARY_DEPENDS ${lib_${subdir}})
endwhile()
# ... and what contraction would change (tests/helpers/platform_runs.py measures it): a*b+c fused
# into an FMA on arm64, and on x86_64 with FMA hardware (x86-64-v3, Haswell and later).
cross_shared_library(lib_contract_arm64 TARGET ${ZIG_LINUX_ARM64} SUBDIR aarch64-linux-contract
                     FLAGS -ffp-contract=fast ${fmu_cross_common})
cross_shared_library(lib_contract_v3 TARGET ${ZIG_LINUX_X86_64} SUBDIR x86_64-v3-contract
                     FLAGS -mcpu=x86_64_v3 -ffp-contract=fast ${fmu_cross_common})
universal_macos_library(lib_darwin64 NAME Pendulum INPUTS ${lib_darwin-x86_64} ${lib_darwin-arm64})
list(APPEND FMU_BINARY_DEPENDS ${lib_darwin64} ${lib_contract_arm64} ${lib_contract_v3})

set(FMU_LINUX64 ${lib_linux64})
set(FMU_OTHER_BINARIES
    COMMAND ${CMAKE_COMMAND} -E make_directory ${FMU_DIR}/binaries/win64 ${FMU_DIR}/binaries/darwin64
    COMMAND ${CMAKE_COMMAND} -E copy ${lib_win64} ${FMU_DIR}/binaries/win64/Pendulum.dll
    COMMAND ${CMAKE_COMMAND} -E copy ${lib_darwin64} ${FMU_DIR}/binaries/darwin64/Pendulum.dylib)

# pendulum_exact (the library behind pendulum_fmu.exact) for the same three platforms, so a
# py3-none-any wheel carries it for each: build/exact_lib/<platform>/<the file name the
# package loads>, where setup.py picks them up.
# With the AVX-512 copy of the exact solution, as pendulum_core (CMakeLists.txt).
set(exact_cross_common NAME pendulum_exact
    SOURCES ${LIBS_DIR}/exact_lib/pendulum_exact_lib.c ${CORE_SOURCES} ${AVX512_COPY_SOURCE}
    FLAGS -DPENDULUM_EXACT_AVX512=1
    INCLUDES ${FMU_INCLUDE_DIRS} ${GENERATED_DIR}
    DEPENDS ${FMU_HEADERS} ${GENERATED_DIR}/pendulum_vrs.h ${LIBS_DIR}/exact_lib/pendulum_exact_lib.h)
foreach(platform IN ITEMS LINUX_X86_64 WINDOWS_X86_64 MACOS_X86_64 MACOS_ARM64)
  cross_shared_library(exact_${platform} TARGET ${ZIG_${platform}} SUBDIR exact-${platform} ${exact_cross_common})
endforeach()
universal_macos_library(exact_darwin64 NAME pendulum_exact INPUTS ${exact_MACOS_X86_64} ${exact_MACOS_ARM64})
# ... and pendulum_driver (the output loop of pendulum_fmu.fmu.driver), the same way.
set(driver_cross_common NAME pendulum_driver SOURCES ${LIBS_DIR}/driver_lib/pendulum_driver.c
    INCLUDES ${LIBS_DIR}/driver_lib DEPENDS ${LIBS_DIR}/driver_lib/pendulum_driver.h)
foreach(platform IN ITEMS LINUX_X86_64 WINDOWS_X86_64 MACOS_X86_64 MACOS_ARM64)
  cross_shared_library(driver_${platform} TARGET ${ZIG_${platform}} SUBDIR driver-${platform} ${driver_cross_common})
endforeach()
universal_macos_library(driver_darwin64 NAME pendulum_driver INPUTS ${driver_MACOS_X86_64} ${driver_MACOS_ARM64})
set(exact_dir ${CMAKE_BINARY_DIR}/exact_lib)
add_custom_command(
  OUTPUT ${exact_dir}/linux64/libpendulum_exact.so ${exact_dir}/win64/pendulum_exact.dll
         ${exact_dir}/darwin64/libpendulum_exact.dylib
         ${exact_dir}/linux64/libpendulum_driver.so ${exact_dir}/win64/pendulum_driver.dll
         ${exact_dir}/darwin64/libpendulum_driver.dylib
  COMMAND ${CMAKE_COMMAND} -E make_directory ${exact_dir}/linux64 ${exact_dir}/win64 ${exact_dir}/darwin64
  COMMAND ${CMAKE_COMMAND} -E copy ${exact_LINUX_X86_64} ${exact_dir}/linux64/libpendulum_exact.so
  COMMAND ${CMAKE_COMMAND} -E copy ${exact_WINDOWS_X86_64} ${exact_dir}/win64/pendulum_exact.dll
  COMMAND ${CMAKE_COMMAND} -E copy ${exact_darwin64} ${exact_dir}/darwin64/libpendulum_exact.dylib
  COMMAND ${CMAKE_COMMAND} -E copy ${driver_LINUX_X86_64} ${exact_dir}/linux64/libpendulum_driver.so
  COMMAND ${CMAKE_COMMAND} -E copy ${driver_WINDOWS_X86_64} ${exact_dir}/win64/pendulum_driver.dll
  COMMAND ${CMAKE_COMMAND} -E copy ${driver_darwin64} ${exact_dir}/darwin64/libpendulum_driver.dylib
  DEPENDS ${exact_LINUX_X86_64} ${exact_WINDOWS_X86_64} ${exact_darwin64}
          ${driver_LINUX_X86_64} ${driver_WINDOWS_X86_64} ${driver_darwin64}
  VERBATIM)
add_custom_target(pendulum_exact_platforms ALL
                  DEPENDS ${exact_dir}/linux64/libpendulum_exact.so ${exact_dir}/win64/pendulum_exact.dll
                          ${exact_dir}/darwin64/libpendulum_exact.dylib
                          ${exact_dir}/linux64/libpendulum_driver.so ${exact_dir}/win64/pendulum_driver.dll
                          ${exact_dir}/darwin64/libpendulum_driver.dylib)
