# Smoke run of shadergen_scale_chart on the --json of a quick shadergen_scale_bench run: the
# bench must exit 0, the chart must be a PNG file, and a file that is not the bench's JSON must
# be refused with exit 1 and a message naming it. Timings are not looked at.
# Arguments: -DBENCH=<shadergen_scale_bench> -DCHART=<shadergen_scale_chart> -DOUT=<scratch folder>.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND "${BENCH}" --features 8,10 --shard-features 8 --shards 2 --secret signed --json "${OUT}/scale.json"
                        --work "${OUT}/work"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "shadergen_scale_bench exited with ${rc}\nstdout:\n${stdout}\nstderr:\n${stderr}")
endif()
execute_process(COMMAND "${CHART}" "${OUT}/scale.json" "${OUT}/scale.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "shadergen_scale_chart exited with ${rc}\nstderr:\n${stderr}")
endif()
file(READ "${OUT}/scale.png" magic LIMIT 8 HEX)
if(NOT magic STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "${OUT}/scale.png is not a PNG file (starts with ${magic})")
endif()
file(WRITE "${OUT}/not-scale.json" "{\"configurations\": []}\n")
execute_process(COMMAND "${CHART}" "${OUT}/not-scale.json" "${OUT}/other.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 1 OR NOT stderr MATCHES "not-scale.json: error: not the --json file of shadergen_scale_bench")
  message(FATAL_ERROR "a foreign JSON gave exit ${rc} and stderr:\n${stderr}")
endif()
if(EXISTS "${OUT}/other.png")
  message(FATAL_ERROR "a refused JSON still wrote ${OUT}/other.png")
endif()
