# Installs shadergen into a scratch prefix and builds tests/consumer against it, then checks
# the build-time integration: a no-op rebuild does nothing; touching an included GLSL file
# reruns shadergen; touching a file the domain does not read reruns nothing. The consumer
# includes shadergen/vulkan.h through find_package(shadergen ... COMPONENTS vulkan).
#
# cmake -DBUILD_DIR=<shadergen build> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P outside_consumer.cmake
#
# With -DSHADERGEN_ONLY=ON it installs, instead of BUILD_DIR, a shadergen-only build of SOURCE_DIR
# configured the way the README's recipe does it on a machine without Vulkan
# (-DSHADERGEN_BUILD_RUNTIME=OFF -DSHADERGEN_BUILD_TESTS=OFF -DSHADERGEN_BUILD_BENCH=OFF, and
# -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON standing in for the missing headers), in
# SHADERGEN_BUILD_DIR (default <WORK_DIR>/shadergen; removed when all passed), with the compiler
# settings of the cache script INIT_CACHE (-C; optional). The consumer is then built without
# Vulkan (CONSUMER_VULKAN=OFF, Vulkan disabled too), and asking that install for COMPONENTS
# vulkan with Vulkan disabled must fail to configure, saying why. The rebuild checks, which the
# default run makes, are skipped.
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "outside_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

include(${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake)  # run(), step_done()

# Disabling find_package(Vulkan) leaves the headers in /usr/include: fail if any object of the
# Ninja build in <dir> read one (`ninja -t deps`: every header each object read).
function(no_vulkan_header_in dir)
  run(${CMAKE_COMMAND} --build "${dir}" -- -t deps)
  if(last_output MATCHES "[^\n]*/vulkan/vulkan[_a-z0-9]*\\.h")
    message(FATAL_ERROR "${dir}: a build that must not need Vulkan read ${CMAKE_MATCH_0}")
  endif()
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
set(domain "${WORK_DIR}/domain")
set(consumer_build "${WORK_DIR}/build")

if(SHADERGEN_ONLY)
  if(NOT SHADERGEN_BUILD_DIR)
    set(SHADERGEN_BUILD_DIR "${WORK_DIR}/shadergen")
  endif()
  file(REMOVE_RECURSE "${SHADERGEN_BUILD_DIR}")
  set(init)
  if(INIT_CACHE)
    set(init -C "${INIT_CACHE}")
  endif()
  run(${CMAKE_COMMAND} ${init} -S "${SOURCE_DIR}" -B "${SHADERGEN_BUILD_DIR}" -G Ninja
      -DSHADERGEN_BUILD_RUNTIME=OFF -DSHADERGEN_BUILD_TESTS=OFF -DSHADERGEN_BUILD_BENCH=OFF
      -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON)
  if(NOT last_output MATCHES "no shadergen::vulkan")
    message(FATAL_ERROR "the shadergen-only configure did not say it went without Vulkan:\n${last_output}")
  endif()
  step_done("shadergen-only configure without Vulkan")
  run(${CMAKE_COMMAND} --build "${SHADERGEN_BUILD_DIR}" --parallel 2)
  no_vulkan_header_in("${SHADERGEN_BUILD_DIR}")
  step_done("shadergen-only build, no Vulkan header read")
  set(BUILD_DIR "${SHADERGEN_BUILD_DIR}")
  set(consumer_options -DCONSUMER_VULKAN=OFF -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON)
else()
  set(consumer_options -DCONSUMER_VULKAN=ON)
endif()

run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
foreach(file include/shadergen/registry.h include/shadergen/vulkan.h lib/cmake/shadergen/shadergenVulkanTargets.cmake)
  if(NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "the install has no ${file}")
  endif()
endforeach()
step_done("install")
file(COPY "${SOURCE_DIR}/tests/fixtures/toy/" DESTINATION "${domain}")
file(WRITE "${domain}/unrelated.glsl" "// not read by the domain\n")

run(${CMAKE_CTEST_COMMAND} --build-and-test "${SOURCE_DIR}/tests/consumer" "${consumer_build}"
    --build-generator Ninja
    --build-options "-DCMAKE_PREFIX_PATH=${prefix}" "-DCONSUMER_DOMAIN=${domain}/toy.json"
                    "-DCMAKE_BUILD_TYPE=Release" ${consumer_options}
    --test-command consumer_app)
step_done("consumer configure + build + run (${consumer_options})")
if(SHADERGEN_ONLY)
  no_vulkan_header_in("${consumer_build}")
  step_done("the consumer read no Vulkan header")
endif()

if(SHADERGEN_ONLY)
  # The same install, asked for the vulkan component where there is no Vulkan: the configure
  # must fail and say why (a pass here would mean the component was never looked at).
  execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/consumer" -B "${WORK_DIR}/build-vulkan" -G Ninja
                          "-DCMAKE_PREFIX_PATH=${prefix}" "-DCONSUMER_DOMAIN=${domain}/toy.json"
                          -DCONSUMER_VULKAN=ON -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "COMPONENTS vulkan configured without Vulkan:\n${out}\n${err}")
  endif()
  string(REGEX REPLACE "[ \t\r\n]+" " " flat "${out}${err}")  # CMake wraps long messages
  if(NOT flat MATCHES "shadergen's vulkan component .* needs the Vulkan headers, and find_package\\(Vulkan\\) did not find them")
    message(FATAL_ERROR "COMPONENTS vulkan without Vulkan failed, but not with the component's message:\n${out}\n${err}")
  endif()
  step_done("COMPONENTS vulkan without Vulkan fails with the component's message")
  file(REMOVE_RECURSE "${SHADERGEN_BUILD_DIR}")
  return()
endif()

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
