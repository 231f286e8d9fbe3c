# Smoke run of tilelight_local_light_bench: --quick (2 and 4 lights, shadows off and rebuilt, at
# 96x54, one frame). It must exit 0 (which it does only where every volume image equals its
# full-screen image), write both files, and print a table row per light count and shadow mode
# with 0 pixels differing. Timings are not looked at.
# Then a light count past the procedural scene's 1024 lamps must be a usage error (exit 2).
# Arguments: -DBENCH=<tilelight_local_light_bench> -DOUT=<scratch folder>.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${BENCH}" --quick --out "${OUT}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tilelight_local_light_bench --quick exited with ${rc}\nstdout:\n${stdout}\nstderr:\n${stderr}")
endif()
foreach(name IN ITEMS results.json local_lights.png)
  file(SIZE "${OUT}/${name}" size)
  if(NOT EXISTS "${OUT}/${name}" OR size EQUAL 0)
    message(FATAL_ERROR "tilelight_local_light_bench --quick wrote no (or an empty) ${OUT}/${name}")
  endif()
endforeach()
foreach(lights IN ITEMS 2 4)
  foreach(shadows IN ITEMS off rebuilt)
    string(REGEX MATCH "\n\\| ${lights} \\| ${shadows} \\|[^\n]*\\| 0 \\|\n" row "${stdout}")
    if(row STREQUAL "")
      message(FATAL_ERROR "tilelight_local_light_bench --quick printed no row for ${lights} lights, shadows ${shadows}, "
                          "ending in 0 pixels differing\nstdout:\n${stdout}")
    endif()
  endforeach()
endforeach()
file(READ "${OUT}/results.json" json)
string(JSON count LENGTH "${json}" configurations)
if(NOT count EQUAL 8)
  message(FATAL_ERROR "results.json has ${count} configurations, expected 8 (2 light counts x 2 shadow modes x 2 passes)")
endif()
# With shadows rebuilt every frame, the maps are drawn in the timed frame too.
string(JSON maps GET "${json}" configurations 2 shadow_maps maps)
if(maps LESS 1)
  message(FATAL_ERROR "results.json: 2 lights with shadows rebuilt got ${maps} maps, expected at least 1")
endif()
string(JSON pass GET "${json}" configurations 1 local_light_pass)
if(NOT pass STREQUAL "fullscreen")
  message(FATAL_ERROR "results.json's second configuration is ${pass}, expected fullscreen")
endif()

execute_process(COMMAND "${BENCH}" --lights 2000 --out "${OUT}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 2 OR NOT stderr MATCHES "--lights")
  message(FATAL_ERROR "--lights 2000: expected exit 2 naming --lights, got ${rc}\nstderr:\n${stderr}")
endif()
