#!/bin/sh
# The project's style checks, by hand, before a commit and in CI (.ci/run: scripts/run-tests.sh
# --lint runs this after the test build; the suite runs the clang-format half on its own as the
# test style.clang_format, so a plain ctest still checks the layout):
#   scripts/lint.sh            clang-format over every tracked C++ file, then clang-tidy
#                              (.clang-tidy) over the product's sources (shadergen/, runtime/,
#                              common/) in build/tests/compile_commands.json: what CI runs
#   scripts/lint.sh --all      clang-tidy over the tests' and benchmarks' sources as well
#                              (tests/.clang-tidy), by hand: about twice the time (docs/ci.md)
#   scripts/lint.sh --format   clang-format only
# BUILD_DIR=<folder> names another configured build (any build type; compile commands are
# exported by every preset). Exit status: non-zero when either tool reports anything.
set -eu
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build/tests}

need() {
  command -v "$1" >/dev/null || { echo "lint: $1 not found (Debian 12: apt-get install $2)" >&2; exit 2; }
}
need clang-format clang-format

# Tracked C++ sources only: generated code lives in build trees and is not ours to format.
# Outside a git checkout (a source archive), every C++ file outside build folders.
if ! sources=$(git ls-files '*.cpp' '*.h' 2>/dev/null); then
  sources=$(find . -path './build*' -prune -o -path './.*' -prune -o \( -name '*.cpp' -o -name '*.h' \) -print)
fi
echo "lint: clang-format --dry-run over $(echo "$sources" | wc -l) files"
# shellcheck disable=SC2086 # one word per file name; the repository has no spaces in paths
clang-format --dry-run --Werror $sources

[ "${1:-}" = "--format" ] && exit 0

need clang-tidy clang-tidy
need python3 python3
need ninja ninja-build

if [ ! -f "$build_dir/compile_commands.json" ]; then
  echo "lint: $build_dir/compile_commands.json is missing: configure first (cmake --preset tests)" >&2
  exit 2
fi
# GCC-only warning flags in the compile commands are not clang-tidy's business. A file whose
# source, headers, compile command and .clang-tidy files are unchanged since an earlier lint on
# this machine is not linted again (scripts/clang-tidy-cached: the cache, where it lives,
# LINT_CACHE_DIR=off).
scope="shadergen|runtime|common"
[ "${1:-}" = "--all" ] && scope="shadergen|runtime|common|bench|tests"
echo "lint: clang-tidy over the sources of $scope in $build_dir"
tidy_status=0
scripts/clang-tidy-cached -p "$build_dir" -j "$(nproc)" --extra-arg=-Wno-unknown-warning-option \
  "^$(pwd)/($scope)/.*\.cpp$" >"$build_dir/clang-tidy.log" || tidy_status=$?
# One line per finding, "file:line:col: warning: text [check]", colour codes removed.
sed 's/\x1b\[[0-9;]*m//g' "$build_dir/clang-tidy.log" |
  grep -E '^/.*:[0-9]+:[0-9]+: (warning|error): .*\]$' | sort -u >"$build_dir/clang-tidy.findings" || true
if [ -s "$build_dir/clang-tidy.findings" ]; then
  cat "$build_dir/clang-tidy.findings"
  echo "lint: clang-tidy reported $(wc -l <"$build_dir/clang-tidy.findings") finding(s); full log: $build_dir/clang-tidy.log" >&2
  exit 1
fi
if [ "$tidy_status" -ne 0 ]; then
  echo "lint: clang-tidy failed (exit $tidy_status) without a finding; full log: $build_dir/clang-tidy.log" >&2
  exit 1
fi
echo "lint: clean"
