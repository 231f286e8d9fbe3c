# Smoke run of tilelight_sweep: --quick (64x36 and 96x54, one frame), then every output file
# must exist and not be empty, and stdout must hold every comparison's table. Timings are not
# looked at. The tables also go into a copy of docs/results.md, which must then hold them.
# Arguments: -DSWEEP=<tilelight_sweep> -DOUT=<scratch folder> -DDOC=<docs/results.md>.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
file(COPY_FILE "${DOC}" "${OUT}/results.md")
execute_process(COMMAND "${SWEEP}" --quick --out "${OUT}" --update-doc "${OUT}/results.md"
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tilelight_sweep --quick exited with ${rc}\nstdout:\n${stdout}\nstderr:\n${stderr}")
endif()

foreach(name IN ITEMS results.json permutations.png tile_size.png index_path.png coalescing.png
                      primitive.png resolution.png stages.png baselines.png kinds.png)
  if(NOT EXISTS "${OUT}/${name}")
    message(FATAL_ERROR "tilelight_sweep --quick did not write ${OUT}/${name}")
  endif()
  file(SIZE "${OUT}/${name}" size)
  if(size EQUAL 0)
    message(FATAL_ERROR "tilelight_sweep --quick wrote an empty ${OUT}/${name}")
  endif()
endforeach()

foreach(heading IN ITEMS "### Optimised vs raw permutations (64x36)" "### Tile size 4 vs 8 vs 16 (64x36)"
                         "### CPU patching vs GPU-driven index build (64x36)"
                         "### Coalesced vs uncoalesced tiles (64x36)" "### Point sprites vs triangle pairs (64x36)"
                         "### Resolution scaling, naive vs classified"
                         "### Per-stage cost, naive vs classified (64x36)" "| 96x54 |"
                         "### Classified vs per-pixel branching (dynamic) vs naive" "| raster | 1x | 96x54 | closeup |"
                         "| compute | 1x | 96x54 | closeup |" "| raster, 4x MSAA, 96x54, CPU index build | 6 |"
                         "| compute, 4x MSAA, 96x54, CPU index build | 6 |"
                         "### Feature kinds: SKY and LIGHT_SCATTERING as variants, specialization constants, branches (64x36)"
                         "| raster | specialization | 28 (48) |" "| compute | branch | 28 (48) |")
  string(FIND "${stdout}" "${heading}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "tilelight_sweep --quick printed no '${heading}'\nstdout:\n${stdout}")
  endif()
endforeach()

# Every table of the page replaced: none of its 1280x720 rows (57600 tiles) is left, the tiny
# sizes' rows are there.
file(READ "${OUT}/results.md" doc)
foreach(row IN ITEMS "| 144 |" "| 96x54 |" "Device: ")
  string(FIND "${doc}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "tilelight_sweep --update-doc left no '${row}' in ${OUT}/results.md")
  endif()
endforeach()
string(FIND "${doc}" "| 57600 |" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "tilelight_sweep --update-doc left a 1280x720 row in ${OUT}/results.md")
endif()

# Every configuration must still draw the classified frame, and the dynamic one, equal to the naive one.
file(READ "${OUT}/results.json" json)
string(JSON count LENGTH "${json}" configurations)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON key GET "${json}" configurations ${i} key)
  string(JSON differ GET "${json}" configurations ${i} equivalence pixels_different)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "tilelight_sweep --quick: ${key}: ${differ} pixels differ between classified and naive")
  endif()
  string(JSON differ GET "${json}" configurations ${i} dynamic_equivalence pixels_different)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "tilelight_sweep --quick: ${key}: ${differ} pixels differ between dynamic and naive")
  endif()
endforeach()
