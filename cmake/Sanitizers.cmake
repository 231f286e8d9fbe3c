# -DSANITIZE=ON: AddressSanitizer + UndefinedBehaviorSanitizer on the code this project ships.
# The flags live in INTERFACE targets (like shadergen::warnings) instead of CMAKE_CXX_FLAGS, so
# nothing leaks into a parent project or an installed package config.
# shadergen_sanitize_all_targets() links them PRIVATE into the targets of every directory, so
# targets added later (tests, benchmarks, the libraries shadergen_add_permutations generates)
# are covered without each CMakeLists having to remember it:
#   - the product's targets (shadergen/, runtime/, common/, permutations/, and every registry
#     library shadergen_add_permutations generates, wherever it is called) compile instrumented,
#     at -O1, the level the AddressSanitizer documentation recommends;
#   - the test code (tests/, bench/) compiles exactly as in the test build, uninstrumented, and
#     only links the sanitizer runtimes: ASan still sees every allocation and every access the
#     product makes, LSan every leak, UBSan every check in product code. Test code compiled with
#     the test build's command lines is what lets ccache hand the sanitizer build the test
#     build's objects (docs/ci.md: the cold sanitizer build went from 1,394 s to 392 s).
#     -DSHADERGEN_SANITIZE_TESTS=ON instruments the test code as well; tests/sanitizers/ (the
#     self-tests, which do wrong things in their own code) always is.
option(SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer (the product instrumented)" OFF)
option(SHADERGEN_SANITIZE_TESTS "With SANITIZE: instrument the test code as well, not only the product" OFF)
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
  # -O1 after the configuration's -O2: the later option wins.
  target_compile_options(shadergen_sanitizers INTERFACE ${SHADERGEN_SANITIZER_FLAGS} -O1)
  target_link_options(shadergen_sanitizers INTERFACE ${SHADERGEN_SANITIZER_FLAGS})
  if(SHADERGEN_FUZZ)
    target_compile_options(shadergen_sanitizers INTERFACE -fsanitize=fuzzer-no-link)
  endif()
endif()
# What an uninstrumented executable needs to run with the instrumented product: the runtimes.
add_library(shadergen_sanitizer_runtimes INTERFACE)
if(SANITIZE)
  target_link_options(shadergen_sanitizer_runtimes INTERFACE ${SHADERGEN_SANITIZER_FLAGS})
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

# Whether `target` (defined in `dir`) is test code: under tests/ or bench/, not a library
# shadergen_add_permutations generated (generated product code), not a sanitizer self-test.
function(_shadergen_is_test_code target dir out)
  set(test_code FALSE)
  file(RELATIVE_PATH rel "${PROJECT_SOURCE_DIR}" "${dir}")
  get_target_property(generated ${target} SHADERGEN_MANIFEST)
  if(rel MATCHES "^(tests|bench)(/|$)" AND NOT rel MATCHES "^tests/sanitizers(/|$)" AND NOT generated)
    set(test_code TRUE)
  endif()
  set(${out} ${test_code} PARENT_SCOPE)
endfunction()

# Call once, at the end of the top-level CMakeLists.txt, after every target exists.
function(shadergen_sanitize_all_targets)
  if(NOT SANITIZE)
    return()
  endif()
  _shadergen_collect_targets("${PROJECT_SOURCE_DIR}" targets)
  set(instrumented 0)
  set(plain 0)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    # Interface libraries compile nothing; utility targets (custom commands) link nothing.
    if(NOT type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$")
      continue()
    endif()
    get_target_property(dir ${target} SOURCE_DIR)
    _shadergen_is_test_code(${target} "${dir}" test_code)
    # libFuzzer's coverage instrumentation has to reach every target, test code included.
    if(test_code AND NOT SHADERGEN_SANITIZE_TESTS AND NOT SHADERGEN_FUZZ)
      target_link_libraries(${target} PRIVATE shadergen_sanitizer_runtimes)
      math(EXPR plain "${plain} + 1")
    else()
      target_link_libraries(${target} PRIVATE shadergen::sanitizers)
      math(EXPR instrumented "${instrumented} + 1")
    endif()
    if(type STREQUAL "EXECUTABLE")
      target_link_libraries(${target} PRIVATE shadergen_sanitizer_defaults)
    endif()
  endforeach()
  message(STATUS "SANITIZE=ON: ASan+UBSan compiled into ${instrumented} targets; ${plain} test targets "
                 "link the runtimes only (SHADERGEN_SANITIZE_TESTS=ON instruments them too)")
endfunction()
