# area_library(<prefix> <area> SOURCES <file>... [SOURCE_FOLDER <folder>] [PUBLIC <target>...]
#              [PRIVATE <target>...])
#
# One area of a tool as a static library, made the same way in shadergen (shadergen_area(),
# shadergen/CMakeLists.txt) and the runtime (tilelight_library(), TilelightLibrary.cmake):
# target <prefix>_<area>, alias <prefix>::<area>, C++20, its sources listed once (relative to
# SOURCE_FOLDER when given), the project's warnings. PUBLIC and PRIVATE are passed to
# target_link_libraries(). The callers add what differs: where their headers live.
function(area_library prefix area)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "SOURCE_FOLDER" "SOURCES;PUBLIC;PRIVATE")
  if(arg_UNPARSED_ARGUMENTS OR NOT arg_SOURCES)
    message(FATAL_ERROR "${prefix} library ${area}: expected SOURCES, PUBLIC and PRIVATE lists, "
                        "got '${arg_UNPARSED_ARGUMENTS}'")
  endif()
  if(arg_SOURCE_FOLDER)
    list(TRANSFORM arg_SOURCES PREPEND ${arg_SOURCE_FOLDER}/)
  endif()
  set(target ${prefix}_${area})
  add_library(${target} STATIC ${arg_SOURCES})
  add_library(${prefix}::${area} ALIAS ${target})
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${arg_PUBLIC} PRIVATE ${arg_PRIVATE} shadergen::warnings)
endfunction()
