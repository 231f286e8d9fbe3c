# shadergen_add_permutations(<target> DOMAIN <spec> [NAMESPACE <ns>] [CACHE_DIR <dir>] [JOBS <n>]
#                            [TARGET_ENV <vulkan1.0|vulkan1.1|vulkan1.2|vulkan1.3>]
#                            [DEFINES <NAME=VALUE|NAME>...] [STRIP_DEBUG] [VARIANTS <file>]
#                            [REMOTE_CACHE <url> [REMOTE_CACHE_READONLY]]
#                            [REMOTE_CACHE_SECRET_FILE <file>])
#
# Creates a static library <target> holding every permutation of the domain <spec> as SPIR-V,
# the raw -> optimised lookup table and a registry, with the header <target>.h on its include
# path (namespace <ns>, default: the target name). shadergen runs at build time and writes only
# into the build tree; its depfile lists the spec and every GLSL file it read, so editing any
# of them reruns it and nothing else does. DEFINES are passed as `--define` arguments: fixed
# defines for every shader of the domain, on top of the spec's own "defines". TARGET_ENV is
# passed as `--target-env` (default: the spec's "target_env", else vulkan1.2). STRIP_DEBUG
# passes `--strip-debug`: blobs without names, sources or lines (the registry keeps the names). Files whose bytes did not change keep their
# timestamps, so nothing downstream recompiles after an edit that changes no SPIR-V.
#
# VARIANTS passes --variants: the raw combinations to build, one per line (it replaces the spec's
# "variants_file"; a domain of more than 2^20 raw IDs needs one). Like the spec it is an input:
# editing it reruns shadergen.
#
# REMOTE_CACHE passes --remote-cache (without it, shadergen still reads SHADERGEN_REMOTE_CACHE
# from the build's environment); REMOTE_CACHE_READONLY passes --remote-cache-readonly;
# REMOTE_CACHE_SECRET_FILE passes --remote-cache-secret-file (without it, shadergen reads
# SHADERGEN_REMOTE_CACHE_SECRET from the build's environment; the secret itself never appears in
# the build files).
#
# Needs SHADERGEN_EXECUTABLE to name the shadergen executable target (the project sets it; the
# package config sets it to the imported shadergen::shadergen).
function(shadergen_add_permutations target)
  cmake_parse_arguments(PARSE_ARGV 1 SG "REMOTE_CACHE_READONLY;STRIP_DEBUG" "DOMAIN;NAMESPACE;CACHE_DIR;JOBS;TARGET_ENV;REMOTE_CACHE;REMOTE_CACHE_SECRET_FILE;VARIANTS"
                        "DEFINES")
  if(SG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "shadergen_add_permutations(${target}): unknown arguments: ${SG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT SG_DOMAIN)
    message(FATAL_ERROR "shadergen_add_permutations(${target}): DOMAIN <spec> is required")
  endif()
  if(NOT SHADERGEN_EXECUTABLE AND TARGET shadergen::shadergen)
    # Reached through add_subdirectory(): the variable was set in the subproject's scope only.
    set(SHADERGEN_EXECUTABLE shadergen::shadergen)
  endif()
  if(NOT SHADERGEN_EXECUTABLE OR NOT TARGET ${SHADERGEN_EXECUTABLE})
    message(FATAL_ERROR "shadergen_add_permutations(${target}): SHADERGEN_EXECUTABLE does not name the shadergen "
                        "executable target; use find_package(shadergen CONFIG REQUIRED) or add_subdirectory()")
  endif()
  cmake_path(ABSOLUTE_PATH SG_DOMAIN BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE spec)
  if(NOT EXISTS "${spec}")
    message(FATAL_ERROR "shadergen_add_permutations(${target}): DOMAIN ${SG_DOMAIN} does not exist (looked for ${spec})")
  endif()
  if(NOT SG_NAMESPACE)
    set(SG_NAMESPACE ${target})
  endif()

  set(variants)
  if(SG_VARIANTS)
    cmake_path(ABSOLUTE_PATH SG_VARIANTS BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE variants)
    if(NOT EXISTS "${variants}")
      message(FATAL_ERROR "shadergen_add_permutations(${target}): VARIANTS ${SG_VARIANTS} does not exist (looked for "
                          "${variants})")
    endif()
  endif()

  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}.shadergen")
  set(depfile "${CMAKE_CURRENT_BINARY_DIR}/${target}.shadergen.d")
  set(extra)
  if(SG_CACHE_DIR)
    list(APPEND extra --cache-dir "${SG_CACHE_DIR}")
  endif()
  if(SG_JOBS)
    list(APPEND extra -j "${SG_JOBS}")
  endif()
  if(SG_TARGET_ENV)
    list(APPEND extra --target-env "${SG_TARGET_ENV}")
  endif()
  if(SG_STRIP_DEBUG)
    list(APPEND extra --strip-debug)
  endif()
  if(variants)
    list(APPEND extra --variants "${variants}")
  endif()
  foreach(define IN LISTS SG_DEFINES)
    list(APPEND extra --define "${define}")
  endforeach()
  if(SG_REMOTE_CACHE)
    list(APPEND extra --remote-cache "${SG_REMOTE_CACHE}")
  endif()
  if(SG_REMOTE_CACHE_READONLY)
    list(APPEND extra --remote-cache-readonly)
  endif()
  if(SG_REMOTE_CACHE_SECRET_FILE)
    list(APPEND extra --remote-cache-secret-file "${SG_REMOTE_CACHE_SECRET_FILE}")
  endif()
  add_custom_command(
    OUTPUT "${out}/${target}.h" "${out}/${target}.cpp" "${out}/manifest.json"
    COMMAND "$<TARGET_FILE:${SHADERGEN_EXECUTABLE}>" build "${spec}" --out "${out}" --cpp-name "${target}"
            --namespace "${SG_NAMESPACE}" --depfile "${depfile}" ${extra}
    DEPENDS "${spec}" ${variants} ${SHADERGEN_EXECUTABLE}
    DEPFILE "${depfile}"
    COMMENT "shadergen: compiling the permutations of ${SG_DOMAIN} into ${target}"
    VERBATIM)
  add_library(${target} STATIC "${out}/${target}.cpp" "${out}/${target}.h")
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${out}>")
  target_link_libraries(${target} PUBLIC shadergen::registry)
  target_compile_features(${target} PUBLIC cxx_std_20)
  set_target_properties(${target} PROPERTIES
    SHADERGEN_MANIFEST "${out}/manifest.json"
    SHADERGEN_OUTPUT_DIR "${out}")
endfunction()
