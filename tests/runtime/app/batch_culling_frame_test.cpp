// Batch culling through the whole frame: the scene passes skip the batches wholly outside the
// camera's or the sun's clip volume, and no pixel of any target changes for it.
#include "frame_support.h"
#include "tilelight/scene/scene.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include <cstring>

namespace tilelight::test {
namespace {

RendererOptions closeup(bool cull) {
  RendererOptions options;
  options.width = 160;
  options.height = 96;
  options.camera = "closeup";  // the procedural camera that leaves a batch outside both volumes
  options.cull_batches = cull;
  return options;
}

class BatchCullingFrame : public VulkanTest {};

TEST_F(BatchCullingFrame, SkipsBatchesOutsideEachPassAndChangesNoPixel) {
  const Scene scene = make_demo_scene();
  TileRenderer culled(context(), scene, closeup(true));
  TileRenderer drawn(context(), scene, closeup(false));
  culled.render_frame();
  drawn.render_frame();

  EXPECT_GE(culled.culled_batches().gbuffer, 1u);
  EXPECT_GE(culled.culled_batches().shadow, 1u);
  EXPECT_LT(culled.culled_batches().gbuffer, scene.batches.size());
  EXPECT_EQ(drawn.culled_batches().gbuffer, 0u);
  EXPECT_EQ(drawn.culled_batches().shadow, 0u);

  EXPECT_EQ(TileRendererTestSeam::read_shadow_map(culled), TileRendererTestSeam::read_shadow_map(drawn));
  const GBufferSamples a = TileRendererTestSeam::read_gbuffer(culled);
  const GBufferSamples b = TileRendererTestSeam::read_gbuffer(drawn);
  ASSERT_EQ(a.values.size(), b.values.size());
  EXPECT_EQ(0, std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(float)))
      << "the G-buffers differ";
  const FrameComparison cmp = compare(culled.read_classified(), drawn.read_classified(), 0.0);
  EXPECT_EQ(cmp.pixels_over_tolerance, 0u) << cmp.first_difference;
  const FrameComparison equivalence = compare(culled.read_classified(), culled.read_naive(), kEquivalenceTolerance);
  EXPECT_EQ(equivalence.pixels_over_tolerance, 0u) << equivalence.first_difference;
}

}  // namespace
}  // namespace tilelight::test
