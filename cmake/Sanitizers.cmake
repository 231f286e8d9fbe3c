# -DSANITIZE=ON: AddressSanitizer + UndefinedBehaviorSanitizer on every target this project
# defines. The flags live in an INTERFACE target (like shadergen::warnings) instead of
# CMAKE_CXX_FLAGS, so nothing leaks into a parent project or an installed package config.
# shadergen_sanitize_all_targets() links it PRIVATE into every compiled target of every
# directory, so targets added later (tests, benchmarks, the libraries shadergen_add_permutations
# generates) are covered without each CMakeLists having to remember it.
option(SANITIZE "Build every target with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
# -DSHADERGEN_FUZZ=ON (Clang only): the libFuzzer targets of tests/fuzz. Implies SANITIZE, and
# adds libFuzzer's coverage instrumentation to every target so the fuzzers see inside shadergen.
option(SHADERGEN_FUZZ "Build the libFuzzer targets (Clang only; implies SANITIZE)" OFF)
if(SHADERGEN_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SHADERGEN_FUZZ=ON needs Clang (e.g. -DCMAKE_CXX_COMPILER=clang++-14), "
                        "not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  set(SANITIZE ON)
endif()

add_library(shadergen_sanitizers INTERFACE)
add_library(shadergen::sanitizers ALIAS shadergen_sanitizers)
if(SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "SANITIZE=ON needs GCC or Clang (compiler: ${CMAKE_CXX_COMPILER_ID})")
  endif()
  # -fno-sanitize-recover=undefined: a UBSan report aborts, so it fails the test that hit it.
  set(SHADERGEN_SANITIZER_FLAGS
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_compile_options(shadergen_sanitizers INTERFACE ${SHADERGEN_SANITIZER_FLAGS})
  target_link_options(shadergen_sanitizers INTERFACE ${SHADERGEN_SANITIZER_FLAGS})
  if(SHADERGEN_FUZZ)
    target_compile_options(shadergen_sanitizers INTERFACE -fsanitize=fuzzer-no-link)
  endif()
endif()

# Every sanitized executable carries its runtime options (cmake/sanitizers/default_options.cpp:
# build configuration compiled into the products too, so it lives here, not under tests/): the
# tests under ctest, shadergen run at build time by shadergen_add_permutations() and a binary
# started by hand all get the same options and the same LeakSanitizer suppressions, with no
# environment to remember. ASAN_OPTIONS / UBSAN_OPTIONS / LSAN_OPTIONS still override.
set(SHADERGEN_LSAN_SUPPRESSIONS "${PROJECT_SOURCE_DIR}/cmake/sanitizers/lsan.supp")
if(SANITIZE)
  add_library(shadergen_sanitizer_defaults OBJECT
    ${PROJECT_SOURCE_DIR}/cmake/sanitizers/default_options.cpp
    ${PROJECT_SOURCE_DIR}/cmake/sanitizers/keep_drivers_loaded.cpp)
  target_compile_definitions(shadergen_sanitizer_defaults PRIVATE
    SHADERGEN_LSAN_SUPPRESSIONS="${SHADERGEN_LSAN_SUPPRESSIONS}")
endif()

# Recursively collects the build-system targets of `dir` and its subdirectories into `out`.
function(_shadergen_collect_targets dir out)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    _shadergen_collect_targets("${subdir}" sub_targets)
    list(APPEND targets ${sub_targets})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# Call once, at the end of the top-level CMakeLists.txt, after every target exists.
function(shadergen_sanitize_all_targets)
  if(NOT SANITIZE)
    return()
  endif()
  _shadergen_collect_targets("${PROJECT_SOURCE_DIR}" targets)
  set(count 0)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    # Interface libraries compile nothing; utility targets (custom commands) link nothing.
    if(type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$")
      target_link_libraries(${target} PRIVATE shadergen::sanitizers)
      if(type STREQUAL "EXECUTABLE")
        target_link_libraries(${target} PRIVATE shadergen_sanitizer_defaults)
      endif()
      math(EXPR count "${count} + 1")
    endif()
  endforeach()
  message(STATUS "SANITIZE=ON: ASan+UBSan on ${count} targets")
endfunction()
