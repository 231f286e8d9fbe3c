#!/bin/sh
# The main job: install what is missing, build, and compile every permutation of the
# Split/Second domain (128 raw, 32 pruned, 32 optimised) into build/main/split_second.
set -eu
cd "$(dirname "$0")/.."

./scripts/install-deps.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DSHADERGEN_BUILD_TESTS=OFF
cmake --build build/release

shadergen=build/release/shadergen/shadergen
"$shadergen" lut permutations/split_second.json
"$shadergen" build permutations/split_second.json --out build/main/split_second --stats
echo "main: manifest, SPIR-V and generated C++ are in build/main/split_second"
