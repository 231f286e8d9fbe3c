#!/bin/sh
# The device side of scripts/gpu-bench.sh: packed as gpu-pack/run.sh by `gpu-bench.sh --pack` and
# run on the lent GPU machine as `sh gpu-pack/run.sh` (docs/gpu-bench.md). That machine has no
# toolchain, no package registry and no Vulkan loader: everything comes from the pack. It
#   1. extracts the Vulkan loader's .debs (pack/debs/root) into / and runs ldconfig, and
#      vulkaninfo's (pack/debs/tools: vulkan-tools and the X11/Wayland client libraries) into the
#      work folder, not into /, whose own libraries they could replace,
#   2. puts the pack's libraries (pack/lib), then the tools' ones, on LD_LIBRARY_PATH, and the
#      pack's C++ runtime (pack/lib/toolchain) too if the machine's own cannot start the binaries,
#   3. runs `vulkaninfo --summary` and `tilelight --list-devices` (cheap first checks),
#   4. runs tilelight_sweep's baselines comparison (--baselines all, both index builds, both
#      light-pass kinds, six cameras) once per MSAA mode and frame size, each under what is left
#      of a time budget, so that a slow part cannot cost the parts measured before it,
#   5. merges their tables into $OUT/gpu-bench.md and their results.json into $OUT/gpu-bench.json;
#      $OUT also gets gpu-bench.log (every progress line) and each sweep's results.json
#      (results-<sweep>.json). The device tool brings back at most 8 files from $OUT, so the rest
#      (charts, per-sweep logs) stays in the work folder.
# Progress lines carry UTC timestamps. `gpu-bench.sh --quick` and `--pack` run this same script
# on lavapipe with tiny sizes (the GPU_BENCH_* settings below).
#
# Settings (environment; defaults are the GPU run's):
#   OUT                     output folder (required; the device tool sets it)
#   GPU_BENCH_WORK          scratch folder                                   [${TMPDIR:-/tmp}/gpu-bench-work]
#   GPU_BENCH_LOADER        debs: extract pack/debs/root/*.deb into / (needs root); system: use
#                           the loader installed here (lavapipe runs)        [debs]
#   GPU_BENCH_DEB_ROOT      where the loader's .debs go (another folder: a trial run; the
#                           loader is then found through LD_LIBRARY_PATH)    [/]
#   GPU_BENCH_TILELIGHT, GPU_BENCH_SWEEP   the binaries                      [pack/bin/...]
#   GPU_BENCH_DEVICE        tilelight --device                               [auto]
#   GPU_BENCH_SIZES         frame sizes, space-separated                     [1920x1080 3840x2160]
#   GPU_BENCH_MSAA          sample counts, space-separated                   [2 1]
#   GPU_BENCH_CAMERAS       cameras, comma-separated                         [all six]
#   GPU_BENCH_PATHS         index builds, comma-separated                    [cpu,gpu]
#   GPU_BENCH_LIGHT_PASSES  light-pass kinds, comma-separated                [compute,raster]
#   GPU_BENCH_FRAMES        timed frames per configuration                   [20]
#   GPU_BENCH_BUDGET_S      seconds for all the sweeps together              [270]
set -eu

pack=$(cd "$(dirname "$0")" && pwd)
loader=${GPU_BENCH_LOADER:-debs}
tilelight=${GPU_BENCH_TILELIGHT:-$pack/bin/tilelight}
sweep=${GPU_BENCH_SWEEP:-$pack/bin/tilelight_sweep}
device=${GPU_BENCH_DEVICE:-auto}
sizes=${GPU_BENCH_SIZES:-1920x1080 3840x2160}
msaa_modes=${GPU_BENCH_MSAA:-2 1}
cameras=${GPU_BENCH_CAMERAS:-default,low,street,closeup,shadow,sky}
paths=${GPU_BENCH_PATHS:-cpu,gpu}
light_passes=${GPU_BENCH_LIGHT_PASSES:-compute,raster}
frames=${GPU_BENCH_FRAMES:-20}
budget=${GPU_BENCH_BUDGET_S:-270}
work=${GPU_BENCH_WORK:-${TMPDIR:-/tmp}/gpu-bench-work}
deb_root=${GPU_BENCH_DEB_ROOT:-/}

log() { printf '%s gpu-bench: %s\n' "$(date -u +%H:%M:%S)" "$*"; }
fail() {
  printf 'gpu-bench: error: %s\n' "$*" >&2
  exit 1
}

[ -n "${OUT:-}" ] || fail "OUT is not set: name the output folder (the device tool sets it)"
[ "$work" != / ] || fail "GPU_BENCH_WORK=/: the work folder is emptied first"
# Every line goes to the console and to $OUT/gpu-bench.log: the script runs itself again behind
# tee (POSIX sh has no process substitution) and exits with that run's status.
if [ -z "${GPU_BENCH_TEED:-}" ]; then
  mkdir -p "$OUT"
  rm -rf "$work"
  mkdir -p "$work"
  {
    rc=0
    GPU_BENCH_TEED=1 sh "$0" || rc=$?
    echo "$rc" >"$work/exit-status"
  } 2>&1 | tee "$OUT/gpu-bench.log"
  exit "$(cat "$work/exit-status")"
fi
for binary in "$tilelight" "$sweep"; do
  [ -x "$binary" ] || fail "missing $binary (build and pack with scripts/gpu-bench.sh --pack)"
done

# 1 and 2: the loader and the libraries the binaries were linked against.
case "$loader" in
  debs)
    set -- "$pack"/debs/root/*.deb
    [ -e "$1" ] || fail "no .deb in $pack/debs/root (scripts/gpu-bench.sh --pack downloads them)"
    command -v dpkg >/dev/null || fail "dpkg is missing: it extracts the Vulkan loader's .debs"
    mkdir -p "$deb_root"
    [ -w "$deb_root" ] || fail "the loader's .debs extract into $deb_root, which is not writable here (run as root)"
    log "extracting $# .deb(s) into $deb_root: the Vulkan loader and GL dispatch"
    for deb in "$@"; do dpkg -x "$deb" "$deb_root"; done
    if [ "$deb_root" = / ]; then
      ldconfig
    else  # a trial run away from /: the loader is found through LD_LIBRARY_PATH instead
      LD_LIBRARY_PATH=$deb_root/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
    fi
    for deb in "$pack"/debs/tools/*.deb; do
      if [ -e "$deb" ]; then dpkg -x "$deb" "$work/tools"; fi
    done
    tools_lib=$work/tools/usr/lib/x86_64-linux-gnu
    if [ -d "$tools_lib" ]; then LD_LIBRARY_PATH=$tools_lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}; fi
    if [ -d "$work/tools/usr/bin" ]; then PATH=$work/tools/usr/bin:$PATH; fi
    # Without it the loader picks an ICD file there that fails ("Found no drivers").
    nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
    if [ -z "${VK_DRIVER_FILES:-}" ] && [ -e "$nvidia_icd" ]; then VK_DRIVER_FILES=$nvidia_icd; fi
    [ -n "${VK_DRIVER_FILES:-}" ] || log "warning: no $nvidia_icd and VK_DRIVER_FILES unset; the loader searches itself"
    ;;
  system) log "using the Vulkan loader installed here (GPU_BENCH_LOADER=system)" ;;
  *) fail "GPU_BENCH_LOADER=$loader: expected debs or system" ;;
esac
# The pack's libraries first: the binaries were linked against exactly these.
if [ -d "$pack/lib" ]; then LD_LIBRARY_PATH=$pack/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}; fi
XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
export LD_LIBRARY_PATH PATH XDG_RUNTIME_DIR
if [ -n "${VK_DRIVER_FILES:-}" ]; then export VK_DRIVER_FILES; fi
# The C++ runtime (lib/toolchain: libstdc++, libgcc_s) only where the machine's own cannot start
# the binaries: the NVIDIA driver, loaded into the same process, may need the machine's newer one.
if ! "$tilelight" --help >/dev/null 2>&1; then
  if [ -d "$pack/lib/toolchain" ]; then
    LD_LIBRARY_PATH=$LD_LIBRARY_PATH:$pack/lib/toolchain
    log "this machine's C++ runtime does not start the binaries: using the pack's (lib/toolchain)"
  fi
  "$tilelight" --help >/dev/null || fail "$tilelight does not start here (the loader's message is above)"
fi

# A command under a time limit where coreutils' timeout exists (it is not guaranteed there).
limited() {
  seconds=$1
  shift
  if command -v timeout >/dev/null; then timeout -k 10 "$seconds" "$@"; else "$@"; fi
}

# Copies each line of stdin to stdout with a timestamp.
stamp() {
  while IFS= read -r line || [ -n "$line" ]; do printf '%s   %s\n' "$(date -u +%H:%M:%S)" "$line"; done
}

# 3: the cheap checks. A vulkaninfo failure is reported, not fatal: tilelight's own is.
if command -v vulkaninfo >/dev/null; then
  if limited 30 vulkaninfo --summary >"$work/vulkaninfo.txt" 2>&1; then
    log "vulkaninfo --summary: $(grep -m1 'deviceName' "$work/vulkaninfo.txt" | sed 's/^ *//' || true)"
  else
    log "warning: vulkaninfo --summary failed:"
    tail -n 5 "$work/vulkaninfo.txt"
  fi
else
  log "no vulkaninfo here; tilelight --list-devices only"
fi
limited 60 "$tilelight" --list-devices >"$work/devices.txt" 2>&1 || {
  cat "$work/devices.txt" >&2
  fail "tilelight --list-devices failed: no Vulkan device to measure"
}
log "devices: $(tr '\n' ';' <"$work/devices.txt")"

# 4: one sweep per MSAA mode and size, headline first, under the budget's deadline.
start=$(date +%s)
deadline=$((start + budget))
runs=""
status=0
for msaa in $msaa_modes; do
  for size in $sizes; do
    name=sweep-$size-msaa$msaa
    left=$((deadline - $(date +%s)))
    if [ "$left" -le 5 ]; then
      log "$name: skipped, the budget of ${budget} s is spent"
      echo 124 >"$work/$name.status"
      echo "skipped: the budget of ${budget} s was spent" >"$work/$name.log"
      runs="$runs $name"
      continue
    fi
    log "$name: starting (${left} s left of ${budget} s)"
    t0=$(date +%s)
    # stdout is the markdown; stderr the progress, timestamped on its way to the console. A
    # pipeline's status is its last command's, so the sweep's goes through a file.
    {
      rc=0
      limited "$left" "$sweep" --device "$device" --only baselines --baselines all --sizes "$size" --msaa "$msaa" \
        --path "$paths" --light-passes "$light_passes" --cameras "$cameras" --frames "$frames" \
        --out "$work/$name" 2>&1 >"$work/$name.md" || rc=$?
      echo "$rc" >"$work/$name.status"
    } | stamp | tee "$work/$name.log"
    rc=$(cat "$work/$name.status")
    echo "$(($(date +%s) - t0))" >"$work/$name.seconds"
    log "$name: exit $rc after $(cat "$work/$name.seconds") s"
    if [ -s "$work/$name/results.json" ]; then cp "$work/$name/results.json" "$OUT/results-$name.json"; fi
    [ "$rc" -eq 0 ] || status=1
    runs="$runs $name"
  done
done

# 5: one markdown table and one JSON file over every sweep. The sweeps' tables share their
# layout (bench/sweep/sweep_tables.cpp, the whole-frame table): headings and notes come from the
# first that has them, rows from each in run order.
md=$OUT/gpu-bench.md
json=$OUT/gpu-bench.json
commit=$(cat "$pack/COMMIT" 2>/dev/null || echo unknown)
when=$(date -u +%Y-%m-%dT%H:%M:%SZ)
# The first line matching $1 in any sweep's markdown, and with -A1 the line after it too.
first_match() {
  for name in $runs; do
    if [ -s "$work/$name.md" ] && grep -q "$1" "$work/$name.md"; then
      grep -m1 -A"${2:-0}" "$1" "$work/$name.md"
      return 0
    fi
  done
}
all_matches() {
  for name in $runs; do
    if [ -s "$work/$name.md" ]; then grep -E "$1" "$work/$name.md" || true; fi
  done
}
{
  echo "# gpu-bench: the classified frame against the full-frame baselines"
  echo
  echo "Commit $commit, run $when; $frames timed frame(s) per configuration after one warm-up frame;"
  echo "index builds $paths, light passes $light_passes, cameras $cameras. How to run it and what"
  echo "the columns mean: docs/gpu-bench.md (scripts/gpu-bench.sh)."
  echo
  echo "| sweep | exit status | seconds | last line of its log |"
  echo "|---|---:|---:|---|"
  for name in $runs; do
    echo "| $name | $(cat "$work/$name.status") | $(cat "$work/$name.seconds" 2>/dev/null || echo -) |" \
      "$(tail -n 1 "$work/$name.log" | tr '|' '/') |"
  done
  echo
  all_matches '^Device: ' | sed 's/^/- /'
  echo
  echo "## Light path and whole frame (ms, medians)"
  echo
  first_match '^| light pass | MSAA |' 1
  all_matches '^\| (compute|raster) \|'
  echo
  first_match '^Ratios are per frame'
  echo
  echo "## Over the cameras, and the physical limit"
  echo
  first_match '^Over the cameras'
  echo
  first_match '^| light pass, MSAA, size |' 1
  all_matches '^\| (compute|raster), '
} >"$md"

{
  printf '{\n  "commit": "%s",\n  "date": "%s",\n  "frames": %s,\n  "budget_s": %s,\n  "status": %s,\n' \
    "$commit" "$when" "$frames" "$budget" "$status"
  printf '  "runs": ['
  separator=""
  for msaa in $msaa_modes; do
    for size in $sizes; do
      name=sweep-$size-msaa$msaa
      printf '%s\n    {"name": "%s", "size": "%s", "msaa": %s, "exit_status": %s, "seconds": %s,\n     "results": ' \
        "$separator" "$name" "$size" "$msaa" "$(cat "$work/$name.status")" "$(cat "$work/$name.seconds" 2>/dev/null || echo null)"
      if [ -s "$work/$name/results.json" ]; then cat "$work/$name/results.json"; else echo null; fi
      printf '    }'
      separator=","
    done
  done
  printf '\n  ]\n}\n'
} >"$json"

log "wrote $md and $json"
sed -n '/^## Over the cameras/,$p' "$md"
exit "$status"
