// tilelight's camera flags: --eye/--target/--up/--fov, --camera gltf:N, --list-cameras of a
// file, --sun-direction and the distance flags; report.json's camera and camera_pose; and every
// bad value a usage error (exit 2) naming the flag and the value, with nothing written.
#include "frame_support.h"
#include "tilelight_testing/test_support.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tilelight::test {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace camera_cli_test {
namespace {

namespace fs = std::filesystem;
const fs::path kFixtures = TILELIGHT_GLTF_FIXTURES;

nlohmann::json read_report(const fs::path& out) { return nlohmann::json::parse(std::ifstream(out / "report.json")); }

// box.gltf with two cameras: cameras[0] perspective, placed by a node at (0, 1, 6) facing -z;
// cameras[1] orthographic.
fs::path write_box_with_cameras(const fs::path& folder) {
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(kFixtures / "box.gltf"));
  gltf["nodes"].push_back({{"camera", 0}, {"translation", {0.0, 1.0, 6.0}}});
  gltf["scenes"][0]["nodes"].push_back(gltf["nodes"].size() - 1);
  gltf["cameras"] = nlohmann::json::array(
      {{{"type", "perspective"}, {"name", "front"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}},
       {{"type", "orthographic"}, {"orthographic", {{"xmag", 2.0}, {"ymag", 2.0}, {"znear", 0.1}, {"zfar", 9.0}}}}});
  fs::path file = folder / "box_cameras.gltf";
  std::ofstream(file) << gltf.dump();
  return file;
}

const std::string kHelpLine = "\nRun with --help for more information.\n";

TEST(TilelightCameraCli, EyeAndTargetPlaceTheCameraAndTheReportSaysWhere) {
  const fs::path out = scratch_dir() / "out";
  const CliResult r =
      run_cli({"--width", "64", "--height", "48", "--frames", "1", "--eye", "3.5,1.7,-9", "--target", "3.5,-8.9,-59",
               "--up", "0,1,0", "--fov", "50", "--camera", "sky", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["camera"], "eye") << "--eye overrides --camera";
  const nlohmann::json& pose = report["camera_pose"];
  EXPECT_EQ(pose["eye"], (std::vector<double>{3.5, 1.7f, -9}));
  EXPECT_EQ(pose["target"], (std::vector<double>{3.5, -8.9f, -59}));
  EXPECT_EQ(pose["up"], (std::vector<double>{0, 1, 0}));
  EXPECT_EQ(pose["fov_deg"], 50.0);
  EXPECT_EQ(report["equivalence"]["pixels_different"], 0);
}

TEST(TilelightCameraCli, ANamedCameraReportsItsPose) {
  const fs::path out = scratch_dir() / "out";
  ASSERT_EQ(run_cli({"--width", "64", "--height", "48", "--camera", "low", "--out", out.string()}).exit_code, 0);
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["camera"], "low");
  EXPECT_EQ(report["camera_pose"]["eye"], (std::vector<double>{-30, 1.8f, 5}));
  EXPECT_EQ(report["camera_pose"]["fov_deg"], 70.0);
}

TEST(TilelightCameraCli, AFileCameraIsListedChosenAndReported) {
  const fs::path dir = scratch_dir();  // emptied by each call
  const fs::path file = write_box_with_cameras(dir);
  const CliResult list = run_cli({"--scene", file.string(), "--list-cameras"});
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_NE(list.out.find("\ngltf:0: cameras[0] \"front\" placed by nodes[2], vertical field of view 40.1 degrees\n"),
            std::string::npos)
      << list.out;
  EXPECT_NE(list.out.find("gltf:1: cameras[1] (not usable: orthographic, and only perspective cameras are drawn)"),
            std::string::npos)
      << list.out;

  const fs::path out = dir / "out";
  const CliResult r = run_cli({"--width", "64", "--height", "48", "--scene", file.string(), "--camera", "gltf:0",
                               "--sun-direction", "0.2,1,0.3", "--shadow-fade-start", "4", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["camera"], "gltf:0");
  const std::vector<double> eye = report["camera_pose"]["eye"];
  EXPECT_NEAR(eye[0], 0.0, 1e-4);
  EXPECT_NEAR(eye[1], 1.0, 1e-4);
  EXPECT_NEAR(eye[2], 6.0, 1e-4);
  EXPECT_NEAR(report["camera_pose"]["fov_deg"].get<double>(), 0.7 * 180.0 / 3.14159265358979, 1e-3);
  EXPECT_EQ(report["equivalence"]["pixels_different"], 0);
}

struct BadCamera {
  std::vector<std::string> args;
  std::string message;  // stderr before the help line
};

TEST(TilelightCameraCli, BadCameraValuesAreUsageErrorsNamingTheFlagAndValue) {
  const fs::path dir = scratch_dir();  // emptied by each call
  const std::string file = write_box_with_cameras(dir).string();
  const fs::path out = dir / "out";
  // The file's orthographic camera is also a warning, printed as the scene loads.
  const std::string warning =
      "warning: " + file +
      ": 1 camera cannot be chosen: orthographic, or placed by no node (--list-cameras says why)\n";
  const std::vector<BadCamera> cases{
      {{"--eye", "1,2", "--target", "0,0,0"}, "--eye: 1,2 is not X,Y,Z (three finite numbers, comma-separated)"},
      {{"--eye", "1,2,3", "--target", "0,0,x"}, "--target: 0,0,x is not X,Y,Z (three finite numbers, comma-separated)"},
      {{"--eye", "1,2,3", "--target", "0,0,0", "--fov", "0"},
       "--fov: 0 is not a vertical field of view (degrees, more than 0 and less than 180)"},
      {{"--eye", "1,2,3", "--target", "0,0,0", "--fov", "180"},
       "--fov: 180 is not a vertical field of view (degrees, more than 0 and less than 180)"},
      {{"--eye", "1,2,3", "--target", "1,2,3"}, "--target 1,2,3: the same point as --eye: the camera has no direction"},
      {{"--eye", "0,5,0", "--target", "0,0,0"},
       "--up 0,1,0: parallel to the view from --eye to --target; choose another up"},
      {{"--eye", "0,0,0", "--target", "0,0,-1", "--up", "0,0,2"},
       "--up 0,0,2: parallel to the view from --eye to --target; choose another up"},
      {{"--sun-direction", "0,0,0"}, "--sun-direction: 0,0,0 has no direction (all zero)"},
      {{"--scene", file, "--camera", "gltf:7"},
       warning + "--camera gltf:7: box_cameras.gltf has 2 camera(s), gltf:0 to gltf:1"},
      {{"--scene", file, "--camera", "gltf:1"},
       warning + "--camera gltf:1: cameras[1]: orthographic, and only perspective cameras are drawn"},
      {{"--camera", "gltf:0"},
       "--camera gltf:0: unknown camera (known: default, sky, shadow, low, street, closeup; --list-cameras)"},
  };
  for (const BadCamera& c : cases) {
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"--width", "32", "--height", "32", "--out", out.string()});
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << c.message;
    EXPECT_EQ(r.err, c.message + kHelpLine);
    EXPECT_EQ(r.out, "");
  }
  // --target, --up and --fov need --eye, and --eye needs --target.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--eye", "1,2,3"}, {"--target", "1,2,3"}, {"--up", "0,1,0"}, {"--fov", "40"}}) {
    std::vector<std::string> with_out = args;
    with_out.insert(with_out.end(), {"--out", out.string()});
    EXPECT_EQ(run_cli(with_out).exit_code, 2) << args.front();
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(TilelightCameraCli, HelpNamesTheCameraAndLightingFlags) {
  const CliResult help = run_cli({"--help"});
  ASSERT_EQ(help.exit_code, 0);
  for (const char* flag : {"--eye", "--target", "--up", "--fov", "--sun-direction", "--shadow-fade-start",
                           "--shadow-fade-length", "--scattering-start", "gltf:N"}) {
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
  }
}

}  // namespace
}  // namespace camera_cli_test
}  // namespace tilelight::test
