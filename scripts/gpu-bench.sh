#!/bin/sh
# GPU-ready in one command: build and pack here what the lent GPU machine needs to measure the
# classified frame against the full-frame baselines, or smoke-test the same procedure on
# lavapipe. `scripts/gpu-bench.sh --help` explains it all; docs/gpu-bench.md is the long form.
set -eu
cd "$(dirname "$0")/.."

pack_dir=gpu-pack
# The Vulkan loader and GL dispatch, extracted into / on the device (it has no loader), and what
# vulkaninfo needs beyond them, extracted into a scratch folder there (see scripts/gpu-bench-device.sh).
root_debs="libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2"
tool_debs="vulkan-tools libxext6 libx11-6 libxcb1 libwayland-client0 libxau6 libxdmcp6 libbsd0 libmd0"
# What the device tool carries: the working tree and the carried paths together.
limit_mib=64
run_timeout_s=420

usage() {
  cat <<EOF
usage: scripts/gpu-bench.sh --pack | --quick | --help

Measures tilelight's tile-classified frame against the full-frame baselines (naive, dynamic,
floor) on the lent GPU machine (the device tool's H100 or H200: x86-64, the NVIDIA driver and
its Vulkan ICD, but no compiler, no package registry and no Vulkan loader), in one call of
about 5 minutes. Everything is prepared here.

  --pack    1. configures and builds the release preset (build/release): tilelight and
               tilelight_sweep (about 10 minutes from cold; ccache is used when installed),
            2. fills $pack_dir/ (ignored by git) with
                 bin/       both binaries, stripped
                 lib/       every shared library ldd lists for them that is not the base system
                            (libc, libm, ld-linux, libpthread, libdl, librt stay; libvulkan
                            comes from the .debs); the C++ runtime (libstdc++, libgcc_s) in
                            lib/toolchain, used there only if the machine's own is too old
                 debs/root  $root_debs
                 debs/tools $tool_debs
                            (apt-get download, amd64, after an apt-get update into
                            \${GPU_BENCH_APT_LISTS:-/tmp/amd64}; skipped when all are there)
                 run.sh     the device-side script (scripts/gpu-bench-device.sh)
                 COMMIT     the commit packed
            3. runs $pack_dir/run.sh here on lavapipe with tiny sizes, as on the device but for the
               .debs going into a scratch root instead of / (its own binaries, libraries,
               loader and vulkaninfo), so the device run is not its first run,
            4. prints the pack's size (limit: ${limit_mib} MiB with the working tree) and the
               device tool's call.
  --quick   the same device-side script on lavapipe against the test build (build/tests, the
            tests preset; nothing else is built): 64x36, one frame, MSAA 4 and 1, cameras
            default and sky, both light passes and index builds; checks that gpu-bench.md and
            gpu-bench.json came out whole. scripts/run-tests.sh runs it after the test suite.
  --help    this text.

On the GPU machine (the device tool's run, from the checkout that holds $pack_dir/):
  carry:     ["$pack_dir"]
  command:   sh $pack_dir/run.sh
  timeout_s: $run_timeout_s
run.sh extracts the loader, sets LD_LIBRARY_PATH to $pack_dir/lib, runs vulkaninfo --summary and
tilelight --list-devices, then tilelight_sweep --only baselines --baselines all once per MSAA
mode (2, 1) and size (1920x1080, 3840x2160): compute and raster light passes, cpu and gpu index
builds, the six cameras, 20 frames each, all sweeps within a 270 s budget (progress lines carry
timestamps). \$OUT gets gpu-bench.md (one table: light path and whole frame against naive,
dynamic and floor, the per-frame-ratio speed-ups, and per group the G-buffer-read limit at the
device's memory bandwidth), gpu-bench.json (every sweep's results.json inside), gpu-bench.log
and results-<sweep>.json. GPU_BENCH_* variables change the sizes, frames, budget and more
(listed at the top of scripts/gpu-bench-device.sh).
EOF
}

fail() {
  printf 'gpu-bench: error: %s\n' "$*" >&2
  exit 1
}

need() {
  for tool in "$@"; do
    command -v "$tool" >/dev/null || fail "$tool is missing (scripts/install-deps.sh installs the build tools)"
  done
}

# Checks what the device-side script wrote into $1 for a run whose MSAA modes are $2 (space-
# separated) at 64x36 with cameras default and sky: every row, the summary, the JSON.
check_outputs() {
  out=$1
  for file in gpu-bench.md gpu-bench.json gpu-bench.log; do
    [ -s "$out/$file" ] || fail "the device-side script wrote no $out/$file"
  done
  for msaa in $2; do
    [ -s "$out/results-sweep-64x36-msaa$msaa.json" ] || fail "no $out/results-sweep-64x36-msaa$msaa.json"
    for pass in compute raster; do
      for path in CPU GPU; do
        for camera in default sky; do
          row="| $pass | ${msaa}x | 64x36 | $path | $camera |"
          grep -qF "$row" "$out/gpu-bench.md" || fail "$out/gpu-bench.md has no row '$row'"
        done
        row="| $pass, ${msaa}x MSAA, 64x36, $path index build | 2 |"
        grep -qF "$row" "$out/gpu-bench.md" || fail "$out/gpu-bench.md has no summary row '$row'"
      done
    done
  done
  grep -qF "| G-buffer read | limit (bandwidth unknown) |" "$out/gpu-bench.md" ||
    fail "$out/gpu-bench.md has no G-buffer-read limit column"
  # cmake is there wherever this project builds; its JSON parser proves the merged file whole.
  cat >"$out/../check-json.cmake" <<'EOF'
file(READ "${JSON}" text)
string(JSON status GET "${text}" status)
string(JSON runs LENGTH "${text}" runs)
math(EXPR last "${runs} - 1")
foreach(i RANGE ${last})
  string(JSON rc GET "${text}" runs ${i} exit_status)
  string(JSON configurations LENGTH "${text}" runs ${i} results configurations)
  if(NOT rc EQUAL 0 OR configurations EQUAL 0)
    message(FATAL_ERROR "run ${i}: exit status ${rc}, ${configurations} configurations")
  endif()
endforeach()
if(NOT status EQUAL 0)
  message(FATAL_ERROR "status ${status}")
endif()
EOF
  cmake -DJSON="$out/gpu-bench.json" -P "$out/../check-json.cmake" || fail "$out/gpu-bench.json is not what the runs wrote"
}

# Runs the device-side script $1 on lavapipe at 64x36, one frame, into $2/out and $2/work; the
# remaining arguments are VAR=value settings for it (binaries, loader).
lavapipe_run() {
  script=$1
  scratch=$2
  shift 2
  rm -rf "$scratch"
  mkdir -p "$scratch"
  env OUT="$scratch/out" GPU_BENCH_WORK="$scratch/work" GPU_BENCH_LOADER=system GPU_BENCH_DEVICE=llvmpipe \
    GPU_BENCH_SIZES=64x36 GPU_BENCH_MSAA="4 1" GPU_BENCH_FRAMES=1 GPU_BENCH_CAMERAS=default,sky \
    GPU_BENCH_BUDGET_S=240 "$@" sh "$script" >"$scratch/console.txt" 2>&1 || {
    tail -n 30 "$scratch/console.txt" >&2
    fail "$script failed on lavapipe (whole output: $scratch/console.txt)"
  }
  check_outputs "$scratch/out" "4 1"
}

quick() {
  need cmake
  tilelight=build/tests/runtime/app/tilelight
  sweep=build/tests/bench/tilelight_sweep
  for binary in "$tilelight" "$sweep"; do
    [ -x "$binary" ] || fail "missing $binary: build the test preset first (cmake --preset tests && cmake --build --preset tests)"
  done
  start=$(date +%s)
  lavapipe_run scripts/gpu-bench-device.sh build/tests/gpu-bench-quick \
    GPU_BENCH_TILELIGHT="$tilelight" GPU_BENCH_SWEEP="$sweep"
  echo "gpu-bench --quick: passed in $(($(date +%s) - start)) s (build/tests/gpu-bench-quick/out/gpu-bench.md)"
}

build_release() {
  # shellcheck source=scripts/ccache-launcher.sh
  . scripts/ccache-launcher.sh
  # The release preset builds the benchmarks too (SHADERGEN_BUILD_BENCH defaults on); said
  # explicitly so that a cache configured otherwise still builds tilelight_sweep.
  # shellcheck disable=SC2086 # $launcher is empty or one word
  cmake --preset release -DSHADERGEN_BUILD_BENCH=ON $launcher
  nice cmake --build --preset release --target tilelight tilelight_sweep
}

# Copies into $pack_dir/lib every library ldd lists for the packed binaries, but the base
# system's and the loader (libvulkan comes from the .debs, with the rest of the loader). The C++
# runtime goes into lib/toolchain, which run.sh uses only if the machine's own is too old.
copy_libraries() {
  mkdir -p "$pack_dir/lib/toolchain"
  if ldd "$pack_dir"/bin/* | grep -q 'not found'; then
    ldd "$pack_dir"/bin/* >&2
    fail "a library of the binaries is not found here (above)"
  fi
  ldd "$pack_dir"/bin/* | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | sort -u | while IFS= read -r lib; do
    name=$(basename "$lib")
    case $name in
      libc.so.* | libm.so.* | ld-linux*.so.* | libpthread.so.* | libdl.so.* | librt.so.* | libvulkan.so.*) continue ;;
      libstdc++.so.* | libgcc_s.so.*) into=$pack_dir/lib/toolchain ;;
      *) into=$pack_dir/lib ;;
    esac
    cp -L "$lib" "$into/"
    strip --strip-unneeded "$into/$name"
  done
}

# apt-get download of the amd64 .debs $2... into $1, unless every one is there already.
download_debs() {
  into=$1
  shift
  missing=""
  for package in "$@"; do
    set -- "$into/${package}_"*.deb
    [ -e "$1" ] || missing="$missing $package"
  done
  [ -n "$missing" ] || return 0
  need apt-get
  lists=${GPU_BENCH_APT_LISTS:-/tmp/amd64}
  mkdir -p "$into" "$lists/partial"
  o="-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=$lists"
  if [ ! -e "$lists/updated" ]; then
    # shellcheck disable=SC2086 # $o is several options
    apt-get $o update || fail "apt-get update failed: the loader's .debs need Debian's package lists"
    touch "$lists/updated"
  fi
  # shellcheck disable=SC2086
  (cd "$into" && apt-get $o download $missing) || fail "apt-get download$missing failed"
}

pack() {
  need cmake ninja strip ldd awk
  build_release
  rm -rf "${pack_dir:?}/bin" "${pack_dir:?}/lib"
  mkdir -p "$pack_dir/bin"
  for binary in build/release/runtime/app/tilelight build/release/bench/tilelight_sweep; do
    [ -x "$binary" ] || fail "the release build made no $binary"
    cp "$binary" "$pack_dir/bin/"
  done
  strip --strip-unneeded "$pack_dir"/bin/*
  copy_libraries
  # shellcheck disable=SC2086 # the lists are words
  download_debs "$pack_dir/debs/root" $root_debs
  # shellcheck disable=SC2086
  download_debs "$pack_dir/debs/tools" $tool_debs
  cp scripts/gpu-bench-device.sh "$pack_dir/run.sh"
  commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
  if [ -n "$(git status --porcelain 2>/dev/null)" ]; then commit="$commit (with uncommitted changes)"; fi
  echo "$commit" >"$pack_dir/COMMIT"

  # The device's path as far as it can be walked here: the .debs extracted (into a scratch root,
  # not into /), vulkaninfo and the loader from them, lavapipe as the driver.
  lvp_icd=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
  [ -e "$lvp_icd" ] || fail "no $lvp_icd: the pack's check runs on lavapipe (mesa-vulkan-drivers)"
  echo "gpu-bench: checking $pack_dir/run.sh on lavapipe (the pack's binaries, libraries and .debs)"
  lavapipe_run "$pack_dir/run.sh" build/gpu-pack-check GPU_BENCH_LOADER=debs \
    GPU_BENCH_DEB_ROOT="$(pwd)/build/gpu-pack-check/root" VK_DRIVER_FILES="$lvp_icd"
  grep -q "vulkaninfo --summary: .*llvmpipe" build/gpu-pack-check/out/gpu-bench.log ||
    fail "vulkaninfo from the pack's .debs did not run (build/gpu-pack-check/out/gpu-bench.log)"

  pack_kib=$(du -sk --apparent-size "$pack_dir" | cut -f1)
  tree_kib=$(git ls-files -z | xargs -0 du -ck --apparent-size 2>/dev/null | tail -n 1 | cut -f1)
  total_kib=$((pack_kib + tree_kib))
  echo
  echo "gpu-bench: $pack_dir/ is $((pack_kib / 1024)) MiB ($pack_kib KiB); with the tracked files $((total_kib / 1024)) MiB of the ${limit_mib} MiB the device tool carries"
  [ "$total_kib" -le $((limit_mib * 1024)) ] || fail "over the ${limit_mib} MiB limit"
  echo "$pack_dir/run.sh checked on lavapipe: build/gpu-pack-check/out/gpu-bench.md"
  echo
  echo "On the GPU machine, from this checkout, call the device tool's run with:"
  echo "  carry:     [\"$pack_dir\"]"
  echo "  command:   sh $pack_dir/run.sh"
  echo "  timeout_s: $run_timeout_s"
  echo "The figures come back in \$OUT: gpu-bench.md, gpu-bench.json, gpu-bench.log, results-<sweep>.json."
}

case "${1:-}" in
  --pack) pack ;;
  --quick) quick ;;
  --help | -h) usage ;;
  *)
    usage >&2
    exit 2
    ;;
esac
