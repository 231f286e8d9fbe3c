# Warnings live in an INTERFACE target that project targets link PRIVATE, so they never leak
# into consumers and no global flags are set.
add_library(shadergen_warnings INTERFACE)
add_library(shadergen::warnings ALIAS shadergen_warnings)
target_compile_options(shadergen_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual>
  $<$<CXX_COMPILER_ID:MSVC>:/W4 /permissive->)
