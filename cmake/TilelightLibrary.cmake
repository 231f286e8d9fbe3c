# tilelight_library(<area> SOURCES <file>... [PUBLIC <target>...] [PRIVATE <target>...])
#
# One runtime library, the same way for every area (docs/architecture.md): area_library()
# (AreaLibrary.cmake) as tilelight_<area>, alias tilelight::<area>, with public headers in
# <folder>/include/tilelight/<area>/ and private ones beside the sources.
include(${CMAKE_CURRENT_LIST_DIR}/AreaLibrary.cmake)

function(tilelight_library area)
  area_library(tilelight ${area} ${ARGN})
  target_include_directories(tilelight_${area} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  # Vulkan structs are written `VkFoo info{VK_STRUCTURE_TYPE_FOO};` on purpose: every other
  # member starts zeroed, which -Wmissing-field-initializers would flag at every one of them.
  target_compile_options(tilelight_${area} PRIVATE $<$<CXX_COMPILER_ID:GNU,Clang>:-Wno-missing-field-initializers>)
endfunction()
