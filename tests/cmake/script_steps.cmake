# The two helpers of the test scripts that build outside projects (cmake -P): run() runs a
# command and fails the script with its output when it fails (its output is then in
# `last_output`); step_done() prints a step's name and the seconds since the previous step.
# Including this file starts the first step's clock.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction()

string(TIMESTAMP step_start "%s")
function(step_done what)
  string(TIMESTAMP now "%s")
  math(EXPR seconds "${now} - ${step_start}")
  message(STATUS "${what}: ok (${seconds} s)")
  set(step_start ${now} PARENT_SCOPE)
endfunction()
