# shellcheck shell=sh
# shellcheck disable=SC2034 # launcher is read by the scripts that source this one
# Sourced by the build scripts (scripts/run-tests.sh, scripts/gpu-bench.sh): sets `launcher` to
# the CMake option that compiles through ccache when it is installed (install-deps --tests), or to
# nothing. A cold run gains nothing, a repeat run on the same machine recompiles only what
# changed. Paths under this checkout are hashed relative to it (CCACHE_BASEDIR,
# CCACHE_NOHASHDIR), so a fresh clone anywhere on the machine hits what another clone compiled;
# scripts/lint.sh's clang-tidy cache does the same. Run from the checkout's root.
launcher=""
if command -v ccache >/dev/null; then
  launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
  CCACHE_BASEDIR=$(pwd)
  CCACHE_NOHASHDIR=1
  export CCACHE_BASEDIR CCACHE_NOHASHDIR
fi
