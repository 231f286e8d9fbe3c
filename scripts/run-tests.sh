#!/bin/sh
# Every test: install what is missing, build with tests, run the whole CTest suite and the GPU
# benchmark's smoke run on lavapipe (scripts/gpu-bench.sh --quick); then the same suite again in
# a sanitizer build.
#   scripts/run-tests.sh          the suite, twice (what the README asks for)
#   scripts/run-tests.sh --lint   and scripts/lint.sh (clang-format, clang-tidy) on the test
#                                 build, right after it is built; a finding makes the script fail
#                                 once both suites have run (what CI runs: .ci/run)
set -eu
cd "$(dirname "$0")/.."

lint=0
case "${1:-}" in
  "") ;;
  --lint) lint=1 ;;
  *) echo "usage: $0 [--lint]" >&2; exit 2 ;;
esac

./scripts/install-deps.sh --tests
# ccache when it is there (scripts/ccache-launcher.sh sets $launcher).
# shellcheck source=scripts/ccache-launcher.sh
. scripts/ccache-launcher.sh

# The presets (CMakePresets.json) build in build/tests and build/sanitize. Tests pass their own
# scratch cache folders; the presets' SHADERGEN_CACHE_DIR keeps the build-time shadergen runs of
# the test targets (and the outside-consumer project) out of the user's cache as well. ctest
# runs 2 jobs, a 900 s timeout per test, output on failure.
# shellcheck disable=SC2086 # $launcher is empty or one word
cmake --preset tests $launcher
cmake --build --preset tests

# clang-tidy needs the compile commands and the generated headers of this build, so the lint
# runs here, before the suite; its findings do not stop the suite.
lint_status=0
if [ "$lint" = 1 ]; then
  ./scripts/lint.sh || lint_status=$?
fi

ctest --preset tests

# The GPU benchmark's procedure (scripts/gpu-bench.sh, docs/gpu-bench.md) on lavapipe with the
# test build's binaries: the device-side script, its tables and JSON, in about 20 s. The GPU run
# itself happens on a lent machine, where nothing can be fixed; this keeps the script from rotting.
./scripts/gpu-bench.sh --quick

# AddressSanitizer + UndefinedBehaviorSanitizer on every target (cmake/Sanitizers.cmake), the
# shadergen runs at build time and the lavapipe tests included. The sanitizer options and the
# driver-only leak suppressions are built into the executables (cmake/sanitizers/), so a plain
# `ctest` in build/sanitize behaves the same.
# shellcheck disable=SC2086
cmake --preset sanitize $launcher
cmake --build --preset sanitize
ctest --preset sanitize

if [ "$lint_status" -ne 0 ]; then
  echo "run-tests: the suite passed, but scripts/lint.sh failed (exit $lint_status, findings above)" >&2
  exit "$lint_status"
fi
