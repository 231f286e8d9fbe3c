#!/bin/sh
# The test suite by tiers (ctest labels, tests/tiers.cmake; docs/ci.md has the counts and times):
#   scripts/run-tests.sh           install what is missing, build with tests, run the default
#                                  tier and the GPU benchmark's smoke run on lavapipe (what the
#                                  README asks for: one build; docs/ci.md has its cold time)
#   scripts/run-tests.sh --all     and the long tier, then the sanitizer build (ASan + UBSan)
#                                  and its tier
#   scripts/run-tests.sh --lint    and scripts/lint.sh (clang-format, clang-tidy) on the test
#                                  build, right after it is built; a finding fails the run once
#                                  every suite has run. CI runs --all --lint (.ci/run).
#   scripts/run-tests.sh --quick   the edit loop: build what changed, run the quick tier (a few
#                                  minutes), nothing else
# Options combine (--all --lint). Every run ends with a table of its stages and their wall
# seconds and, for each suite, its ten slowest tests from ctest's own timings, whether it passed
# or not. A failing suite does not stop the later ones, so one report shows everything; a failed
# build stops what needs it. Exit status: 0 when every stage that ran passed.
set -eu
cd "$(dirname "$0")/.."

all=0
lint=0
quick=0
for arg in "$@"; do
  case "$arg" in
    --all) all=1 ;;
    --lint) lint=1 ;;
    --quick) quick=1 ;;
    -h | --help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: $0 [--all] [--lint] [--quick] (--help explains them)" >&2; exit 2 ;;
  esac
done
if [ "$quick" = 1 ] && [ "$all" = 1 ]; then
  echo "run-tests: --quick and --all exclude each other" >&2
  exit 2
fi

report_dir=build/run-tests
mkdir -p "$report_dir"
stages="$report_dir/stages.tsv"
slowest="$report_dir/slowest.txt"
: >"$stages"
: >"$slowest"
failed=0
run_start=$(date +%s)

# stage NAME COMMAND...: runs COMMAND, records NAME, its wall seconds and its result.
stage() {
  name=$1
  shift
  echo "run-tests: == $name: $*"
  start=$(date +%s)
  status=0
  "$@" || status=$?
  seconds=$(($(date +%s) - start))
  if [ "$status" -eq 0 ]; then result=passed; else result="FAILED (exit $status)"; failed=1; fi
  printf '%s\t%s\t%s\n' "$name" "$seconds" "$result" >>"$stages"
  return "$status"
}

skipped() { printf '%s\t-\t%s\n' "$1" "$2" >>"$stages"; }

# ctest_tier PRESET LOG CTEST-ARGS...: ctest, its output shown and kept in LOG; ctest's status.
ctest_tier() {
  preset=$1
  log=$2
  shift 2
  {
    rc=0
    ctest --preset "$preset" "$@" || rc=$?
    echo "$rc" >"$log.rc"
  } 2>&1 | tee "$log"
  return "$(cat "$log.rc")"
}

# suite NAME PRESET CTEST-ARGS...: one tier under ctest, then its ten slowest tests, from
# ctest's own line per test ("  12/345 Test  #67: name ......   Passed   12.34 sec").
suite() {
  name=$1
  preset=$2
  shift 2
  log="$report_dir/$(echo "$name" | tr ' ' '-').log"
  status=0
  stage "$name" ctest_tier "$preset" "$log" "$@" || status=$?
  {
    echo "$name: the ten slowest tests (seconds, ctest's timings)"
    sed -nE 's/^ *[0-9]+\/[0-9]+ +Test +#[0-9]+: (.*[^ ]) \.{3,} .*[^0-9.]([0-9]+\.[0-9]+) sec$/\2 \1/p' "$log" |
      sed 's/  # GetParam() = .*//' | sort -rn | head -n 10 | awk '{ printf "  %8.1f  %s\n", $1, substr($0, index($0, " ") + 1) }'
    grep -E '^[0-9]+% tests passed' "$log" | sed 's/^/  /' || true
  } >>"$slowest"
  return "$status"
}

report() {
  echo
  echo "run-tests: stages (wall seconds)"
  awk -F '\t' '{ printf "  %-22s %7s  %s\n", $1, $2, $3 }' "$stages"
  printf '  %-22s %7s\n' total "$(($(date +%s) - run_start))"
  if [ -s "$slowest" ]; then
    echo
    cat "$slowest"
  fi
  echo "run-tests: the table is also in $stages"
}
trap report EXIT

stage install ./scripts/install-deps.sh --tests
# ccache when it is there (scripts/ccache-launcher.sh sets $launcher).
# shellcheck source=scripts/ccache-launcher.sh
. scripts/ccache-launcher.sh

# The presets (CMakePresets.json) build in build/tests and build/sanitize. Tests pass their own
# scratch cache folders; the presets' SHADERGEN_CACHE_DIR keeps the build-time shadergen runs of
# the test targets out of the user's cache as well. ctest runs 2 jobs, a 900 s timeout per test,
# output on failure.
# shellcheck disable=SC2086 # $launcher is empty or one word
stage configure cmake --preset tests $launcher
stage build cmake --build --preset tests

# Every test is in exactly one of the tiers default and long (tests/tiers.cmake): one that is in
# neither would run nowhere, silently.
tier_check() {
  all_tests=$(ctest --preset tests -N | sed -n 's/^Total Tests: //p')
  tiered=$(ctest --preset tests -N -L '^(default|long)$' | sed -n 's/^Total Tests: //p')
  if [ "$all_tests" != "$tiered" ]; then
    echo "run-tests: $((all_tests - tiered)) of $all_tests tests have no tier (tests/tiers.cmake):" >&2
    ctest --preset tests -N -LE '^(default|long)$' | grep 'Test *#' >&2
    return 1
  fi
  echo "run-tests: $all_tests tests: $(ctest --preset tests -N -L '^default$' | sed -n 's/^Total Tests: //p') default, $(ctest --preset tests -N -L '^long$' | sed -n 's/^Total Tests: //p') long"
}
stage "tier check" tier_check

# clang-tidy needs the compile commands and the generated headers of this build, so the lint
# runs here, before the suites; its findings do not stop them.
if [ "$lint" = 1 ]; then
  stage lint ./scripts/lint.sh || true
else
  skipped lint "not asked (--lint)"
fi

if [ "$quick" = 1 ]; then
  suite "quick tier" tests -L '^quick$' || true
  exit "$failed"
fi

suite "default suite" tests -L '^default$' || true

# The GPU benchmark's procedure (scripts/gpu-bench.sh, docs/gpu-bench.md) on lavapipe with the
# test build's binaries: the device-side script, its tables and JSON, in about 10 s. The GPU run
# itself happens on a lent machine, where nothing can be fixed; this keeps the script from rotting.
stage "GPU-bench smoke" ./scripts/gpu-bench.sh --quick || true

if [ "$all" = 0 ]; then
  skipped "long tier" "not asked (--all)"
  skipped "sanitizer build" "not asked (--all)"
  skipped "sanitizer suite" "not asked (--all)"
  exit "$failed"
fi

suite "long tier" tests -L '^long$' || true

# AddressSanitizer + UndefinedBehaviorSanitizer (cmake/Sanitizers.cmake) on what the sanitizer
# tier needs, the shadergen runs at build time and the lavapipe tests included. The sanitizer
# options and the driver-only leak suppressions are built into the executables
# (cmake/sanitizers/), so a plain `ctest -L sanitizer` in build/sanitize behaves the same.
sanitizer_build() {
  # shellcheck disable=SC2086 # $launcher is empty or one word
  cmake --preset sanitize $launcher && cmake --build --preset sanitize
}
if stage "sanitizer build" sanitizer_build; then
  suite "sanitizer suite" sanitize -L '^sanitizer$' || true
else
  skipped "sanitizer suite" "its build failed"
fi
exit "$failed"
