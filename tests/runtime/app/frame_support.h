#pragma once
// Helpers for the frame tests: render one frame with given options and compare.

#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/readback.h"
#include "tilelight_testing/cpu_classifier.h"

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace tilelight::test {

// The tolerance of the equivalence tests: the classified and naive frames must be EQUAL, bit
// for bit. Every permutation computes the full shader's arithmetic on the pixels its class
// admits (precise math on threshold decisions, exact identities where a feature is skipped),
// so there is no floating-point noise to allow for.
inline constexpr double kEquivalenceTolerance = 0.0;

struct FrameComparison {
  std::uint64_t pixels_over_tolerance = 0;
  double max_abs_difference = 0.0;
  std::uint64_t magenta_pixels = 0;  // the classified target's clear colour: an uncovered tile
  std::string first_difference;      // "pixel (x, y): classified (...) naive (...)"
};

FrameComparison compare(const RgbaImage& classified, const RgbaImage& naive, double tolerance);

// The last frame's classified and dynamic images equal its naive one (kEquivalenceTolerance),
// every tile drawn. Precondition: `renderer` runs the naive and dynamic passes.
void expect_classified_and_dynamic_equal_naive(const TileRenderer& renderer);

// Renders a frame, then expect_classified_and_dynamic_equal_naive() and every tile drawn once
// (the per-class tile counts add up to the grid).
FrameResult render_equivalent_frame(TileRenderer& renderer);

// Renders `scene` twice, its local lights drawn full-screen (the reference) and as volumes
// (`options` otherwise; each frame through render_equivalent_frame()), and expects the volume
// frame's classified and naive light targets to equal the reference's bit for bit. Returns the
// volume renderer's shadow-map pool. Precondition: `options` runs the naive and dynamic passes.
LocalLightShadowPool expect_volumes_equal_full_screen(const Context& context, const Scene& scene,
                                                      RendererOptions options);

// The GPU's raw IDs against the CPU reference (which classifies every sample and counts every
// tap), outside the bits the reference marks as near a threshold: SKY and SUN_LIGHT must be
// equal; MSAA_EDGE, SHADOW_FADE and LIGHT_SCATTERING must be set wherever the reference sets them
// (more is allowed: those features are exact identities where not needed); the shadow type must
// be one no sample rules out: SOFT always, SOLID only with no lit tap, none only with no
// occluded tap (see classify_tiles.comp).
struct ReferenceComparison {
  std::size_t mismatches = 0;
  std::string first_mismatch;  // "tile (x, y): GPU raw ID ..., CPU ...: why"
  std::size_t uncertain_tiles = 0;
  std::size_t soft_by_bounds = 0;     // sunlit tiles the reference calls SOLID or lit, the GPU SOFT
  std::size_t settled_by_bounds = 0;  // sunlit tiles the reference calls SOLID or lit, and so does the GPU
};

ReferenceComparison compare_with_reference(const std::vector<std::uint8_t>& gpu_raw_ids,
                                           const ReferenceClassification& cpu, std::uint32_t tiles_x);

// A narrow (10 degree) view from 70 m onto the boxes, between the shadow-fade start and end: each
// tile covers a few centimetres at a distance where float positions are coarse, so the
// classifier's per-tile bounds are as thin as its rounding margins. Tests add it to the demo
// scene's cameras.
Camera telephoto_camera();

// tilelight's command line run in-process (app::run), with its exit code and output. The run is
// on lavapipe (`--device llvmpipe` is added unless `args` names a device): tilelight's default
// is auto, which would take a GPU where the machine has one.
struct CliResult {
  int exit_code;
  std::string out, err;
};
CliResult run_cli(std::vector<std::string> args);

// Optimised IDs present in a frame's raw tile IDs (row-major).
std::set<std::uint32_t> optimised_ids_of(const std::vector<std::uint8_t>& raw_ids);

}  // namespace tilelight::test
