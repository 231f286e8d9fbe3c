// Correctness criterion of the whole technique (docs/design.md): for every pixel, the classified
// render equals the naive render. One comparison checks classification conservativeness, the
// LUT, every permutation drawn, the index buffers and the deferred draw patching together.
// The dynamic baseline (one full-screen pass branching per pixel) must give the naive render
// too: its skipped work is the same exact identity the permutations rely on.
#include "frame_support.h"
#include "tilelight/scene/scene.h"
#include "tilelight_testing/test_support.h"

#include <split_second_shaders.h>

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <optional>

namespace tilelight::test {
namespace {

struct Case {
  const char* name;
  std::uint32_t width, height;
  IndexPath path;
  bool raw;
  bool coalesce;
  const char* camera;
  std::uint32_t tile_size = 4;
  std::optional<TilePrimitive> primitive = std::nullopt;  // empty: auto, which is points on lavapipe
  std::uint32_t msaa = 0;                                 // 0: auto, which is 4x on lavapipe
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// Every case runs with both kinds of light pass: the tile pass and the baselines drawn (raster)
// or dispatched (compute).
using CaseAndPass = std::tuple<Case, LightPass>;

std::string case_name(const ::testing::TestParamInfo<CaseAndPass>& info) {
  return std::string(std::get<0>(info.param).name) +
         (std::get<1>(info.param) == LightPass::compute ? "_compute" : "_raster");
}

RendererOptions options_for(const Case& c, LightPass light_pass) {
  RendererOptions options;
  options.width = c.width;
  options.height = c.height;
  options.path = c.path;
  options.raw_permutations = c.raw;
  options.coalesce = c.coalesce;
  options.camera = c.camera;
  options.tile_size = c.tile_size;
  options.primitive = c.primitive;
  options.msaa = c.msaa;
  options.light_pass = light_pass;
  return options;
}

Scene test_scene() {
  Scene scene = make_demo_scene();
  scene.cameras.push_back(telephoto_camera());
  return scene;
}

// The raster tile pass's figures: primitives (rectangles, coalesced or not) per class.
void expect_raster_primitives(const Case& c, const TileRenderer& renderer, const FrameStats& stats) {
  ASSERT_EQ(renderer.tile_primitive(), c.primitive.value_or(TilePrimitive::points));
  if (c.coalesce) {
    EXPECT_LT(stats.primitives_coalesced, stats.primitives_uncoalesced);
  } else {
    EXPECT_EQ(stats.primitives_coalesced, stats.primitives_uncoalesced);
  }
  // Triangles draw each rectangle as one pair; points draw a non-square one tile by tile.
  const std::uint32_t drawn_primitives =
      std::accumulate(stats.class_primitives.begin(), stats.class_primitives.end(), 0u);
  EXPECT_EQ(drawn_primitives, stats.primitives_coalesced);
  if (renderer.tile_primitive() == TilePrimitive::triangles) {
    EXPECT_EQ(stats.class_primitives, stats.class_rectangles);
    EXPECT_EQ(stats.primitives_coalesced, stats.rectangles);
  } else {
    EXPECT_GE(stats.primitives_coalesced, stats.rectangles);
  }
}

// The compute tile pass's figures: per class, ceil(tiles / tiles per workgroup) workgroups.
void expect_compute_workgroups(const TileRenderer& renderer, const FrameStats& stats) {
  const std::uint32_t tile_pixels = renderer.grid().tile_size * renderer.grid().tile_size;
  const std::uint32_t per_group = std::max(1u, 64u / tile_pixels);
  std::uint32_t groups = 0;
  for (std::size_t c = 0; c < stats.class_tiles.size(); ++c) {
    EXPECT_EQ(stats.class_primitives[c], (stats.class_tiles[c] + per_group - 1) / per_group) << "class " << c;
    groups += stats.class_primitives[c];
  }
  EXPECT_EQ(stats.primitives_coalesced, groups);
  EXPECT_EQ(stats.rectangles, 0u);
}

class Equivalence : public VulkanTest, public ::testing::WithParamInterface<CaseAndPass> {};

TEST_P(Equivalence, ClassifiedEqualsNaivePerPixel) {
  const auto& [c, light_pass] = GetParam();
  const Scene scene = test_scene();
  TileRenderer renderer(context(), scene, options_for(c, light_pass));
  ASSERT_EQ(renderer.light_pass(), light_pass);
  ASSERT_EQ(renderer.msaa_samples(), c.msaa == 0 ? 4u : c.msaa);
  const FrameResult frame = renderer.render_frame();

  expect_classified_and_dynamic_equal_naive(renderer);
  EXPECT_GT(frame.timings.dynamic_light, 0.0);
  if (renderer.msaa_samples() == 1) {
    // One sample per pixel never differs from itself: no tile may need the MSAA-edge shader.
    const std::vector<std::uint8_t> ids = renderer.raw_tile_ids();
    EXPECT_EQ(std::count_if(ids.begin(), ids.end(),
                            [](std::uint8_t id) { return (id & split_second::raw_bit::MSAA_EDGE.value()) != 0; }),
              0);
  }
  // Every tile drawn exactly once: the per-class tile counts add up to the grid.
  const std::uint32_t drawn = std::accumulate(frame.stats.class_tiles.begin(), frame.stats.class_tiles.end(), 0u);
  EXPECT_EQ(drawn, renderer.grid().tile_count());
  EXPECT_EQ(frame.stats.primitives_uncoalesced, renderer.grid().tile_count());
  if (light_pass == LightPass::compute) {
    expect_compute_workgroups(renderer, frame.stats);
  } else {
    expect_raster_primitives(c, renderer, frame.stats);
  }
}

const Case kCases[] = {
    Case{"cpu_default", 320, 180, IndexPath::cpu, false, true, "default"},
    Case{"gpu_default", 320, 180, IndexPath::gpu, false, true, "default"},
    Case{"cpu_odd_size", 333, 197, IndexPath::cpu, false, true, "default"},
    Case{"gpu_odd_size", 333, 197, IndexPath::gpu, false, true, "default"},
    Case{"cpu_uncoalesced", 161, 93, IndexPath::cpu, false, false, "default"},
    Case{"gpu_uncoalesced", 161, 93, IndexPath::gpu, false, false, "default"},
    Case{"cpu_raw", 256, 144, IndexPath::cpu, true, true, "default"},
    Case{"gpu_raw", 256, 144, IndexPath::gpu, true, true, "default"},
    Case{"cpu_sky", 200, 120, IndexPath::cpu, false, true, "sky"},
    Case{"gpu_sky", 200, 120, IndexPath::gpu, false, true, "sky"},
    Case{"cpu_shadow", 200, 120, IndexPath::cpu, false, true, "shadow"},
    Case{"gpu_shadow", 200, 120, IndexPath::gpu, false, true, "shadow"},
    Case{"cpu_low", 257, 131, IndexPath::cpu, false, true, "low"},
    // Larger tiles: one depth-plane prism spans 8x8 / 16x16 pixels.
    Case{"cpu_tile8", 320, 180, IndexPath::cpu, false, true, "default", 8},
    Case{"gpu_tile16_odd_size", 333, 197, IndexPath::gpu, false, true, "default", 16},
    // Partial tiles 6 px wide and tall: their points' centres (8 px in) lie
    // outside the frame, inside the tile pass's whole-tile viewport. (lavapipe
    // draws such points even without that viewport, so this cannot show the
    // culling the Vulkan spec allows; it does check their coverage.)
    Case{"cpu_tile16_narrow_partials", 326, 198, IndexPath::cpu, false, true, "default", 16},
    // Thin prisms at 55-85 m, where the rounding margins decide most.
    Case{"cpu_telephoto", 320, 180, IndexPath::cpu, false, true, "telephoto"},
    // The chapter's two triangles per rectangle, where auto would choose points.
    Case{"cpu_triangles", 320, 180, IndexPath::cpu, false, true, "default", 4, TilePrimitive::triangles},
    Case{"gpu_triangles_odd_size", 333, 197, IndexPath::gpu, false, true, "default", 4, TilePrimitive::triangles},
    // The views with little or no sky.
    Case{"cpu_street", 240, 136, IndexPath::cpu, false, true, "street"},
    Case{"gpu_closeup", 240, 136, IndexPath::gpu, false, true, "closeup"},
    // No MSAA: the single-sampled G-buffer and the split_second_1x shaders.
    Case{"cpu_1x", 320, 180, IndexPath::cpu, false, true, "default", 4, std::nullopt, 1},
    Case{"gpu_1x_odd_size", 333, 197, IndexPath::gpu, false, true, "default", 4, std::nullopt, 1},
    Case{"cpu_1x_raw", 256, 144, IndexPath::cpu, true, true, "default", 4, std::nullopt, 1},
    Case{"gpu_1x_low", 257, 131, IndexPath::gpu, false, true, "low", 4, std::nullopt, 1},
    Case{"cpu_1x_triangles", 200, 120, IndexPath::cpu, false, true, "closeup", 4, TilePrimitive::triangles, 1}};

INSTANTIATE_TEST_SUITE_P(Frames, Equivalence,
                         ::testing::Combine(::testing::ValuesIn(kCases),
                                            ::testing::Values(LightPass::raster, LightPass::compute)),
                         case_name);

// The two kinds of light pass run the same shading code (uber/include/light_pass.glsl) in the
// same order on the same G-buffer: on lavapipe their frames are equal bit for bit, the
// classified, naive and dynamic ones alike.
class ComputeMatchesRaster : public VulkanTest, public ::testing::WithParamInterface<Case> {};

TEST_P(ComputeMatchesRaster, EveryFrameBitForBit) {
  const Case& c = GetParam();
  const Scene scene = test_scene();
  TileRenderer raster(context(), scene, options_for(c, LightPass::raster));
  raster.render_frame();
  TileRenderer compute(context(), scene, options_for(c, LightPass::compute));
  compute.render_frame();
  const std::pair<const char*, RgbaImage (TileRenderer::*)() const> frames[] = {
      {"classified", &TileRenderer::read_classified},
      {"naive", &TileRenderer::read_naive},
      {"dynamic", &TileRenderer::read_dynamic}};
  for (const auto& [name, read] : frames) {
    const FrameComparison cmp = compare((compute.*read)(), (raster.*read)(), 0.0);
    EXPECT_EQ(cmp.magenta_pixels, 0u) << name;
    EXPECT_EQ(cmp.pixels_over_tolerance, 0u)
        << name << ": " << cmp.first_difference << " (max difference " << cmp.max_abs_difference << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Frames, ComputeMatchesRaster,
    ::testing::Values(Case{"msaa4", 320, 180, IndexPath::gpu, false, true, "default"},
                      Case{"msaa1", 200, 120, IndexPath::cpu, false, true, "street", 4, std::nullopt, 1},
                      Case{"raw_tile16", 333, 197, IndexPath::cpu, true, true, "low", 16}),
    [](const ::testing::TestParamInfo<Case>& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace tilelight::test
