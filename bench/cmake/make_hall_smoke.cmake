# Smoke run of tilelight_make_hall: a small hall is written, and tilelight draws it from the view
# the generator suggests under validation, with culling; report.json must count the triangles the
# generator printed, cull some batches behind the eye, and show no pixel differing.
# Arguments: -DMAKE_HALL=<tilelight_make_hall> -DTILELIGHT=<tilelight> -DOUT=<scratch folder>.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND "${MAKE_HALL}" --out "${OUT}/hall.glb" --bays 4 --column-segments 12 --column-rings 6
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tilelight_make_hall exited with ${rc}\n${stdout}\n${stderr}")
endif()
if(NOT stdout MATCHES "hall.glb: ([0-9]+) triangles in ([0-9]+) meshes" )
  message(FATAL_ERROR "no triangle count in:\n${stdout}")
endif()
set(triangles "${CMAKE_MATCH_1}")
if(NOT stdout MATCHES "--eye ([-0-9.e,]+) --target ([-0-9.e,]+)")
  message(FATAL_ERROR "no suggested view in:\n${stdout}")
endif()
set(eye "${CMAKE_MATCH_1}")
set(target "${CMAKE_MATCH_2}")

execute_process(COMMAND "${TILELIGHT}" --scene "${OUT}/hall.glb" --eye "${eye}" --target "${target}"
  --width 96 --height 54 --validation --out "${OUT}/frame"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tilelight --scene hall.glb exited with ${rc}\n${stdout}\n${stderr}")
endif()
file(READ "${OUT}/frame/report.json" report)
string(JSON drawn GET "${report}" scene_triangles)
string(JSON culled GET "${report}" culled gbuffer_batches)
string(JSON differ GET "${report}" equivalence pixels_different)
if(NOT drawn EQUAL triangles OR NOT culled GREATER 0 OR NOT differ EQUAL 0)
  message(FATAL_ERROR "report.json: ${drawn} triangles (generator: ${triangles}), ${culled} G-buffer batches culled, ${differ} pixels differ")
endif()

# A bad option: exit 2 (CLI11's usage error), nothing written.
execute_process(COMMAND "${MAKE_HALL}" --out "${OUT}/bad.glb" --bays 0
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(rc EQUAL 0 OR EXISTS "${OUT}/bad.glb")
  message(FATAL_ERROR "--bays 0 was accepted (exit ${rc})")
endif()
