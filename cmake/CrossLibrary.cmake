# Cross-building small C shared libraries with zig (`zig cc`, PyPI package `ziglang`), for
# any target zig knows, from this Linux machine. Used for the FMU's win64, darwin64 and
# glibc-floor linux64 binaries; written for any library of the project (a list of C
# sources whose public functions are marked visibility("default") / __declspec(dllexport)).
#
#   cross_shared_library(<out-var> NAME <name> TARGET <zig-target> SOURCES <c files>...
#                        [INCLUDES <dirs>...] [FLAGS <extra compiler flags>...]
#                        [DEPENDS <files>...] [SUBDIR <folder name>])
#     builds ${CMAKE_BINARY_DIR}/cross/<SUBDIR or zig-target>/<name>.so|.dll|.dylib and sets
#     <out-var> to its path. Only the marked functions are public: -fvisibility=hidden on ELF
#     and Mach-O, the dllexport list on Windows (a DLL with dllexport exports nothing else).
#     Also written: <name>.lib, the import library of a DLL (for linking test programs; not
#     shipped).
#   universal_macos_library(<out-var> NAME <name> INPUTS <thin dylibs>...)
#     joins thin Mach-O dylibs into one universal (fat) dylib with cmake/fat_macho.py.
#
# Needs CROSS_ZIG (the zig executable) and CROSS_PYTHON (a Python for fat_macho.py).
# zig's caches (the C runtimes it compiles once per target, about 1.5 min for Windows) live
# in ${CMAKE_BINARY_DIR}/zig-cache, so they go with the build folder and a rebuild is quick;
# -DPENDULUM_ZIG_CACHE=DIR shares another build's (the tests' wheel build takes build/'s, so a
# fresh clone compiles the C runtimes once, not twice).

set(PENDULUM_ZIG_CACHE ${CMAKE_BINARY_DIR}/zig-cache CACHE PATH "zig's global and local cache of the cross builds")
set(CROSS_ZIG_CACHE ${PENDULUM_ZIG_CACHE})
set(CROSS_LIBRARY_DIR ${CMAKE_CURRENT_LIST_DIR})

# Flags of every cross build: the same optimisation as the host Release build, C11, hidden
# symbols, and no floating-point contraction: clang (zig) would otherwise fuse a*b+c into
# an FMA wherever the target has one (arm64 always), and results would differ by target.
set(CROSS_COMMON_FLAGS -std=c11 -O3 -DNDEBUG -fvisibility=hidden -ffp-contract=off -s
    -Wall -Wextra -Wpedantic -Wshadow)
if(PENDULUM_WERROR)
  list(APPEND CROSS_COMMON_FLAGS -Werror)
endif()

# Linker flags and file extension of a shared library for a zig target.
function(_cross_target_traits target name ext_var link_var)
  if(target MATCHES "-windows")
    set(${ext_var} dll PARENT_SCOPE)
    set(${link_var} "" PARENT_SCOPE)
  elseif(target MATCHES "-macos")
    # install name: the importer loads the file by path; @rpath is the neutral choice
    set(${ext_var} dylib PARENT_SCOPE)
    set(${link_var} -Wl,-install_name,@rpath/${name}.dylib PARENT_SCOPE)
  else()
    set(${ext_var} so PARENT_SCOPE)
    set(${link_var} -Wl,-soname,${name}.so -Wl,-z,defs PARENT_SCOPE)
  endif()
endfunction()

function(cross_shared_library out_var)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "NAME;TARGET;SUBDIR" "SOURCES;INCLUDES;FLAGS;DEPENDS")
  if(NOT ARG_NAME OR NOT ARG_TARGET OR NOT ARG_SOURCES)
    message(FATAL_ERROR "cross_shared_library: NAME, TARGET and SOURCES are required")
  endif()
  if(NOT ARG_SUBDIR)
    set(ARG_SUBDIR ${ARG_TARGET})
  endif()
  _cross_target_traits(${ARG_TARGET} ${ARG_NAME} ext link_flags)
  set(out_dir ${CMAKE_BINARY_DIR}/cross/${ARG_SUBDIR})
  set(output ${out_dir}/${ARG_NAME}.${ext})
  set(include_flags "")
  foreach(dir IN LISTS ARG_INCLUDES)
    list(APPEND include_flags -I${dir})
  endforeach()
  if(ext STREQUAL "dll")
    list(APPEND link_flags -Wl,--out-implib,${out_dir}/${ARG_NAME}.lib)
  endif()
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
    COMMAND ${CMAKE_COMMAND} -E env ZIG_GLOBAL_CACHE_DIR=${CROSS_ZIG_CACHE} ZIG_LOCAL_CACHE_DIR=${CROSS_ZIG_CACHE}
            ${CROSS_ZIG} cc -target ${ARG_TARGET} ${CROSS_COMMON_FLAGS} ${ARG_FLAGS} ${include_flags}
            -shared -o ${output} ${ARG_SOURCES} ${link_flags}
    DEPENDS ${ARG_SOURCES} ${ARG_DEPENDS}
    COMMENT "zig cc -target ${ARG_TARGET}: ${ARG_SUBDIR}/${ARG_NAME}.${ext}"
    VERBATIM)
  set(${out_var} ${output} PARENT_SCOPE)
endfunction()

function(universal_macos_library out_var)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "NAME" "INPUTS")
  set(output ${CMAKE_BINARY_DIR}/cross/universal-macos/${ARG_NAME}.dylib)
  set(writer ${CROSS_LIBRARY_DIR}/fat_macho.py)
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/cross/universal-macos
    COMMAND ${CROSS_PYTHON} ${writer} ${output} ${ARG_INPUTS}
    DEPENDS ${ARG_INPUTS} ${writer}
    COMMENT "fat_macho.py: universal ${ARG_NAME}.dylib"
    VERBATIM)
  set(${out_var} ${output} PARENT_SCOPE)
endfunction()
