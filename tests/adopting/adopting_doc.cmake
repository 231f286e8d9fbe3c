# Builds the example project of docs/adopting.md from the doc itself, so the doc cannot drift
# from the tool: every fenced block whose opening line names a file after the language
# (```json material/shaders/material.json) is written to that path under a scratch folder, the
# folder `material/` is configured and built as an outside project against this build installed
# into a scratch prefix, and its programs run (they check what the doc says the generated API
# does; the output the doc quotes must be theirs). The doc's quoted diagnostics (shadergen's
# for four spec and shader mistakes, the compiler's for a bare integer as a RawId) are triggered
# for real and must appear in the doc word for word, and the edit-rebuild loop must run what the
# doc says it runs (the times are the doc's measurement, not checked here).
#
# cmake -DBUILD_DIR=<shadergen build> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> [-DWITH_VULKAN=OFF]
#       -P adopting_doc.cmake
#
# The example includes <shadergen/vulkan.h> (COMPONENTS vulkan). With -DWITH_VULKAN=OFF (a build
# that found no Vulkan headers) the project is not built: the blocks are still extracted, both
# specs still built with shadergen, and the diagnostics still compared.
cmake_minimum_required(VERSION 3.25)  # policies: while(TRUE), if(IN_LIST)
if(NOT DEFINED WITH_VULKAN)
  set(WITH_VULKAN ON)
endif()
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "adopting_doc.cmake: -D${var}=... is required")
  endif()
endforeach()

set(doc "${SOURCE_DIR}/docs/adopting.md")
# The files the example project cannot do without; a block renamed or dropped from the doc
# fails here, by name, rather than somewhere in the build.
set(required_files
    material/CMakeLists.txt
    material/main.cpp
    material/kinds.cpp
    material/shaders/material.json
    material/shaders/material_kinds.json
    material/shaders/material.vert
    material/shaders/material.frag
    material/shaders/include/material_common.glsl)

include(${CMAKE_CURRENT_LIST_DIR}/../cmake/script_steps.cmake)  # run(), step_done()

if(NOT EXISTS "${doc}")
  message(FATAL_ERROR "${doc} does not exist")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(project_root "${WORK_DIR}/doc")

# --- 1. Extract the blocks ------------------------------------------------------------------
# A fence opens at the start of a line with three backticks; its info string is the language
# and, for a file of the example, the file's path. The block ends at the next line starting
# with three backticks. Blocks that name no file (sessions, excerpts) are left alone.
file(READ "${doc}" text)
set(rest "\n${text}")
set(written "")
while(TRUE)
  string(FIND "${rest}" "\n```" open)
  if(open EQUAL -1)
    break()
  endif()
  math(EXPR after "${open} + 4")
  string(SUBSTRING "${rest}" ${after} -1 rest)
  string(FIND "${rest}" "\n" eol)
  if(eol EQUAL -1)
    message(FATAL_ERROR "${doc}: a fence opens on the last line")
  endif()
  string(SUBSTRING "${rest}" 0 ${eol} info)
  math(EXPR body_start "${eol} + 1")
  string(SUBSTRING "${rest}" ${body_start} -1 rest)
  string(FIND "\n${rest}" "\n```" close)
  if(close EQUAL -1)
    message(FATAL_ERROR "${doc}: the block opened by \"```${info}\" is never closed")
  endif()
  string(SUBSTRING "${rest}" 0 ${close} body)
  math(EXPR after "${close} + 3")
  string(SUBSTRING "${rest}" ${after} -1 rest)

  string(STRIP "${info}" info)
  string(REGEX MATCH "^[A-Za-z0-9_+-]+[ \t]+([^ \t]+)$" named "${info}")
  if(NOT named)
    continue()
  endif()
  set(path "${CMAKE_MATCH_1}")
  if(IS_ABSOLUTE "${path}" OR path MATCHES "(^|/)\\.\\.(/|$)")
    message(FATAL_ERROR "${doc}: block \"```${info}\": a file of the example must be a relative path inside it")
  endif()
  if(path IN_LIST written)
    message(FATAL_ERROR "${doc}: two blocks name ${path}; each file of the example is written once")
  endif()
  list(APPEND written "${path}")
  file(WRITE "${project_root}/${path}" "${body}")
endwhile()

if(NOT written)
  message(FATAL_ERROR "${doc}: no fenced block names a file (```json material/shaders/material.json); "
                      "the doc's example project has gone, so nothing of it can be compiled")
endif()
foreach(path IN LISTS required_files)
  if(NOT path IN_LIST written)
    message(FATAL_ERROR "${doc}: no block names ${path}, which the example project needs "
                        "(blocks found: ${written})")
  endif()
endforeach()
list(LENGTH written count)
step_done("extracted ${count} files from docs/adopting.md")

# --- 2. Install shadergen into a scratch prefix, as the doc's section 1 does ------------------
set(prefix "${WORK_DIR}/prefix")
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
set(shadergen "${prefix}/bin/shadergen")
if(NOT EXISTS "${shadergen}")
  message(FATAL_ERROR "the install has no bin/shadergen")
endif()
# Every shadergen run below, also those of the example's build, uses a cache of its own.
set(ENV{SHADERGEN_CACHE_DIR} "${WORK_DIR}/cache")
unset(ENV{SHADERGEN_REMOTE_CACHE})
step_done("install")

set(project "${project_root}/material")
set(shaders "${project}/shaders")
set(build "${WORK_DIR}/build")

# --- 3. The mistakes: each edit the doc describes, and the message it quotes ------------------
# Applies one edit to a file of the example, runs shadergen on `spec` in the shaders folder (as
# the doc says), restores the file, and fails unless the build failed with an error line that
# the doc quotes word for word.
function(expect_quoted_error name file from to spec)
  set(path "${shaders}/${file}")
  file(READ "${path}" original)
  string(FIND "${original}" "${from}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "mistake \"${name}\": ${file} no longer holds \"${from}\", which the test replaces; "
                        "update the mistake in docs/adopting.md and here")
  endif()
  string(REPLACE "${from}" "${to}" edited "${original}")
  file(WRITE "${path}" "${edited}")
  execute_process(COMMAND "${shadergen}" build "${spec}" --out "${WORK_DIR}/mistake"
                  WORKING_DIRECTORY "${shaders}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(WRITE "${path}" "${original}")
  if(rc EQUAL 0)
    message(FATAL_ERROR "mistake \"${name}\": shadergen built ${spec} with ${file} edited (\"${to}\")")
  endif()
  string(REGEX MATCH "[^\n]*error:[^\n]*" line "${out}${err}")
  if(NOT line)
    message(FATAL_ERROR "mistake \"${name}\": shadergen failed without an error line:\n${out}${err}")
  endif()
  string(FIND "${text}" "\n${line}\n" quoted)
  if(quoted EQUAL -1)
    message(FATAL_ERROR "mistake \"${name}\": docs/adopting.md does not quote what shadergen says now; "
                        "replace its message with this line:\n${line}")
  endif()
endfunction()

expect_quoted_error(misspelt_define material.json [["define": "HAS_EMISSIVE"]] [["define": "HAS_EMMISIVE"]]
                    material.json)
expect_quoted_error(if_on_a_constant material_kinds.json [["define": "NORMAL_MAP" }]]
                    [["define": "NORMAL_MAP", "kind": "specialization" }]] material_kinds.json)
expect_quoted_error(interface material.vert "layout(location = 3) out vec4 out_tangent;"
                    "layout(location = 4) out vec4 out_tangent;" material.json)
expect_quoted_error(unknown_value material.json "SHADING == UNLIT && NORMAL_MAP" "SHADING == UNLIT && LIGHT_COUNT == 3"
                    material.json)
step_done("the four diagnostics of \"Common mistakes\" are quoted as shadergen prints them")

if(NOT WITH_VULKAN)
  foreach(spec material.json material_kinds.json)
    run("${shadergen}" build "${shaders}/${spec}" --out "${WORK_DIR}/out/${spec}")
  endforeach()
  message(STATUS "no Vulkan headers: both specs build; the example's C++ (COMPONENTS vulkan) is not built")
  return()
endif()

# --- 4. The project: configure, build, run ------------------------------------------------------
run(${CMAKE_COMMAND} -S "${project}" -B "${build}" -G Ninja "-DCMAKE_PREFIX_PATH=${prefix}"
    -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build "${build}")
foreach(program material_check material_kinds_check)
  run("${build}/${program}")
  if(NOT last_output MATCHES "all checks passed")
    message(FATAL_ERROR "${program} did not say all its checks passed:\n${last_output}")
  endif()
  string(STRIP "${last_output}" said)
  message(STATUS "${program}: ${said}")
  # The doc quotes each program's output; it must be what the program prints.
  string(FIND "${text}" "${said}\n```" quoted)
  if(quoted EQUAL -1)
    message(FATAL_ERROR "docs/adopting.md does not quote ${program}'s output:\n${said}")
  endif()
endforeach()
step_done("the example project builds against the install and its checks pass")

# The C++ mistake: a bare integer where a RawId is wanted must not compile, with the message the
# doc quotes (C locale: GCC's ASCII quotes).
file(STRINGS "${build}/CMakeCache.txt" compiler REGEX "^CMAKE_CXX_COMPILER:")
string(REGEX REPLACE "^[^=]*=" "" compiler "${compiler}")
file(WRITE "${WORK_DIR}/bare_integer.cpp"
     "#include <material_shaders.h>\nconst shadergen::Permutation* p = studio::material::registry().optimised_for_raw(7);\n")
set(ENV{LC_ALL} C)
execute_process(COMMAND "${compiler}" -std=c++20 -fsyntax-only "-I${prefix}/include"
                        "-I${build}/material_shaders.shadergen" "${WORK_DIR}/bare_integer.cpp"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
unset(ENV{LC_ALL})
string(REGEX MATCH "cannot convert '[^']*' to '[^']*'" said "${out}${err}")
if(rc EQUAL 0 OR NOT said)
  message(FATAL_ERROR "optimised_for_raw(7) must not compile, saying \"cannot convert\":\n${out}${err}")
endif()
string(FIND "${text}" "(`${said}`)" quoted)
if(quoted EQUAL -1)
  message(FATAL_ERROR "docs/adopting.md does not quote the compiler's message for a bare integer: ${said}")
endif()
step_done("a bare integer as a RawId does not compile, as the doc says")

# --- 5. The edit-rebuild loop as section 7 describes it (what runs, not how long) --------------
run(${CMAKE_COMMAND} --build "${build}")
if(NOT last_output MATCHES "no work to do")
  message(FATAL_ERROR "a no-op rebuild did work:\n${last_output}")
endif()

execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)  # coarse file system timestamps
file(READ "${shaders}/material.json" spec_text)
string(REGEX REPLACE "\"description\": \"[^\"]*\"" "\"description\": \"take 2\"" edited "${spec_text}")
file(WRITE "${shaders}/material.json" "${edited}")
run(${CMAKE_COMMAND} --build "${build}")
if(NOT last_output MATCHES "material_shaders.shadergen: .*output unchanged" OR last_output MATCHES "material_kinds"
   OR last_output MATCHES "Building CXX")
  message(FATAL_ERROR "an edit of the description alone must rerun material.json's shadergen and nothing else:\n${last_output}")
endif()

execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
file(READ "${shaders}/material.frag" shader)
string(REPLACE "colour = 0.03 * base.rgb;" "colour = 0.031 * base.rgb;" edited "${shader}")
if(edited STREQUAL shader)
  message(FATAL_ERROR "material.frag no longer holds \"colour = 0.03 * base.rgb;\", the edit section 7 times")
endif()
file(WRITE "${shaders}/material.frag" "${edited}")
run(${CMAKE_COMMAND} --build "${build}")
if(NOT last_output MATCHES "\\(24 compiled, 2 cached\\)" OR NOT last_output MATCHES "\\(3 compiled, 2 cached\\)"
   OR NOT last_output MATCHES "material_shaders.cpp.o" OR last_output MATCHES "main.cpp.o|kinds.cpp.o")
  message(FATAL_ERROR "an edit of material.frag must recompile 24 + 3 sources and the generated .cpp files, "
                      "not main.cpp or kinds.cpp:\n${last_output}")
endif()
run("${build}/material_check")

file(TOUCH "${shaders}/include/unused.glsl")
run(${CMAKE_COMMAND} --build "${build}")
if(NOT last_output MATCHES "no work to do")
  message(FATAL_ERROR "a new file in shaders/include/ that nothing includes rebuilt something:\n${last_output}")
endif()
step_done("the edit-rebuild loop runs what section 7 says")
