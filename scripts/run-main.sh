#!/bin/sh
# The main job: install what is missing, build, compile every permutation of the Split/Second
# domain, then render the tile-classified frame with tilelight at 1280x720 on lavapipe: prints
# the Table-4.2-style timings and writes build/main/tilelight/{frame_classified.png,
# frame_naive.png, tile_classes.png, report.json}.
set -eu
cd "$(dirname "$0")/.."

./scripts/install-deps.sh
cmake --preset release  # CMakePresets.json: build/release, Release, no tests
cmake --build --preset release

shadergen=build/release/shadergen/shadergen
"$shadergen" lut permutations/split_second.json
"$shadergen" build permutations/split_second.json --out build/main/split_second --stats
echo "main: manifest, SPIR-V and generated C++ are in build/main/split_second"

build/release/runtime/app/tilelight --width 1280 --height 720 --frames 5 --out build/main/tilelight
