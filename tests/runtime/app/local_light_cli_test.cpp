// tilelight's --local-light-pass, --local-light-shadows and --local-light-shadow-cache
// (docs/local-lights.md) and report.json's timings_ms.local_lights, timings_ms.local_light_shadows
// and local_light_shadows.
#include "frame_support.h"
#include "tilelight_testing/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace tilelight::test {
namespace {

namespace fs = std::filesystem;

TEST(LocalLightCli, BothPassesRunAndTheReportHasTheirTiming) {
  for (const char* pass : {"volumes", "fullscreen"}) {
    const fs::path out = scratch_dir() / (std::string("local_light_cli_") + pass);
    const CliResult r = run_cli({"--width", "32", "--height", "24", "--frames", "1", "--local-light-pass", pass,
                                 "--validation", "--out", out.string()});
    ASSERT_EQ(r.exit_code, 0) << pass << ": " << r.err;
    std::ifstream file(out / "report.json");
    const nlohmann::json report = nlohmann::json::parse(file);
    EXPECT_EQ(report["local_light_pass"], pass);
    // The procedural scene has no local lights (yet): the pass records nothing and costs 0.
    ASSERT_TRUE(report["timings_ms"].contains("local_lights")) << pass;
    EXPECT_EQ(report["timings_ms"]["local_lights"].get<double>(), 0.0) << pass;
  }
}

TEST(LocalLightCli, AnUnknownPassIsAUsageError) {
  const CliResult r = run_cli({"--local-light-pass", "deferred"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--local-light-pass"), std::string::npos) << r.err;
}

// The procedural scene's lamps (point, spot, box) with shadows: the pool in the report; cached
// maps are rendered in the warm-up frame only, so the timed frames render none.
TEST(LocalLightCli, ShadowsAndTheirCacheAreReported) {
  struct Run {
    const char* shadows;
    const char* cache;
  };
  for (const Run run : {Run{"on", "on"}, Run{"on", "off"}, Run{"off", "on"}}) {
    const std::string name = std::string(run.shadows) + "_" + run.cache;
    const fs::path out = scratch_dir() / ("local_light_shadows_" + name);
    const CliResult r = run_cli({"--width", "32", "--height", "24", "--frames", "2", "--lights", "3", "--baseline",
                                 "none", "--local-light-shadows", run.shadows, "--local-light-shadow-cache", run.cache,
                                 "--validation", "--out", out.string()});
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << name << ": " << r.err;
    std::ifstream file(out / "report.json");
    const nlohmann::json report = nlohmann::json::parse(file);
    const bool on = std::string(run.shadows) == "on";
    const nlohmann::json& pool = report["local_light_shadows"];
    EXPECT_EQ(pool["enabled"], on) << name;
    EXPECT_EQ(pool["cached"], std::string(run.cache) == "on") << name;
    EXPECT_EQ(pool["maps"], on ? 3 : 0) << name;
    EXPECT_EQ(pool["faces"], on ? 8 : 0) << name << ": a point light's 6, a spot's and a box's 1";
    EXPECT_EQ(pool["face_size"], 512) << name;
    EXPECT_EQ(pool["bytes"], on ? 9ull * 512 * 512 * 4 : 0) << name << ": an atlas of 3 x 3 faces";
    EXPECT_EQ(pool["cap_bytes"], 256ull << 20) << name;
    EXPECT_EQ(pool["unshadowed"], 0) << name;
    const nlohmann::json& frames = report["frame_timings_ms"]["local_light_shadows"];
    ASSERT_EQ(frames.size(), 2u) << name;
    for (const nlohmann::json& ms : frames) {
      // Rendered in every timed frame only without the cache; never without maps.
      EXPECT_EQ(ms.get<double>() > 0.0, on && std::string(run.cache) == "off") << name;
    }
  }
}

// 100 lamps (point, spot, box in turn: 8 faces per 3) need 268 faces; the default cap (256 MiB at
// 512²) holds 256: the first 96 lamps get maps, the last 4 are drawn unshadowed, with one warning.
TEST(LocalLightCli, LightsBeyondThePoolsCapAreWarnedAboutAndCounted) {
  const fs::path out = scratch_dir() / "local_light_shadow_cap";
  const CliResult r = run_cli({"--width", "32", "--height", "24", "--frames", "1", "--lights", "100", "--baseline",
                               "none", "--validation", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err,
            "warning: 4 local light(s) cast shadows but are drawn unshadowed: the shadow-map pool's cap of 256 MiB "
            "holds 256 faces of 512x512 (report.json local_light_shadows)\n");
  std::ifstream file(out / "report.json");
  const nlohmann::json pool = nlohmann::json::parse(file)["local_light_shadows"];
  EXPECT_EQ(pool["maps"], 96);
  EXPECT_EQ(pool["faces"], 256);
  EXPECT_EQ(pool["unshadowed"], 4);
  EXPECT_EQ(pool["bytes"], 256ull << 20);
}

TEST(LocalLightCli, UnknownShadowSettingsAreUsageErrorsNamingTheValue) {
  const CliResult shadows = run_cli({"--local-light-shadows", "maybe"});
  EXPECT_EQ(shadows.exit_code, 2);
  EXPECT_NE(shadows.err.find("--local-light-shadows: maybe not in {on,off}"), std::string::npos) << shadows.err;
  const CliResult cache = run_cli({"--local-light-shadow-cache", "sometimes"});
  EXPECT_EQ(cache.exit_code, 2);
  EXPECT_NE(cache.err.find("--local-light-shadow-cache: sometimes not in {on,off}"), std::string::npos) << cache.err;
}

}  // namespace
}  // namespace tilelight::test
