// The GPU index build (tile_rects.comp, tile_prefix.comp) against the CPU one (TileIndexBuilder)
// on the same frame: given the same raw tile IDs, both must find the same rectangles and draw
// them with the same primitives, class by class.
#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/scene.h"
#include "tilelight_testing/test_support.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tilelight::test {
namespace {

class IndexPaths : public VulkanTest {
 protected:
  struct Rendered {
    FrameStats stats;
    std::vector<std::uint8_t> raw_ids;
    std::uint32_t classes = 0;  // draw_class_count()
  };

  Rendered render(IndexPath path) {
    RendererOptions options;
    options.light_pass = LightPass::raster;
    options.width = 200;
    options.height = 120;
    options.path = path;
    options.primitive = TilePrimitive::points;
    TileRenderer renderer(context(), scene_, options);
    EXPECT_EQ(renderer.tile_primitive(), TilePrimitive::points);
    Rendered out;
    out.stats = renderer.render_frame().stats;
    out.raw_ids = renderer.raw_tile_ids();
    out.classes = renderer.draw_class_count();
    return out;
  }

  Scene scene_ = make_demo_scene();
};

// The per-class counts of the frame's draw classes. The CPU path's FrameStats vectors hold an
// entry for every possible class (kMaxDrawClasses), the GPU path's one per draw class; past the
// draw classes there must be nothing to count.
std::vector<std::uint32_t> drawn(const std::vector<std::uint32_t>& per_class, std::uint32_t classes) {
  EXPECT_GE(per_class.size(), classes);
  for (std::size_t id = classes; id < per_class.size(); ++id) EXPECT_EQ(per_class[id], 0u) << "class " << id;
  return {per_class.begin(), per_class.begin() + std::min<std::size_t>(classes, per_class.size())};
}

TEST_F(IndexPaths, GpuPointCountsEqualCpuPointCountsPerClass) {
  const Rendered cpu = render(IndexPath::cpu);
  const Rendered gpu = render(IndexPath::gpu);
  ASSERT_EQ(gpu.raw_ids, cpu.raw_ids) << "the two frames were classified differently: their counts cannot be compared";
  ASSERT_EQ(gpu.classes, cpu.classes);
  const std::uint32_t classes = cpu.classes;
  EXPECT_EQ(drawn(gpu.stats.class_tiles, classes), drawn(cpu.stats.class_tiles, classes));
  EXPECT_EQ(drawn(gpu.stats.class_rectangles, classes), drawn(cpu.stats.class_rectangles, classes));
  EXPECT_EQ(drawn(gpu.stats.class_primitives, classes), drawn(cpu.stats.class_primitives, classes));
  EXPECT_EQ(gpu.stats.rectangles, cpu.stats.rectangles);
  EXPECT_EQ(gpu.stats.primitives_coalesced, cpu.stats.primitives_coalesced);
  EXPECT_EQ(gpu.stats.primitives_uncoalesced, cpu.stats.primitives_uncoalesced);
  // The frame must hold both kinds of rectangle, or points and rectangles would count alike and
  // the comparison would not tell a wrong primitive count from a right one.
  EXPECT_LT(cpu.stats.rectangles, cpu.stats.primitives_coalesced) << "no rectangle was drawn tile by tile";
  EXPECT_LT(cpu.stats.primitives_coalesced, cpu.stats.primitives_uncoalesced) << "no square was drawn as one point";
}

}  // namespace
}  // namespace tilelight::test
