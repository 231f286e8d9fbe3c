// tilelight --baseline, run in-process: which passes report.json times, the whole-frame keys and
// how they add up, the per-frame ratios (null for a baseline that did not run), the comparison
// (null when no lit baseline ran), the floor's frame and the console's lines.
#include "frame_support.h"
#include "tilelight/app/cli.h"
#include "tilelight_testing/test_support.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tilelight::test {
namespace {

namespace fs = std::filesystem;

struct BaselineCase {
  const char* baseline;
  const char* light_pass;
  const char* path;
  bool naive, dynamic, floor;  // the passes that must run
};

void PrintTo(const BaselineCase& c, std::ostream* os) { *os << c.baseline << " " << c.light_pass << " " << c.path; }

constexpr int kFrames = 2;
// Each figure is rounded to 0.001 ms on its own, so a sum of three differs by up to 0.0015.
constexpr double kRounding = 0.002;

const char* const kWholeFrameKeys[] = {"frame_naive", "frame_dynamic", "frame_classified", "gbuffer_plain",
                                       "floor_light"};

nlohmann::json run_report(const BaselineCase& c, const fs::path& out, std::string& console) {
  const CliResult r =
      run_cli({"--width", "64", "--height", "48", "--frames", std::to_string(kFrames), "--baseline", c.baseline,
               "--light-pass", c.light_pass, "--path", c.path, "--validation", "--out", out.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  console = r.out;
  std::ifstream file(out / "report.json");
  return nlohmann::json::parse(file);
}

// A baseline frame is the sum of its passes, frame by frame; 0 where it did not run.
void expect_baseline_frame(const nlohmann::json& frames, const char* frame, const char* light, bool ran) {
  for (int f = 0; f < kFrames; ++f) {
    const double sum = frames["shadow_map"][f].get<double>() + frames["gbuffer_plain"][f].get<double>() +
                       frames[light][f].get<double>();
    EXPECT_NEAR(frames[frame][f].get<double>(), ran ? sum : 0.0, kRounding) << frame << ", frame " << f;
    EXPECT_EQ(frames[light][f].get<double>() > 0, ran) << light << ", frame " << f;
  }
}

// The classified frame, end to end, spans at least its GPU passes.
void expect_classified_frame(const nlohmann::json& frames) {
  for (int f = 0; f < kFrames; ++f) {
    double parts = 0;
    for (const char* part : {"shadow_map", "gbuffer", "classification", "index_build_gpu", "tiled_light"}) {
      parts += frames[part][f].get<double>();
    }
    EXPECT_GE(frames["frame_classified"][f].get<double>() + kRounding, parts) << "frame " << f;
  }
}

void expect_ratio(const nlohmann::json& ratios, const char* key, bool ran) {
  ASSERT_TRUE(ratios.contains(key)) << key;
  const nlohmann::json& r = ratios[key];
  if (!ran) {
    EXPECT_TRUE(r.is_null()) << key << ": " << r;
    return;
  }
  ASSERT_TRUE(r.is_object()) << key;
  EXPECT_GT(r["min"].get<double>(), 0.0) << key;
  EXPECT_LE(r["min"].get<double>(), r["median"].get<double>()) << key;
  EXPECT_LE(r["median"].get<double>(), r["max"].get<double>()) << key;
}

class WholeFrameReport : public ::testing::TestWithParam<BaselineCase> {};

TEST_P(WholeFrameReport, KeysRatiosAndFilesFollowTheBaselines) {
  const BaselineCase& c = GetParam();
  const fs::path out = scratch_dir() / "out";
  std::string console;
  const nlohmann::json report = run_report(c, out, console);
  EXPECT_EQ(report["baselines"], c.baseline);
  const nlohmann::json& medians = report["timings_ms"];
  const nlohmann::json& frames = report["frame_timings_ms"];
  for (const char* key : kWholeFrameKeys) {
    ASSERT_TRUE(medians.contains(key)) << key;
    ASSERT_EQ(frames[key].size(), static_cast<std::size_t>(kFrames)) << key;
  }
  const bool any = c.naive || c.dynamic || c.floor;
  for (int f = 0; f < kFrames; ++f) {
    EXPECT_EQ(frames["gbuffer_plain"][f].get<double>() > 0, any) << "a plain G-buffer pass, frame " << f;
  }
  expect_baseline_frame(frames, "frame_naive", "naive_light", c.naive);
  expect_baseline_frame(frames, "frame_dynamic", "dynamic_light", c.dynamic);
  for (int f = 0; f < kFrames; ++f) EXPECT_EQ(frames["floor_light"][f].get<double>() > 0, c.floor) << f;
  expect_classified_frame(frames);

  expect_ratio(report["ratios"], "whole_frame_vs_naive", c.naive);
  expect_ratio(report["ratios"], "light_vs_naive", c.naive);
  expect_ratio(report["ratios"], "whole_frame_vs_dynamic", c.dynamic);
  expect_ratio(report["ratios"], "light_vs_dynamic", c.dynamic);

  EXPECT_EQ(fs::exists(out / "frame_naive.png"), c.naive);
  EXPECT_EQ(fs::exists(out / "frame_dynamic.png"), c.dynamic);
  EXPECT_EQ(fs::exists(out / "frame_floor.png"), c.floor);
  EXPECT_EQ(console.find("floor") != std::string::npos, c.floor) << console;
  if (c.naive || c.dynamic) {
    EXPECT_EQ(report["equivalence"]["pixels_different"], 0);
    EXPECT_EQ(report["equivalence"]["reference"], c.naive ? "naive" : "dynamic");
    EXPECT_EQ(report["dynamic_equivalence"].is_null(), !(c.naive && c.dynamic));
  } else {
    EXPECT_TRUE(report["equivalence"].is_null());
    EXPECT_TRUE(report["dynamic_equivalence"].is_null());
    EXPECT_NE(console.find("; no comparison ran (neither the naive nor the dynamic pass ran)"), std::string::npos)
        << console;
  }
  EXPECT_EQ(console.find("whole frame vs naive (every feature on every sample): ") != std::string::npos, c.naive)
      << console;
  EXPECT_EQ(console.find("light path vs dynamic (per-pixel branching): ") != std::string::npos, c.dynamic) << console;
}

INSTANTIATE_TEST_SUITE_P(Baselines, WholeFrameReport,
                         ::testing::Values(BaselineCase{"none", "compute", "cpu", false, false, false},
                                           BaselineCase{"naive", "raster", "gpu", true, false, false},
                                           BaselineCase{"dynamic", "compute", "gpu", false, true, false},
                                           BaselineCase{"both", "raster", "cpu", true, true, false},
                                           BaselineCase{"floor", "raster", "cpu", false, false, true},
                                           BaselineCase{"all", "compute", "cpu", true, true, true},
                                           BaselineCase{"all", "raster", "gpu", true, true, true}),
                         [](const ::testing::TestParamInfo<BaselineCase>& param_info) {
                           return std::string(param_info.param.baseline) + "_" + param_info.param.light_pass + "_" +
                                  param_info.param.path;
                         });

// A run without the floor pass retires the floor frame an earlier run left in the folder.
TEST(WholeFrameReportFiles, FloorFrameGoesWithTheFloorPass) {
  const fs::path out = scratch_dir() / "out";
  ASSERT_EQ(run_cli({"--width", "32", "--height", "32", "--baseline", "floor", "--out", out.string()}).exit_code, 0);
  EXPECT_TRUE(fs::exists(out / "frame_floor.png"));
  ASSERT_EQ(run_cli({"--width", "32", "--height", "32", "--baseline", "none", "--out", out.string()}).exit_code, 0);
  EXPECT_FALSE(fs::exists(out / "frame_floor.png"));
  EXPECT_TRUE(fs::exists(out / "frame_classified.png"));
}

}  // namespace
}  // namespace tilelight::test
