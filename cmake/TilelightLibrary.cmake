# tilelight_library(<area> SOURCES <file>... [PUBLIC <target>...] [PRIVATE <target>...])
#
# One runtime library, the same way for every area (docs/architecture.md): target
# tilelight_<area>, alias tilelight::<area>, its sources listed here and nowhere else, public
# headers in <folder>/include/tilelight/<area>/, private ones beside the sources, the project's
# warnings. PUBLIC and PRIVATE are passed to target_link_libraries().
function(tilelight_library area)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;PUBLIC;PRIVATE")
  if(arg_UNPARSED_ARGUMENTS OR NOT arg_SOURCES)
    message(FATAL_ERROR "tilelight_library(${area}): expected SOURCES, PUBLIC and PRIVATE lists, "
                        "got '${arg_UNPARSED_ARGUMENTS}'")
  endif()
  set(target tilelight_${area})
  add_library(${target} STATIC ${arg_SOURCES})
  add_library(tilelight::${area} ALIAS ${target})
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  target_link_libraries(${target} PUBLIC ${arg_PUBLIC} PRIVATE ${arg_PRIVATE} shadergen::warnings)
  # Vulkan structs are written `VkFoo info{VK_STRUCTURE_TYPE_FOO};` on purpose: every other
  # member starts zeroed, which -Wmissing-field-initializers would flag at every one of them.
  target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU,Clang>:-Wno-missing-field-initializers>)
endfunction()
