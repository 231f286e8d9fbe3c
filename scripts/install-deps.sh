#!/bin/sh
# Installs the Debian 12 packages the project builds with, if any is missing (needs root).
#   scripts/install-deps.sh           what the build and the main job need
#   scripts/install-deps.sh --tests   that, and what only the test suite and CI use (clang-format
#                                     for the style test, clang-tidy for scripts/lint.sh, which CI
#                                     runs, assimp-testmodels' real and broken glTF files for the
#                                     scene tests, Apache mod_dav for the remote-cache tests, ccache
#                                     for repeat runs of scripts/run-tests.sh, Slurm and munge for
#                                     the one-node cluster of shadergen.slurm_shards)
set -eu

PACKAGES="cmake ninja-build g++ pkg-config
glslang-dev glslang-tools spirv-tools spirv-cross libspirv-cross-c-shared-dev
libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
libglm-dev libfmt-dev libgtest-dev libgmock-dev libbenchmark-dev
libcli11-dev nlohmann-json3-dev libstb-dev libtinygltf-dev libmeshoptimizer-dev libdraco-dev
libcurl4-openssl-dev libssl-dev libmimalloc-dev nginx"
if [ "${1:-}" = "--tests" ]; then
    PACKAGES="$PACKAGES clang-format clang-tidy assimp-testmodels apache2 ccache slurm-wlm munge"
fi

missing=""
for package in $PACKAGES; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $package"
    fi
done

if [ -z "$missing" ]; then
    echo "install-deps: all packages present"
    exit 0
fi

echo "install-deps: installing$missing"
if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps: error: missing packages and not root; run as root or install:$missing" >&2
    exit 1
fi
apt-get update
DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing
