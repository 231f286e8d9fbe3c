// The light domain with SKY and LIGHT_SCATTERING as specialization constants and as run-time
// branches (tilelight --light-kinds, docs/runtime.md "Feature kinds"): the tile pass draws
// (optimised ID, values) classes instead of optimised IDs, and every pixel of the frame must be
// the variant build's, on every camera, at 4x and 1x MSAA, raster and compute light pass, at
// 256x144. Most cases share one context without the validation layer (three renderers a case,
// 24 cases); KindsFramesUnderValidation draws both kinds, raster and compute, under it.
#include "frame_support.h"
#include "tilelight_testing/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <numeric>
#include <string>
#include <tuple>

namespace tilelight::test {
namespace {

constexpr std::uint32_t kWidth = 256, kHeight = 144;

RendererOptions options_for(const std::string& camera, std::uint32_t msaa, LightPass pass, LightKinds kinds) {
  RendererOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.camera = camera;
  options.msaa = msaa;
  options.light_pass = pass;
  options.light_kinds = kinds;
  // The variant build's frame is the reference and its naive pass proves it right; the other
  // builds are compared with that frame, so they draw no baseline of their own.
  options.baselines = kinds == LightKinds::variant ? Baselines::naive : Baselines::none;
  return options;
}

// The pipelines each build creates for the 32 classes of the light domain: one per optimised ID
// (variant), one per (optimised ID, specialization values) pair (32: each of the 8 optimised
// IDs of the kinds specs with the 4 values of SKY and LIGHT_SCATTERING), one per optimised ID
// (branch: the values come with each draw).
std::uint32_t expected_pipelines(LightKinds kinds) { return kinds == LightKinds::branch ? 8u : 32u; }

// Renders one frame of `kinds` and expects its classified image to equal `reference` pixel for
// pixel, every tile drawn once.
void expect_same_frame(const Context& context, const Scene& scene, const RendererOptions& options,
                       const RgbaImage& reference) {
  TileRenderer renderer(context, scene, options);
  ASSERT_EQ(renderer.light_kinds(), options.light_kinds);
  EXPECT_EQ(renderer.draw_class_count(), 32u);
  EXPECT_EQ(renderer.pipeline_count(), expected_pipelines(options.light_kinds));
  const FrameResult frame = renderer.render_frame();
  EXPECT_EQ(std::accumulate(frame.stats.class_tiles.begin(), frame.stats.class_tiles.end(), 0u),
            renderer.grid().tile_count());
  const FrameComparison same = compare(renderer.read_classified(), reference, 0.0);
  EXPECT_EQ(same.magenta_pixels, 0u) << to_string(options.light_kinds) << ": tiles left undrawn";
  EXPECT_EQ(same.pixels_over_tolerance, 0u)
      << to_string(options.light_kinds) << " vs variant: " << same.first_difference << " (max difference "
      << same.max_abs_difference << ")";
}

// The variant build's frame (checked against its naive pass), then each other build's against it.
void expect_kinds_equal_variant(const Context& context, const std::string& camera, std::uint32_t msaa, LightPass pass) {
  const Scene scene = make_demo_scene();
  RgbaImage variant_frame;
  {
    TileRenderer variant(context, scene, options_for(camera, msaa, pass, LightKinds::variant));
    ASSERT_EQ(variant.msaa_samples(), msaa);
    EXPECT_EQ(variant.pipeline_count(), expected_pipelines(LightKinds::variant));
    variant.render_frame();
    variant_frame = variant.read_classified();
    const FrameComparison naive = compare(variant_frame, variant.read_naive(), kEquivalenceTolerance);
    EXPECT_EQ(naive.pixels_over_tolerance, 0u) << "variant vs naive: " << naive.first_difference;
  }
  for (const LightKinds kinds : {LightKinds::specialization, LightKinds::branch}) {
    expect_same_frame(context, scene, options_for(camera, msaa, pass, kinds), variant_frame);
  }
}

using KindsCase = std::tuple<std::string, std::uint32_t, LightPass>;  // camera, MSAA, light pass

// One lavapipe context for every case, without the validation layer: 72 renderers under it
// would take minutes; KindsFramesUnderValidation covers the layer.
class KindsFrames : public ::testing::TestWithParam<KindsCase> {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<Context>(ContextOptions{}); }
  static void TearDownTestSuite() { context_.reset(); }
  static const Context& context() { return *context_; }

 private:
  static std::unique_ptr<Context> context_;
};
std::unique_ptr<Context> KindsFrames::context_;

TEST_P(KindsFrames, SpecializationAndBranchFramesEqualTheVariantFrame) {
  const auto& [camera, msaa, pass] = GetParam();
  expect_kinds_equal_variant(context(), camera, msaa, pass);
}

std::string kinds_case_name(const ::testing::TestParamInfo<KindsCase>& info) {
  const auto& [camera, msaa, pass] = info.param;
  return camera + "_" + std::to_string(msaa) + "x_" + to_string(pass);
}

INSTANTIATE_TEST_SUITE_P(EveryCamera, KindsFrames,
                         ::testing::Combine(::testing::Values("default", "sky", "shadow", "low", "street", "closeup"),
                                            ::testing::Values(4u, 1u),
                                            ::testing::Values(LightPass::raster, LightPass::compute)),
                         kinds_case_name);

// Under the Khronos validation layer (VulkanTest fails on any message): the specialization data
// merged with the runtime's own constants, the branch set's dynamic offsets and its layout below
// set 2, in both light passes.
class KindsFramesUnderValidation : public VulkanTest {};

TEST_F(KindsFramesUnderValidation, DefaultCameraAt4xRasterAndCompute) {
  for (const LightPass pass : {LightPass::raster, LightPass::compute}) {
    SCOPED_TRACE(to_string(pass));
    expect_kinds_equal_variant(context(), "default", 4, pass);
  }
}

// tilelight --light-kinds: the report names the build and its pipelines, the frame still equals the
// naive pass (the variant build's), the console says which build drew; the default is variant,
// and an unknown kind is a usage error naming the flag.
TEST(TilelightLightKinds, ReportsTheBuildAndAgrees) {
  namespace fs = std::filesystem;
  const fs::path out = scratch_dir() / "out";
  auto report = [&] {
    std::ifstream file(out / "report.json");
    return nlohmann::json::parse(file);
  };
  for (const std::string pass : {"raster", "compute"}) {
    const CliResult r = run_cli({"--width", "64", "--height", "48", "--light-pass", pass, "--light-kinds", "branch",
                                 "--baseline", "naive", "--out", out.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = report();
    EXPECT_EQ(j["light_kinds"], "branch");
    EXPECT_EQ(j["light_pass"], pass);
    EXPECT_EQ(j["tile_pipelines"]["count"], 8);
    EXPECT_EQ(j["equivalence"]["pixels_different"], 0);
    EXPECT_NE(r.out.find("light kinds branch: SKY and LIGHT_SCATTERING as run-time branches, 8 tile-pass pipelines"),
              std::string::npos)
        << r.out;
  }
  ASSERT_EQ(run_cli({"--width", "64", "--height", "48", "--light-kinds", "specialization", "--baseline", "naive",
                     "--out", out.string()})
                .exit_code,
            0);
  EXPECT_EQ(report()["light_kinds"], "specialization");
  EXPECT_EQ(report()["tile_pipelines"]["count"], 32);
  EXPECT_EQ(report()["equivalence"]["pixels_different"], 0);
  const CliResult plain = run_cli({"--width", "64", "--height", "48", "--baseline", "none", "--out", out.string()});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(report()["light_kinds"], "variant");
  EXPECT_EQ(plain.out.find("light kinds"), std::string::npos) << plain.out;
  const CliResult bad = run_cli({"--light-kinds", "uniform", "--out", out.string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--light-kinds"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace tilelight::test
