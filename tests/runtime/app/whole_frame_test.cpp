// The whole frame, like for like: submit B draws the plain G-buffer into the same targets after
// the tile pass, then each baseline that runs. The classified frame must still equal every
// baseline that lights, whichever of them run and however the passes and the index build run;
// the floor pass must read the G-buffer the naive pass reads; the frame timings must add up.
#include "frame_support.h"
#include "tilelight/base/error.h"
#include "tilelight/scene/scene.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include <glm/gtc/packing.hpp>

#include <cmath>
#include <string>
#include <tuple>

namespace tilelight::test {
namespace {

using Combination = std::tuple<Baselines, LightPass, IndexPath>;

std::string combination_name(const ::testing::TestParamInfo<Combination>& info) {
  const auto& [baselines, light_pass, path] = info.param;
  return std::string(to_string(baselines)) + "_" + to_string(light_pass) + (path == IndexPath::gpu ? "_gpu" : "_cpu");
}

RendererOptions options_for(const Combination& c) {
  RendererOptions options;
  options.width = 160;
  options.height = 96;
  std::tie(options.baselines, options.light_pass, options.path) = c;
  return options;
}

void expect_equal(const RgbaImage& actual, const RgbaImage& expected, const char* what) {
  const FrameComparison cmp = compare(actual, expected, kEquivalenceTolerance);
  EXPECT_EQ(cmp.magenta_pixels, 0u) << what << ": pixels left undrawn";
  EXPECT_EQ(cmp.pixels_over_tolerance, 0u)
      << what << ": " << cmp.first_difference << " (max difference " << cmp.max_abs_difference << ")";
}

class WholeFrame : public VulkanTest, public ::testing::WithParamInterface<Combination> {};

TEST_P(WholeFrame, ClassifiedEqualsEveryBaselineOnThePlainGBuffer) {
  const Baselines baselines = std::get<0>(GetParam());
  const Scene scene = make_demo_scene();
  TileRenderer renderer(context(), scene, options_for(GetParam()));
  renderer.render_frame();
  const RgbaImage classified = renderer.read_classified();
  if (runs_naive(baselines)) expect_equal(classified, renderer.read_naive(), "classified vs naive");
  if (runs_dynamic(baselines)) expect_equal(classified, renderer.read_dynamic(), "classified vs dynamic");
  if (runs_floor(baselines)) {
    EXPECT_EQ(compare(renderer.read_floor(), classified, 0.0).magenta_pixels, 0u) << "floor pass left pixels undrawn";
  }
}

// Each baseline alone, and all three, in both kinds of light pass and both index builds.
INSTANTIATE_TEST_SUITE_P(Baselines, WholeFrame,
                         ::testing::Combine(::testing::Values(Baselines::naive, Baselines::dynamic, Baselines::all),
                                            ::testing::Values(LightPass::raster, LightPass::compute),
                                            ::testing::Values(IndexPath::cpu, IndexPath::gpu)),
                         combination_name);

// The floor pass's pixel: the mean of its samples' prelit colours, as the G-buffer stores them
// (uber/include/light_pass.glsl, FLOOR_PASS), stored to the half-float light target.
std::array<float, 3> floor_pixel(const GBufferSamples& g, std::uint32_t x, std::uint32_t y) {
  std::array<float, 3> sum{};
  for (std::uint32_t s = 0; s < g.samples; ++s) {
    const float* sample = g.at(x, y, s);
    for (int c = 0; c < 3; ++c) sum[c] += sample[8 + c];  // RT2.rgb: prelit
  }
  for (float& v : sum) v = glm::unpackHalf1x16(glm::packHalf1x16(v / static_cast<float>(g.samples)));
  return sum;
}

// The floor pass reads every sample of the G-buffer the baselines read: its frame is the mean
// prelit colour of the G-buffer left behind (within a half-float step: the order of the sum
// is the compiler's).
class FloorPass : public VulkanTest, public ::testing::WithParamInterface<LightPass> {};

TEST_P(FloorPass, WritesTheMeanPrelitColourOfEverySample) {
  const Scene scene = make_demo_scene();
  TileRenderer renderer(context(), scene, options_for({Baselines::floor, GetParam(), IndexPath::cpu}));
  const FrameTimings timings = renderer.render_frame().timings;
  EXPECT_GT(timings.floor_light, 0.0);
  EXPECT_EQ(timings.naive_light, 0.0);
  EXPECT_EQ(timings.frame_naive, 0.0);
  const RgbaImage floor = renderer.read_floor();
  const GBufferSamples g = TileRendererTestSeam::read_gbuffer(renderer);
  std::uint64_t differing = 0;
  for (std::uint32_t y = 0; y < g.height; ++y) {
    for (std::uint32_t x = 0; x < g.width; ++x) {
      const std::array<float, 3> expected = floor_pixel(g, x, y);
      const std::array<float, 4> actual = floor.at(x, y);
      for (int c = 0; c < 3; ++c) {
        if (std::fabs(actual[c] - expected[c]) > 1e-3f * std::max(1.0f, std::fabs(expected[c]))) ++differing;
      }
    }
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_THROW((void)renderer.read_naive(), Error);
}

INSTANTIATE_TEST_SUITE_P(LightPasses, FloorPass, ::testing::Values(LightPass::raster, LightPass::compute),
                         [](const ::testing::TestParamInfo<LightPass>& param_info) {
                           return to_string(param_info.param);
                         });

// The frame timings: a baseline's frame is the sum of its passes, the classified frame spans at
// least its GPU passes (it also holds the gaps between them, and the host's build), and with no
// baseline nothing of the baselines' is drawn or timed.
struct TimingCase {
  const char* name;
  Baselines baselines;
  IndexPath path;
};

class FrameTimingsAddUp : public VulkanTest, public ::testing::WithParamInterface<TimingCase> {};

TEST_P(FrameTimingsAddUp, PerFrame) {
  const TimingCase& c = GetParam();
  const Scene scene = make_demo_scene();
  RendererOptions options = options_for({c.baselines, LightPass::compute, c.path});
  options.width = 64;
  options.height = 48;
  TileRenderer renderer(context(), scene, options);
  for (int frame = 0; frame < 2; ++frame) {
    const FrameTimings t = renderer.render_frame().timings;
    EXPECT_EQ(t.gbuffer_plain > 0, runs_any_baseline(c.baselines));
    EXPECT_EQ(t.frame_naive, runs_naive(c.baselines) ? t.shadow_map + t.gbuffer_plain + t.naive_light : 0.0);
    EXPECT_EQ(t.frame_dynamic, runs_dynamic(c.baselines) ? t.shadow_map + t.gbuffer_plain + t.dynamic_light : 0.0);
    EXPECT_EQ(t.floor_light > 0, runs_floor(c.baselines));
    // 1e-9: the parts are differences of the same stamps, summed in another order.
    EXPECT_GE(t.frame_classified + 1e-9,
              t.shadow_map + t.gbuffer + t.classification + t.index_build_gpu + t.tiled_light);
  }
}

INSTANTIATE_TEST_SUITE_P(Baselines, FrameTimingsAddUp,
                         ::testing::Values(TimingCase{"none_cpu", Baselines::none, IndexPath::cpu},
                                           TimingCase{"naive_gpu", Baselines::naive, IndexPath::gpu},
                                           TimingCase{"dynamic_cpu", Baselines::dynamic, IndexPath::cpu},
                                           TimingCase{"all_gpu", Baselines::all, IndexPath::gpu}),
                         [](const ::testing::TestParamInfo<TimingCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

}  // namespace
}  // namespace tilelight::test
