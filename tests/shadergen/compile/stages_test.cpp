// Every stage (tests/fixtures/stages): one shader per stage, each stage taken from the file's
// extension alone; every blob valid for Vulkan 1.2, the manifest naming each stage, the mesh
// and task pair reflected with their work-group sizes, and the ray-tracing stages' resources.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

using nlohmann::json;

class EveryStage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<sgtest::TempDir>("every-stage");
    auto summary =
        sgtest::build(sgtest::fixtures_dir() / "stages" / "stages.json", dir_->path() / "out", dir_->path() / "cache");
    if (!summary.ok())
      error_ = summary.errors().front().to_string();
    else
      manifest_ = json::parse(sgtest::read_file(dir_->path() / "out" / "manifest.json"));
  }
  static void TearDownTestSuite() { dir_.reset(); }
  void SetUp() override { ASSERT_TRUE(error_.empty()) << error_; }

  static const json& blob_of(const std::string& companion) {
    for (const json& c : manifest_["companions"])
      if (c["name"] == companion)
        for (const json& b : manifest_["blobs"])
          if (b["spirv"] == c["spirv"]) return b;
    static const json none;
    return none;
  }

  static inline std::unique_ptr<sgtest::TempDir> dir_;
  static inline json manifest_;
  static inline std::string error_;
};

TEST_F(EveryStage, EachStageComesFromTheExtension) {
  EXPECT_EQ(manifest_["stage"], "vertex") << "surface.vert, no \"stage\" key";
  const std::vector<std::pair<std::string, std::string>> expected = {{"patch_control", "tess_control"},
                                                                     {"patch_evaluation", "tess_evaluation"},
                                                                     {"outline", "geometry"},
                                                                     {"shade", "fragment"},
                                                                     {"cull", "compute"},
                                                                     {"meshlet_task", "task"},
                                                                     {"meshlet", "mesh"},
                                                                     {"primary_rays", "ray_generation"},
                                                                     {"opaque_hit", "closest_hit"},
                                                                     {"alpha_hit", "any_hit"},
                                                                     {"sky", "miss"},
                                                                     {"sphere", "intersection"},
                                                                     {"light_call", "callable"}};
  ASSERT_EQ(manifest_["companions"].size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(manifest_["companions"][i]["name"], expected[i].first);
    EXPECT_EQ(manifest_["companions"][i]["stage"], expected[i].second) << expected[i].first;
    EXPECT_EQ(blob_of(expected[i].first)["stage"], expected[i].second) << expected[i].first;
  }
}

TEST_F(EveryStage, EveryBlobPassesSpirvValForVulkan12) {
  ASSERT_EQ(manifest_["blobs"].size(), 15u);
  for (const json& blob : manifest_["blobs"]) {
    std::string path = blob["spirv"];
    sgtest::ProcessResult val = sgtest::spirv_val(dir_->path() / "out" / path, "vulkan1.2");
    EXPECT_EQ(val.exit_code, 0) << blob["stage"] << " " << path << "\n" << val.out << val.err;
  }
}

TEST_F(EveryStage, TaskAndMeshReportTheirWorkGroups) {
  EXPECT_EQ(blob_of("meshlet_task")["local_size"], json::array({32, 1, 1}));
  EXPECT_EQ(blob_of("meshlet")["local_size"], json::array({1, 1, 1}));
  EXPECT_EQ(blob_of("meshlet")["outputs"][0]["location"], 0);
  EXPECT_FALSE(blob_of("shade").contains("local_size")) << "a graphics stage has no work group";
}

TEST_F(EveryStage, RayGenerationBindsTheSceneAndTheTarget) {
  const json& bindings = blob_of("primary_rays")["bindings"];
  ASSERT_EQ(bindings.size(), 2u);
  EXPECT_EQ(bindings[0]["kind"], "acceleration_structure");
  EXPECT_EQ(bindings[0]["stages"], json::array({"ray_generation"}));
  EXPECT_EQ(bindings[1]["kind"], "storage_image");
}

}  // namespace
