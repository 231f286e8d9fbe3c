#!/bin/sh
# scripts/clang-tidy-cached on a two-file project of its own, with a stand-in clang-tidy that
# logs each file it is asked to lint and reports a finding where a file says PROBE: what is
# linted again after each kind of change, what is replayed, and that two clones at different
# paths share the cache.
#   usage: clang_tidy_cache_test.sh <scripts/clang-tidy-cached> <scratch folder>
set -eu
script=$1
work=$2
rm -rf "$work"
mkdir -p "$work/bin"
work=$(cd "$work" && pwd)
log=$work/linted.log
: >"$log"

cat >"$work/bin/clang-tidy" <<EOF
#!/bin/sh
[ "\$1" = --version ] && { echo "stand-in clang-tidy 1"; exit 0; }
for file; do :; done
echo "\$file" >>"$log"
if grep -q PROBE "\$file"; then echo "\$file:1:1: warning: probe found [stand-in-check]"; fi
EOF
chmod +x "$work/bin/clang-tidy"

fail() { echo "clang_tidy_cache_test: $*" >&2; exit 1; }

make_project() {
  mkdir -p "$1"
  printf 'cmake_minimum_required(VERSION 3.25)\nproject(probe CXX)\nadd_library(probe STATIC one.cpp two.cpp)\n' \
    >"$1/CMakeLists.txt"
  printf '#pragma once\ninline int shared() { return 1; }\n' >"$1/shared.h"
  printf '#include "shared.h"\nint one() { return shared(); }\n' >"$1/one.cpp"
  printf 'int two() { return 2; }\n' >"$1/two.cpp"
  printf 'Checks: "-*"\n' >"$1/.clang-tidy"
}

build() { cmake --build "$1/build" >/dev/null; }

configure() {
  cmake -S "$1" -B "$1/build" -G Ninja -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
  build "$1"
}

# Lints project $1; $2: how many files it must have linted (not replayed) this time.
lint() {
  before=$(wc -l <"$log")
  (cd "$1" && PATH="$work/bin:$PATH" LINT_CACHE_DIR="$work/cache" "$script" -p build -j 2 "^$1/[a-z]+\.cpp$") \
    >"$work/out" 2>"$work/err" || fail "clang-tidy-cached exited non-zero: $(cat "$work/err")"
  linted=$(($(wc -l <"$log") - before))
  [ "$linted" -eq "$2" ] || fail "step '$3': linted $linted file(s), expected $2 ($(tail -n "$linted" "$log" | tr '\n' ' '))"
}

a=$work/a
make_project "$a"
configure "$a"
lint "$a" 2 "first run"
lint "$a" 0 "nothing changed"
grep -q "one.cpp" "$work/out" || fail "a replayed run does not print what clang-tidy printed"

printf '// edited\n' >>"$a/shared.h"
build "$a"
lint "$a" 1 "a header changed"
tail -n 1 "$log" | grep -q "/one.cpp$" || fail "the header edit re-linted $(tail -n 1 "$log"), not one.cpp"

printf 'Checks: "-*,bugprone-*"\n' >"$a/.clang-tidy"
lint "$a" 2 ".clang-tidy changed"

b=$work/elsewhere/b
make_project "$b"
printf '// edited\n' >>"$b/shared.h"
printf 'Checks: "-*,bugprone-*"\n' >"$b/.clang-tidy"
configure "$b"
lint "$b" 0 "a clone at another path"
grep -q "$b/one.cpp" "$work/out" || fail "the replay names the other clone's paths: $(cat "$work/out")"

printf 'int two() { return 3; }\n' >"$a/two.cpp"
lint "$a" 1 "a source changed, not rebuilt"
lint "$a" 1 "still not rebuilt: nothing may be cached"
build "$a"
lint "$a" 1 "rebuilt"
lint "$a" 0 "rebuilt, again"

printf '// PROBE\nint two() { return 3; }\n' >"$a/two.cpp"
build "$a"
lint "$a" 1 "a finding"
grep -q "two.cpp:1:1: warning: probe found" "$work/out" || fail "the finding is not printed"
lint "$a" 0 "the finding, replayed"
grep -q "$a/two.cpp:1:1: warning: probe found" "$work/out" || fail "the replay lost the finding: $(cat "$work/out")"

rm -rf "$work"
echo "clang_tidy_cache_test: passed"
