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

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }

class Equivalence : public VulkanTest, public ::testing::WithParamInterface<Case> {};

TEST_P(Equivalence, ClassifiedEqualsNaivePerPixel) {
  const Case& c = GetParam();
  Scene scene = make_demo_scene();
  scene.cameras.push_back(telephoto_camera());
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
  TileRenderer renderer(context(), scene, options);
  ASSERT_EQ(renderer.tile_primitive(), c.primitive.value_or(TilePrimitive::points));
  ASSERT_EQ(renderer.msaa_samples(), c.msaa == 0 ? 4u : c.msaa);
  const FrameResult frame = renderer.render_frame();

  const RgbaImage naive = renderer.read_naive();
  const FrameComparison cmp = compare(renderer.read_classified(), naive, kEquivalenceTolerance);
  EXPECT_EQ(cmp.magenta_pixels, 0u) << "tiles left undrawn";
  EXPECT_EQ(cmp.pixels_over_tolerance, 0u)
      << cmp.first_difference << " (max difference " << cmp.max_abs_difference << ")";
  const FrameComparison dynamic = compare(renderer.read_dynamic(), naive, kEquivalenceTolerance);
  EXPECT_EQ(dynamic.magenta_pixels, 0u) << "dynamic pass left pixels undrawn";
  EXPECT_EQ(dynamic.pixels_over_tolerance, 0u)
      << "dynamic vs naive: " << dynamic.first_difference << " (max difference " << dynamic.max_abs_difference << ")";
  EXPECT_GT(frame.timings.dynamic_light, 0.0);
  if (renderer.msaa_samples() == 1) {
    // One sample per pixel never differs from itself: no tile may need the MSAA-edge shader.
    const std::vector<std::uint8_t> ids = renderer.raw_tile_ids();
    EXPECT_EQ(std::count_if(ids.begin(), ids.end(),
                            [](std::uint8_t id) { return (id & split_second::raw_bit::MSAA_EDGE) != 0; }),
              0);
  }
  // Every tile drawn exactly once: the per-class tile counts add up to the grid.
  const std::uint32_t drawn = std::accumulate(frame.stats.class_tiles.begin(), frame.stats.class_tiles.end(), 0u);
  EXPECT_EQ(drawn, renderer.grid().tile_count());
  EXPECT_EQ(frame.stats.primitives_uncoalesced, renderer.grid().tile_count());
  if (c.coalesce) {
    EXPECT_LT(frame.stats.primitives_coalesced, frame.stats.primitives_uncoalesced);
  } else {
    EXPECT_EQ(frame.stats.primitives_coalesced, frame.stats.primitives_uncoalesced);
  }
  // Triangles draw each rectangle as one pair; points draw a non-square one tile by tile.
  const std::uint32_t drawn_primitives =
      std::accumulate(frame.stats.class_primitives.begin(), frame.stats.class_primitives.end(), 0u);
  EXPECT_EQ(drawn_primitives, frame.stats.primitives_coalesced);
  if (renderer.tile_primitive() == TilePrimitive::triangles) {
    EXPECT_EQ(frame.stats.class_primitives, frame.stats.class_rectangles);
    EXPECT_EQ(frame.stats.primitives_coalesced, frame.stats.rectangles);
  } else {
    EXPECT_GE(frame.stats.primitives_coalesced, frame.stats.rectangles);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Frames, Equivalence,
    ::testing::Values(
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
        Case{"cpu_1x_triangles", 200, 120, IndexPath::cpu, false, true, "closeup", 4, TilePrimitive::triangles, 1}),
    case_name);

}  // namespace
}  // namespace tilelight::test
