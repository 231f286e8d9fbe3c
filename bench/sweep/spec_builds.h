#pragma once
// The build side of the kinds comparison (tilelight_sweep --only kinds): how many SPIR-V blobs
// and how long `shadergen build` takes for the light domain with SKY and LIGHT_SCATTERING as
// variants, specialization constants or branches. Each spec is built from a copy without its
// companions (the variant spec carries the renderer's 19 shaders that are not permuted; the
// kinds specs none), so every row compiles the permutations of one uber-shader and nothing else,
// cold (--no-cache), the way CMake's build would on a clean tree.

#include "tilelight/render/tile_renderer.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace tilelight::sweep {

struct SpecBuild {
  std::string spec;           // the spec's file name, e.g. "split_second_branch.json"
  std::uint32_t sources = 0;  // distinct sources compiled
  std::uint32_t blobs = 0;    // SPIR-V blobs written
  double seconds = 0;         // wall time of the build, start to exit
};

// permutations/<the spec of `kinds`>.json under `permutations_dir`: one spec per kind, whose two
// uber-shaders ("uber_shaders": raster and compute) are both built.
std::filesystem::path light_spec(const std::filesystem::path& permutations_dir, LightKinds kinds);

// Builds `spec` without its companions with `shadergen` (its executable) into a folder under
// `scratch`, and reads the blob and source counts from its summary line. Throws tilelight::Error
// with shadergen's output when the build fails.
SpecBuild build_light_spec(const std::filesystem::path& shadergen, const std::filesystem::path& spec,
                           const std::filesystem::path& scratch);

}  // namespace tilelight::sweep
