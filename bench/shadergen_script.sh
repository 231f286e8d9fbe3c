#!/bin/sh
# The script a user would write instead of `shadergen build`: for every permutation,
# glslangValidator to SPIR-V, spirv-opt -O, spirv-val; two permutations at a time.
# shadergen_build_bench runs it as baseline (a) of its comparison.
#
# usage: shadergen_script.sh JOBS OUT_DIR [INCLUDE_DIR...]
#   JOBS: one permutation per line, "<name> <stage: vert|frag|comp> <shader path> [DEFINE...]"
#         (whitespace-separated, so paths without spaces). Each DEFINE becomes -DDEFINE=1,
#         which is what shadergen's `#define DEFINE 1` preamble does.
#   Writes OUT_DIR/<name>.spv (unoptimised) and OUT_DIR/<name>.opt.spv (optimised, validated).
#   Exits non-zero if any permutation fails to compile, optimise or validate.
set -eu
[ $# -ge 2 ] || { echo "usage: $0 JOBS OUT_DIR [INCLUDE_DIR...]" >&2; exit 2; }
jobs_file=$1
out=$2
shift 2
includes=""
for dir in "$@"; do includes="$includes -I$dir"; done
mkdir -p "$out"
export out includes

# Two workers; each runs the three tools of one permutation in sequence.
xargs -P 2 -L 1 sh -c '
    set -eu
    name=$1 stage=$2 shader=$3
    shift 3
    defines=""
    for define in "$@"; do defines="$defines -D$define=1"; done
    glslangValidator -V --target-env vulkan1.2 -S "$stage" $defines $includes -o "$out/$name.spv" "$shader" >/dev/null
    spirv-opt -O "$out/$name.spv" -o "$out/$name.opt.spv"
    spirv-val --target-env vulkan1.2 "$out/$name.opt.spv"
' sh <"$jobs_file"
