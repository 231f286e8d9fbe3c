// tilelight --scene: a glTF file rendered end to end, and bad files and flags answered with an
// exit status and a message naming the file, writing nothing.
#include "../../fixtures/gltf/ignored_features_warnings.h"
#include "frame_support.h"
#include "tilelight/app/cli.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight_testing/test_support.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tilelight::test {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace scene_cli_test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = TILELIGHT_ASSIMP_GLTF2_MODELS;
const fs::path kFixtures = TILELIGHT_GLTF_FIXTURES;

TEST(TilelightScene, RendersAGlbUnderValidationAndReportsIt) {
  const fs::path model = kModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  ASSERT_TRUE(fs::exists(model)) << "install Debian's assimp-testmodels (scripts/install-deps.sh --tests)";
  const fs::path out = scratch_dir() / "out";
  const CliResult r =
      run_cli({"--scene", model.string(), "--width", "160", "--height", "96", "--validation", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream file(out / "report.json");
  const nlohmann::json report = nlohmann::json::parse(file);
  EXPECT_EQ(report["scene"], "2CylinderEngine.glb");
  EXPECT_EQ(report["scene_triangles"], 121496);
  EXPECT_EQ(report["camera"], "default");
  EXPECT_GT(report["load_ms"].get<double>(), 0.0) << "parse, decode and upload take time";
  EXPECT_EQ(report["cull"], true);
  EXPECT_TRUE(report["culled"]["gbuffer_batches"].is_number_unsigned()) << report["culled"];
  EXPECT_TRUE(report["culled"]["shadow_batches"].is_number_unsigned()) << report["culled"];
  EXPECT_EQ(report["equivalence"]["pixels_different"], 0);
  EXPECT_EQ(report["dynamic_equivalence"]["pixels_different"], 0);
  EXPECT_NE(r.out.find("scene 2CylinderEngine.glb (121496 triangles)"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(out / "tile_classes.png"));
}

TEST(TilelightScene, TheProceduralSceneIsReportedAsNoFile) {
  const fs::path out = scratch_dir() / "out";
  const CliResult r = run_cli({"--width", "64", "--height", "48", "--baseline", "naive", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream file(out / "report.json");
  const nlohmann::json report = nlohmann::json::parse(file);
  EXPECT_TRUE(report["scene"].is_null());
  EXPECT_EQ(report["scene_warnings"], nlohmann::json::array());
  EXPECT_EQ(report["culled"], nlohmann::json({{"gbuffer_batches", 0}, {"shadow_batches", 0}}))
      << "the default camera sees every batch of the procedural scene";
  EXPECT_EQ(report["scene_triangles"], make_demo_scene().triangle_count());
  EXPECT_NE(r.out.find("scene procedural ("), std::string::npos) << r.out;
}

// What the file holds that is not drawn: one line each on stderr, the same lines in report.json.
TEST(TilelightScene, WarnsOfEveryIgnoredFeatureOnStderrAndInTheReport) {
  const fs::path model = kFixtures / "ignored_features.gltf";
  const fs::path out = scratch_dir() / "out";
  const CliResult r =
      run_cli({"--scene", model.string(), "--width", "64", "--height", "48", "--validation", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = ignored_features_warnings(model.string());

  std::string stderr_text;
  for (const std::string& line : lines) stderr_text += line + "\n";
  EXPECT_EQ(r.err, stderr_text);
  std::ifstream file_stream(out / "report.json");
  const nlohmann::json report = nlohmann::json::parse(file_stream);
  EXPECT_EQ(report["scene_warnings"], nlohmann::json(lines));
  EXPECT_EQ(report["equivalence"]["pixels_different"], 0);
  EXPECT_EQ(report["dynamic_equivalence"]["pixels_different"], 0);
}

// glTF 1.0 and a missing external file: exit 1, the whole message, nothing written.
TEST(TilelightScene, Gltf1AndMissingFilesAreNamedInOurWords) {
  const fs::path truck = kModels.parent_path() / "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";
  const fs::path bin = kFixtures / "bad_missing_bin.gltf";
  const std::vector<std::pair<fs::path, std::string>> cases{
      {kFixtures / "bad_gltf1.gltf", "glTF 1.0 is not supported; convert it to 2.0"},
      {kFixtures / "bad_gltf1.glb", "glTF 1.0 is not supported; convert it to 2.0"},
      {truck, "glTF 1.0 is not supported; convert it to 2.0"},
      {bin, "buffers[0]: the file " + (kFixtures / "no_such_file.bin").string() +
                " does not exist (uri \"no_such_file.bin\")"},
  };
  for (const auto& [path, message] : cases) {
    SCOPED_TRACE(path.string());
    const fs::path out = scratch_dir() / "out";
    const CliResult r = run_cli({"--scene", path.string(), "--out", out.string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "tilelight: error: --scene " + path.string() + ": " + message + "\n");
    EXPECT_FALSE(fs::exists(out)) << "the output folder was made";
  }
}

TEST(TilelightScene, ListsTheScenesCameras) {
  const CliResult r = run_cli({"--scene", (kFixtures / "box.glb").string(), "--list-cameras"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("default: ", 0), 0u) << r.out;
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << "one camera: " << r.out;
}

struct BadScene {
  fs::path file;
  std::string says;
};

// Every bad file: exit 1, "--scene FILE: what is wrong", and the output folder never made.
TEST(TilelightScene, BadFilesExitOneNamingTheFileAndWriteNothing) {
  const std::vector<BadScene> cases{
      {kFixtures / "bad_cycle.gltf", "the node hierarchy has a cycle"},
      {kFixtures / "bad_index_range.gltf", "index 99 at element 1 is out of range"},
      {kFixtures / "bad_accessor_range.gltf", "do not fit in bufferViews[0]"},
      {kFixtures / "bad_nan_position.gltf", "is not finite"},
      {kFixtures / "bad_wrong_type.gltf", "nodes[0].mesh: expected a non-negative integer"},
      {kFixtures / "bad_short_buffer.gltf", "its data URI holds 640 bytes"},
      {kFixtures / "bad_truncated.glb", "truncated GLB"},
      {kFixtures / "no_such_file.glb", "cannot open"},
      {kModels / "RecursiveNodes/RecursiveNodes.gltf", "cycle"},
      {kModels / "MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
      {kModels / "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "not finite"},
      {kFixtures / "bad_sparse_index_range.gltf", "accessors[0].sparse.indices: index 24 at element 3 is out of range"},
      {kFixtures / "bad_quantized_not_listed.gltf", "needs KHR_mesh_quantization"},
      {kFixtures / "bad_draco_stream.gltf",
       "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: not a Draco stream"},
  };
  for (const BadScene& c : cases) {
    SCOPED_TRACE(c.file.string());
    const fs::path out = scratch_dir() / "out";
    const CliResult r = run_cli({"--scene", c.file.string(), "--out", out.string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err.rfind("tilelight: error: --scene " + c.file.string() + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(out)) << "the output folder was made";
  }
}

TEST(TilelightScene, AnUnknownCameraOrSceneIndexIsAnErrorAndBadFlagsAUsageError) {
  const std::string box = (kFixtures / "box.glb").string();
  const CliResult camera = run_cli({"--scene", box, "--camera", "street", "--list-cameras"});
  EXPECT_EQ(camera.exit_code, 0) << "--list-cameras lists before a camera is chosen";
  const fs::path out = scratch_dir() / "out";
  const CliResult street = run_cli({"--scene", box, "--camera", "street", "--out", out.string()});
  EXPECT_EQ(street.exit_code, 2);
  EXPECT_EQ(street.err,
            "--camera street: the cameras sky, shadow, low, street, closeup belong to the procedural "
            "scene, not to --scene " +
                box +
                "; place one with --eye X,Y,Z --target X,Y,Z, or choose the "
                "file's own with --camera gltf:N (--list-cameras)\nRun with --help for more information.\n");
  const CliResult index = run_cli({"--scene", box, "--scene-index", "2", "--out", out.string()});
  EXPECT_EQ(index.exit_code, 1);
  EXPECT_NE(index.err.find("scene 2 does not exist (the file has 1 scene(s), 0 to 0)"), std::string::npos) << index.err;
  EXPECT_FALSE(fs::exists(out));

  EXPECT_EQ(run_cli({"--scene-index", "0", "--out", out.string()}).exit_code, 2) << "--scene-index needs --scene";
  EXPECT_EQ(run_cli({"--scene", box, "--scene-index", "-1", "--out", out.string()}).exit_code, 2);
  EXPECT_EQ(run_cli({"--scene"}).exit_code, 2);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace scene_cli_test
}  // namespace tilelight::test
