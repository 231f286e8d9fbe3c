# Installs shadergen into a scratch prefix and builds tests/consumer against it, then checks
# the build-time integration: a no-op rebuild does nothing; touching an included GLSL file
# reruns shadergen; touching a file the domain does not read reruns nothing.
#
# cmake -DBUILD_DIR=<shadergen build> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P outside_consumer.cmake
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "outside_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
set(domain "${WORK_DIR}/domain")
set(consumer_build "${WORK_DIR}/build")

run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
file(COPY "${SOURCE_DIR}/tests/fixtures/toy/" DESTINATION "${domain}")
file(WRITE "${domain}/unrelated.glsl" "// not read by the domain\n")

run(${CMAKE_CTEST_COMMAND} --build-and-test "${SOURCE_DIR}/tests/consumer" "${consumer_build}"
    --build-generator Ninja
    --build-options "-DCMAKE_PREFIX_PATH=${prefix}" "-DCONSUMER_DOMAIN=${domain}/toy.json"
                    "-DCMAKE_BUILD_TYPE=Release"
    --test-command consumer_app)
message(STATUS "configure + build + run: ok")

run(${CMAKE_COMMAND} --build "${consumer_build}")
if(NOT last_output MATCHES "no work to do")
  message(FATAL_ERROR "a no-op rebuild did work:\n${last_output}")
endif()
message(STATUS "no-op rebuild: ok")

file(TOUCH "${domain}/unrelated.glsl")
run(${CMAKE_COMMAND} --build "${consumer_build}")
if(NOT last_output MATCHES "no work to do")
  message(FATAL_ERROR "touching a file the domain does not read rebuilt something:\n${last_output}")
endif()
message(STATUS "touching an unrelated file: ok")

# Sleep so the touch is newer than the outputs even on file systems with coarse timestamps.
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
file(TOUCH "${domain}/include/particle_common.glsl")
run(${CMAKE_COMMAND} --build "${consumer_build}")
if(NOT last_output MATCHES "shadergen: compiling the permutations")
  message(FATAL_ERROR "touching an included GLSL file did not rerun shadergen:\n${last_output}")
endif()
if(last_output MATCHES "consumer_app.dir/main.cpp")
  message(FATAL_ERROR "an edit that changes no SPIR-V recompiled the consumer's own code:\n${last_output}")
endif()
run(${CMAKE_COMMAND} --build "${consumer_build}")
if(NOT last_output MATCHES "no work to do")
  message(FATAL_ERROR "the build after the include edit is not stable:\n${last_output}")
endif()
message(STATUS "rebuild after touching an include: ok")

execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
file(READ "${domain}/particle.frag" shader)
string(REPLACE "color.rg += 0.1 * in_uv;" "color.rg += 0.2 * in_uv;" shader "${shader}")
file(WRITE "${domain}/particle.frag" "${shader}")
run(${CMAKE_COMMAND} --build "${consumer_build}")
if(NOT last_output MATCHES "consumer_shaders.cpp")
  message(FATAL_ERROR "editing a shader did not recompile the generated registry:\n${last_output}")
endif()
run("${consumer_build}/consumer_app")
message(STATUS "rebuild after editing the uber-shader: ok")
