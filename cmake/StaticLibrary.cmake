# project_static_library(<target> <alias> SOURCES <file>... [PUBLIC <target>...] [PRIVATE <target>...])
#
# The one shape of this project's own static libraries, behind common_library() (common/) and
# tilelight_library() (runtime/): target <target>, alias <alias>, its sources listed here and
# nowhere else, public headers in <folder>/include/, private ones beside the sources, C++20 and
# the project's warnings (linked PRIVATE). PUBLIC and PRIVATE go to target_link_libraries().
function(project_static_library target alias)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "SOURCES;PUBLIC;PRIVATE")
  if(arg_UNPARSED_ARGUMENTS OR NOT arg_SOURCES)
    message(FATAL_ERROR "${alias}: expected SOURCES, PUBLIC and PRIVATE lists, got '${arg_UNPARSED_ARGUMENTS}'")
  endif()
  add_library(${target} STATIC ${arg_SOURCES})
  add_library(${alias} ALIAS ${target})
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  target_link_libraries(${target} PUBLIC ${arg_PUBLIC} PRIVATE ${arg_PRIVATE} shadergen::warnings)
endfunction()
