// tilelight's --local-light-pass (docs/local-lights.md) and report.json's timings_ms.local_lights.
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

}  // namespace
}  // namespace tilelight::test
