# Smoke run of tilelight_sweep --scene: the baseline comparison on a glTF file (--quick), whose
# results.json must name the file and its triangles; a placed --eye view; a procedural camera
# with the file (exit 2); then a broken file, which must exit 1 naming it, before any output is
# written.
# Arguments: -DSWEEP=<tilelight_sweep> -DOUT=<scratch folder> -DSCENE=<a valid .glb> -DBAD=<a broken glTF>.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${SWEEP}" --quick --only baselines --scene "${SCENE}" --out "${OUT}/good"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tilelight_sweep --scene exited with ${rc}\nstdout:\n${stdout}\nstderr:\n${stderr}")
endif()
get_filename_component(scene_name "${SCENE}" NAME)
file(READ "${OUT}/good/results.json" results)
string(JSON scene GET "${results}" scene)
string(JSON triangles GET "${results}" scene_triangles)
string(JSON camera GET "${results}" configurations 0 camera)
if(NOT scene STREQUAL scene_name OR NOT triangles GREATER 0 OR NOT camera STREQUAL "default")
  message(FATAL_ERROR "results.json: scene '${scene}', ${triangles} triangles, camera '${camera}'")
endif()
string(FIND "${stdout}" "scene ${scene_name} (${triangles} triangles)" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the run line does not name the scene:\n${stdout}")
endif()

# A placed camera inside the file's box: the view "eye".
execute_process(COMMAND "${SWEEP}" --quick --only baselines --light-passes compute --scene "${SCENE}"
  --eye 0.2,0.3,0.9 --target 0,0,0 --fov 70 --cull on,off --out "${OUT}/eye"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tilelight_sweep --eye exited with ${rc}\nstderr:\n${stderr}")
endif()
file(READ "${OUT}/eye/results.json" results)
string(JSON camera GET "${results}" configurations 0 camera)
if(NOT camera STREQUAL "eye")
  message(FATAL_ERROR "results.json: camera '${camera}', not 'eye'")
endif()
# --cull on,off: each view with and without batch culling, the second row labelled so.
string(JSON cull0 GET "${results}" configurations 0 cull)
string(JSON cull1 GET "${results}" configurations 1 cull)
string(JSON culled1 GET "${results}" configurations 1 culled gbuffer_batches)
string(JSON warnings TYPE "${results}" scene_warnings)
string(FIND "${stdout}" "(no cull)" labelled)
if(NOT cull0 OR cull1 OR NOT culled1 EQUAL 0 OR NOT warnings STREQUAL "ARRAY" OR labelled EQUAL -1)
  message(FATAL_ERROR "--cull on,off: cull ${cull0} / ${cull1}, ${culled1} culled without culling, scene_warnings ${warnings}, stdout:\n${stdout}")
endif()

# A procedural camera with a file: a usage error, before any output.
execute_process(COMMAND "${SWEEP}" --quick --only baselines --scene "${SCENE}" --cameras street --out "${OUT}/street"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
string(FIND "${stderr}" "--camera street: the cameras sky, shadow, low, street, closeup belong to the procedural scene" at)
if(NOT rc EQUAL 2 OR at EQUAL -1 OR EXISTS "${OUT}/street")
  message(FATAL_ERROR "--cameras street with --scene: exit ${rc}, stderr:\n${stderr}")
endif()

execute_process(COMMAND "${SWEEP}" --quick --only baselines --scene "${BAD}" --out "${OUT}/bad"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
string(FIND "${stderr}" "error: --scene ${BAD}: " at)
if(NOT rc EQUAL 1 OR at EQUAL -1 OR EXISTS "${OUT}/bad")
  message(FATAL_ERROR "a broken --scene: exit ${rc}, stderr:\n${stderr}")
endif()
