// tilelight --lights N (local_light_placement.h) and the lights of a --scene file: report.json's
// "local_lights" counts each type, for either scene; --lights with --scene is a usage error
// (exit 2) saying the file's own lights are used, with nothing written.
#include "frame_support.h"
#include "tilelight/app/cli.h"
#include "tilelight_testing/test_support.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tilelight::test {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace lights_cli_test {
namespace {

namespace fs = std::filesystem;

const fs::path kFixtures = TILELIGHT_GLTF_FIXTURES;
const std::string kHelpLine = "\nRun with --help for more information.\n";

nlohmann::json report_of(const fs::path& out) {
  std::ifstream file(out / "report.json");
  return nlohmann::json::parse(file);
}

nlohmann::json counts(int point, int spot, int box) { return {{"point", point}, {"spot", spot}, {"box", box}}; }

TEST(TilelightLightsCli, TheProceduralSceneReportsItsLightsByType) {
  const fs::path out = scratch_dir() / "out";
  const CliResult r = run_cli({"--lights", "4", "--width", "64", "--height", "48", "--baseline", "none", "--camera",
                               "street", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(report_of(out)["local_lights"], counts(2, 1, 1)) << "point, spot, box, point";
  EXPECT_EQ(report_of(out)["scene_warnings"], nlohmann::json::array());

  const fs::path none = scratch_dir() / "none";
  ASSERT_EQ(run_cli({"--width", "64", "--height", "48", "--baseline", "none", "--out", none.string()}).exit_code, 0);
  EXPECT_EQ(report_of(none)["local_lights"], counts(0, 0, 0)) << "--lights defaults to 0";
}

TEST(TilelightLightsCli, AFilesLightsAreCountedInTheReport) {
  const fs::path out = scratch_dir() / "out";
  const CliResult r = run_cli({"--scene", (kFixtures / "lights.gltf").string(), "--width", "64", "--height", "48",
                               "--baseline", "none", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = report_of(out);
  EXPECT_EQ(report["local_lights"], counts(2, 1, 1)) << "two directional lights: the sun, and one warned about";
  // The local light passes draw them: no warning says they are dropped, only the second sun.
  EXPECT_EQ(r.err.find("KHR_lights_punctual"), std::string::npos) << r.err;
  const std::string second_sun = "warning: " + (kFixtures / "lights.gltf").string() +
                                 ": 1 more directional light ignored: the first one is the sun, and there is one sun";
  EXPECT_NE(r.err.find(second_sun + "\n"), std::string::npos) << r.err;
  EXPECT_EQ(report["scene_warnings"], nlohmann::json::array({second_sun}));
}

TEST(TilelightLightsCli, LightsWithASceneFileIsAUsageErrorWritingNothing) {
  const fs::path out = scratch_dir() / "out";
  const std::string file = (kFixtures / "lights.gltf").string();
  for (const char* count : {"4", "0"}) {
    const CliResult r = run_cli({"--scene", file, "--lights", count, "--out", out.string()});
    EXPECT_EQ(r.exit_code, 2) << count;
    EXPECT_EQ(r.err, std::string("--lights ") + count + ": the procedural scene's lights, not --scene " + file +
                         "'s; the file's own lights (KHR_lights_punctual) are used" + kHelpLine);
    EXPECT_EQ(r.out, "");
  }
  for (const char* bad : {"1025", "-1", "many"}) {
    EXPECT_EQ(run_cli({"--lights", bad, "--out", out.string()}).exit_code, 2) << bad;
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(TilelightLightsCli, HelpNamesTheLightsFlag) {
  const CliResult help = run_cli({"--help"});
  ASSERT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--lights N"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("its own KHR_lights_punctual lights"), std::string::npos) << help.out;
}

}  // namespace
}  // namespace lights_cli_test
}  // namespace tilelight::test
