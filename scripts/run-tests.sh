#!/bin/sh
# Every test: install what is missing, build with tests, run the whole CTest suite; then the
# same suite again in a sanitizer build.
set -eu
cd "$(dirname "$0")/.."

./scripts/install-deps.sh
cmake -S . -B build/tests -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADERGEN_BUILD_TESTS=ON
# Tests pass their own scratch cache folders; this keeps the build-time shadergen runs of the
# test targets (and the outside-consumer project) out of the user's cache as well.
SHADERGEN_CACHE_DIR="$PWD/build/tests/shadergen-cache"
export SHADERGEN_CACHE_DIR
cmake --build build/tests
ctest --test-dir build/tests --output-on-failure --timeout 900 -j 2

# AddressSanitizer + UndefinedBehaviorSanitizer on every target (cmake/Sanitizers.cmake), the
# shadergen runs at build time and the lavapipe tests included. The sanitizer options and the
# driver-only leak suppressions are built into the executables (tests/sanitizers/), so a plain
# `ctest` in build/sanitize behaves the same.
cmake -S . -B build/sanitize -G Ninja -DSANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADERGEN_BUILD_TESTS=ON
SHADERGEN_CACHE_DIR="$PWD/build/sanitize/shadergen-cache"
cmake --build build/sanitize
ctest --test-dir build/sanitize --output-on-failure --timeout 900 -j 2
