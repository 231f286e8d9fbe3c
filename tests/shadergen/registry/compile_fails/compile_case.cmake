# Compiles typed_ids.cpp (syntax only) with -D<CASE>, or with no case for the control, and
# checks the outcome: the control must compile, a case must fail with a diagnostic matching
# EXPECT (the compiler's words about the mixed types), so a case cannot pass by failing for an
# unrelated reason such as a missing header.
#   cmake -DCXX=<compiler> -DINCLUDES=<dir|dir> -DSOURCE=<file> [-DCASE=<macro> -DEXPECT=<regex>]
#         -P compile_case.cmake
# In EXPECT, <line> stands for "anything on the same line" ([^\n]*, which an argument cannot
# easily carry). The compiler runs with LC_ALL=C so that its quotes are plain apostrophes.
string(REPLACE "|" ";" include_dirs "${INCLUDES}")
set(flags -std=c++20 -fsyntax-only)
foreach(dir IN LISTS include_dirs)
  list(APPEND flags "-I${dir}")
endforeach()
if(CASE)
  list(APPEND flags "-D${CASE}")
endif()
string(REPLACE "<line>" "[^\n]*" EXPECT "${EXPECT}")
execute_process(COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C ${CXX} ${flags} ${SOURCE}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT CASE)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the control does not compile, so no case below proves anything:\n${out}")
  endif()
  message(STATUS "the control compiles")
  return()
endif()
if(rc EQUAL 0)
  message(FATAL_ERROR "${CASE} compiles: the types let the mix through")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "${CASE} fails, but not for the expected reason (/${EXPECT}/):\n${out}")
endif()
message(STATUS "${CASE} is refused: ${CMAKE_MATCH_0}")
