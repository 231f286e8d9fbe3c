#!/bin/sh
# Every test: install what is missing, build with tests, run the whole CTest suite; then the
# same suite again in a sanitizer build.
set -eu
cd "$(dirname "$0")/.."

./scripts/install-deps.sh --tests
# The presets (CMakePresets.json) build in build/tests and build/sanitize. Tests pass their own
# scratch cache folders; the presets' SHADERGEN_CACHE_DIR keeps the build-time shadergen runs of
# the test targets (and the outside-consumer project) out of the user's cache as well. ctest
# runs 2 jobs, a 900 s timeout per test, output on failure.
cmake --preset tests
cmake --build --preset tests
ctest --preset tests

# AddressSanitizer + UndefinedBehaviorSanitizer on every target (cmake/Sanitizers.cmake), the
# shadergen runs at build time and the lavapipe tests included. The sanitizer options and the
# driver-only leak suppressions are built into the executables (tests/sanitizers/), so a plain
# `ctest` in build/sanitize behaves the same.
cmake --preset sanitize
cmake --build --preset sanitize
ctest --preset sanitize
