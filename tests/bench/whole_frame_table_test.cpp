// The baselines comparison of tilelight_sweep --baselines all (what scripts/gpu-bench.sh runs on
// the lent GPU): its markdown table, results.json, the G-buffer-read limit and the options that
// ask for it. Measurements are made up here; nothing renders.

#include "sweep/gbuffer_bound.h"
#include "sweep/measurement.h"
#include "sweep/sweep_json.h"
#include "sweep/sweep_options.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_tables.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace tilelight;
using namespace tilelight::sweep;

FrameTimings frame(double scale, bool whole_frame) {
  FrameTimings t;
  t.classification = 0.125 * scale;
  t.index_build_gpu = 0.125 * scale;
  t.tiled_light = 0.75 * scale;
  t.naive_light = 2.0 * scale;
  t.dynamic_light = 1.5 * scale;
  if (whole_frame) {  // what the renderer fills once the floor pass and whole frames are timed
    t.floor_light = 0.5 * scale;
    t.frame_classified = 4.0 * scale;
    t.frame_naive = 6.0 * scale;
    t.frame_dynamic = 5.0 * scale;
  }
  return t;
}

// 3840x2160, 2x MSAA, compute, GPU index build, Baselines::all; three frames, the last one
// slower throughout (ratios within a frame are the same in all three).
Measurement measurement(const std::string& camera, bool whole_frame) {
  Measurement m;
  m.options.width = 3840;
  m.options.height = 2160;
  m.options.msaa = 2;
  m.options.camera = camera;
  m.options.path = IndexPath::gpu;
  m.options.light_pass = LightPass::compute;
  m.options.baselines = Baselines::all;
  m.key = configuration_key(m.options);
  m.frames = 3;
  m.msaa_samples = 2;
  m.frame_timings = {frame(1.0, whole_frame), frame(1.0, whole_frame), frame(3.0, whole_frame)};
  m.timings = all_medians(m.frame_timings);
  return m;
}

const Comparison kBaselines{Facet::baselines, "baselines", "title", {}};

TEST(WholeFrameTable, RowsSummaryAndLimit) {
  const Measurement with = measurement("default", true);
  const Measurement without = measurement("sky", false);  // the renderer of today: those fields read 0
  const std::string table = markdown_table(kBaselines, {&with, &without}, "NVIDIA H100 80GB HBM3");
  EXPECT_NE(table.find("| light pass | MSAA | size | index build | camera | classified light | naive light | dynamic "
                       "light | floor light | classified frame | naive frame | dynamic frame | light vs naive | light "
                       "vs dynamic | frame vs naive | frame vs dynamic | pixels differ (classified, dynamic) |\n"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("| compute | 2x | 3840x2160 | GPU | default | 1.000 | 2.000 | 1.500 | 0.500 | 4.000 | 6.000 | "
                       "5.000 | 2.00x | 1.50x | 1.50x | 1.25x | 0, 0 |\n"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("| compute | 2x | 3840x2160 | GPU | sky | 1.000 | 2.000 | 1.500 | - | - | - | - | 2.00x | "
                       "1.50x | - | - | 0, 0 |\n"),
            std::string::npos)
      << table;
  // 3840 x 2160 x 2 samples x 24 bytes = 398,131,200 bytes; at 3.35 TB/s 0.119 ms.
  EXPECT_NE(table.find("| light pass, MSAA, size | cameras | light vs naive | light vs dynamic | frame vs naive | "
                       "frame vs dynamic | G-buffer read | limit at 3.35 TB/s |\n"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("| compute, 2x MSAA, 3840x2160, GPU index build | 2 | 2.00x / 2.00x / 2.00x | 1.50x / "
                       "1.50x / 1.50x | 1.50x / 1.50x / 1.50x | 1.25x / 1.25x / 1.25x | 398.1 MB | 0.119 |\n"),
            std::string::npos)
      << table;
}

TEST(WholeFrameTable, UnknownDeviceAndNoWholeFrames) {
  const Measurement without = measurement("sky", false);
  const std::string table = markdown_table(kBaselines, {&without}, "llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_NE(table.find("| G-buffer read | limit (bandwidth unknown) |\n"), std::string::npos) << table;
  EXPECT_NE(table.find("| 1 | 2.00x / 2.00x / 2.00x | 1.50x / 1.50x / 1.50x | - | - | 398.1 MB | unknown |\n"),
            std::string::npos)
      << table;
}

TEST(WholeFrameTable, BothBaselinesKeepTheLightPathTable) {
  Measurement m = measurement("default", true);
  m.options.baselines = Baselines::both;
  const std::string table = markdown_table(kBaselines, {&m}, "NVIDIA H100 80GB HBM3");
  EXPECT_EQ(table.find("floor light"), std::string::npos) << table;
  EXPECT_NE(table.find("| tiled light | classified total | vs naive | vs dynamic |"), std::string::npos) << table;
}

TEST(GBufferBound, BytesBandwidthAndLimit) {
  EXPECT_EQ(kGBufferBytesPerSample, 24u);  // RT0 RGBA8, RT1 and RT2 RGBA16F, RT3 R32F
  EXPECT_EQ(gbuffer_bytes(3840, 2160, 2), 398131200u);
  EXPECT_EQ(gbuffer_bytes(1920, 1080, 1), 49766400u);
  EXPECT_EQ(memory_bandwidth("NVIDIA H100 80GB HBM3"), 3.35e12);
  EXPECT_EQ(memory_bandwidth("NVIDIA H100 PCIe"), 2.0e12);
  EXPECT_EQ(memory_bandwidth("NVIDIA H200"), 4.8e12);
  EXPECT_EQ(memory_bandwidth("llvmpipe (LLVM 15.0.6, 256 bits)"), std::nullopt);
  EXPECT_EQ(gbuffer_read_bound_ms(4'800'000'000, 4.8e12), 1.0);
  EXPECT_EQ(gbuffer_read_bound_ms(4'800'000'000, std::nullopt), std::nullopt);
}

TEST(WholeFrameJson, RatiosTimingsAndLimit) {
  SweepOptions options;
  options.sizes = {{3840, 2160, "3840x2160"}};
  SweepPlan plan;
  const std::vector<Measurement> measurements{measurement("default", true), measurement("sky", false)};
  for (const Measurement& m : measurements) plan.configurations.push_back(m.options);
  const SweepRun run{"NVIDIA H200", "", &options, &plan, &measurements, "", 0, {}};
  const nlohmann::json j = nlohmann::json::parse(results_json(run));
  EXPECT_EQ(j["memory_bandwidth_bytes_per_s"], 4.8e12);
  const nlohmann::json& with = j["configurations"][0];
  EXPECT_EQ(with["key"], "3840x2160 tile 4 gpu optimised coalesced auto camera default msaa 2 compute baselines all");
  EXPECT_EQ(with["baselines"], "all");
  EXPECT_EQ(with["gbuffer_bytes"], 398131200u);
  EXPECT_EQ(with["gbuffer_read_bound_ms"], 0.0829);  // 398,131,200 bytes at 4.8 TB/s
  EXPECT_EQ(with["timings_ms"]["frame_classified"], 4.0);
  EXPECT_EQ(with["timings_ms"]["floor_light"], 0.5);
  EXPECT_EQ(with["frame_timings_ms"].size(), 3u);
  EXPECT_EQ(with["frame_timings_ms"][2]["frame_naive"], 18.0);
  EXPECT_EQ(with["frame_ratios"]["whole_frame_vs_dynamic"].dump(), R"({"max":1.25,"median":1.25,"min":1.25})");
  EXPECT_EQ(with["frame_ratios"]["light_vs_naive"]["median"], 2.0);
  const nlohmann::json& without = j["configurations"][1];
  EXPECT_TRUE(without["frame_ratios"]["whole_frame_vs_naive"].is_null());
  EXPECT_EQ(without["frame_ratios"]["light_vs_dynamic"]["median"], 1.5);
}

TEST(SweepOptions, PathsAndBaselines) {
  SweepOptions options;
  int exit_code = 0;
  std::ostringstream out, err;
  const char* argv[] = {"tilelight_sweep", "--path", "cpu,gpu", "--baselines", "all", "--only", "baselines"};
  ASSERT_TRUE(parse_sweep_options(7, argv, options, exit_code, out, err)) << err.str();
  EXPECT_EQ(options.paths, (std::vector<IndexPath>{IndexPath::cpu, IndexPath::gpu}));
  EXPECT_EQ(options.baselines, Baselines::all);
  // Two index builds for each light pass, MSAA mode, size and camera; every one runs all baselines.
  const SweepPlan plan = make_sweep_plan(options);
  ASSERT_EQ(plan.comparisons.size(), 1u);
  EXPECT_EQ(plan.configurations.size(), 2u * 2u * 3u * 2u * 6u);
  EXPECT_EQ(plan.comparisons[0].keys[6],
            "1280x720 tile 4 gpu optimised coalesced auto camera default msaa auto raster baselines all");
}

TEST(SweepOptions, DefaultsKeepOneCpuPathAndBothBaselines) {
  SweepOptions options;
  int exit_code = 0;
  std::ostringstream out, err;
  const char* argv[] = {"tilelight_sweep"};
  ASSERT_TRUE(parse_sweep_options(1, argv, options, exit_code, out, err));
  EXPECT_EQ(options.paths, std::vector<IndexPath>{IndexPath::cpu});
  EXPECT_EQ(options.baselines, Baselines::both);
  EXPECT_EQ(configuration_key(make_sweep_plan(options).configurations.front()),
            "1280x720 tile 4 cpu optimised coalesced auto camera default msaa auto raster");
}

// tilelight's camera flags: a placed camera is the view "eye", alone unless --cameras names others.
TEST(SweepOptions, EyeAndTargetMakeTheViewEye) {
  for (const bool with_cameras : {false, true}) {
    SweepOptions options;
    int exit_code = 0;
    std::ostringstream out, err;
    std::vector<const char*> argv{"tilelight_sweep", "--eye", "1,2,3", "--target", "0,0,0", "--fov", "45"};
    if (with_cameras) argv.insert(argv.end(), {"--cameras", "low"});
    ASSERT_TRUE(parse_sweep_options(static_cast<int>(argv.size()), argv.data(), options, exit_code, out, err))
        << err.str();
    EXPECT_EQ(options.cameras,
              with_cameras ? (std::vector<std::string>{"low", "eye"}) : std::vector<std::string>{"eye"});
    EXPECT_EQ(options.view.eye, "1,2,3");
    EXPECT_EQ(options.view.fov_deg, 45.0);
  }
  SweepOptions options;
  int exit_code = 0;
  std::ostringstream out, err;
  const char* argv[] = {"tilelight_sweep", "--eye", "1,2", "--target", "0,0,0"};
  EXPECT_FALSE(parse_sweep_options(5, argv, options, exit_code, out, err));
  EXPECT_EQ(exit_code, 2);
  EXPECT_NE(err.str().find("--eye: 1,2 is not X,Y,Z"), std::string::npos) << err.str();
}

// --cull on,off: every view of the baseline comparison with and without batch culling, the
// second keyed and labelled as such; the design choices stay culled.
TEST(SweepOptions, CullOnAndOffDoubleTheViews) {
  SweepOptions options;
  int exit_code = 0;
  std::ostringstream out, err;
  const char* argv[] = {"tilelight_sweep", "--cull", "on,off", "--cameras", "low", "--light-passes", "compute"};
  ASSERT_TRUE(parse_sweep_options(7, argv, options, exit_code, out, err)) << err.str();
  EXPECT_EQ(options.culls, (std::vector<bool>{true, false}));
  const SweepPlan plan = make_sweep_plan(options);
  const Comparison& baselines = plan.comparisons.back();
  ASSERT_EQ(baselines.id, "baselines");
  ASSERT_EQ(baselines.keys.size(), 2u * 3u * 2u);  // MSAA auto and 1, three sizes, culling on and off
  EXPECT_EQ(baselines.keys[0], "1280x720 tile 4 cpu optimised coalesced auto camera low msaa auto compute");
  EXPECT_EQ(baselines.keys[1], "1280x720 tile 4 cpu optimised coalesced auto camera low msaa auto compute no-cull");
  for (const RendererOptions& o : plan.configurations) {
    if (configuration_key(o).find("compute") == std::string::npos) {
      EXPECT_TRUE(o.cull_batches);
    }
  }

  const char* bad[] = {"tilelight_sweep", "--cull", "maybe"};
  EXPECT_FALSE(parse_sweep_options(3, bad, options, exit_code, out, err));
  EXPECT_EQ(exit_code, 2);
  EXPECT_NE(err.str().find("--cull"), std::string::npos) << err.str();
}

// The design choices are measured from the first camera: a placed view when --eye is given.
TEST(SweepOptions, DesignChoicesUseTheFirstCamera) {
  SweepOptions options;
  int exit_code = 0;
  std::ostringstream out, err;
  const char* argv[] = {"tilelight_sweep", "--eye", "1,2,3", "--target", "0,0,0", "--only", "tile_size"};
  ASSERT_TRUE(parse_sweep_options(7, argv, options, exit_code, out, err)) << err.str();
  const SweepPlan plan = make_sweep_plan(options);
  ASSERT_EQ(plan.configurations.size(), 3u);
  for (const RendererOptions& o : plan.configurations) EXPECT_EQ(o.camera, "eye");
}

}  // namespace
