// Nothing a file holds is dropped silently: every feature the renderer does not draw is one
// warning line naming the file, glTF 1.0 is named as such, and a missing external file is
// named by the path the loader looked at.
#include "../../fixtures/gltf/ignored_features_warnings.h"
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace tilelight {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace gltf_warnings_test {
namespace {

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;

std::string error_of(const std::filesystem::path& path) {
  try {
    (void)load_gltf(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "(loaded)";
}

TEST(GltfWarnings, EveryIgnoredFeatureIsOneLineNamingTheFile) {
  const std::filesystem::path path = kFixtures / "ignored_features.gltf";
  const GltfScene loaded = load_gltf(path);
  const std::vector<std::string> expected = test::ignored_features_warnings(path.string());

  EXPECT_EQ(loaded.warnings, expected);
  EXPECT_EQ(loaded.scene.triangle_count(), 24u) << "the box is drawn all the same";
}

TEST(GltfWarnings, AFileTheRendererDrawsWhollyHasNone) {
  for (const char* name : {"box.gltf", "textured_quad.glb", "box_sparse.gltf", "textured_quad_quantized.gltf"}) {
    EXPECT_EQ(load_gltf(kFixtures / name).warnings, std::vector<std::string>{}) << name;
  }
}

TEST(GltfWarnings, FromMemoryTheWarningsNameTheGivenName) {
  std::ifstream file(kFixtures / "ignored_features.gltf", std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(file), {}};
  const GltfScene loaded = load_gltf_from_memory(bytes, "memory.gltf", kFixtures);
  ASSERT_FALSE(loaded.warnings.empty());
  EXPECT_EQ(loaded.warnings[0], "warning: memory.gltf: 2 animations ignored: drawn in the rest pose");
}

TEST(GltfWarnings, Gltf1IsNamedAsSuch) {
  for (const char* name :
       {"bad_gltf1.gltf", "bad_gltf1_version_number.gltf", "bad_gltf1_no_version.gltf", "bad_gltf1.glb"}) {
    const std::filesystem::path path = kFixtures / name;
    EXPECT_EQ(error_of(path), path.string() + ": glTF 1.0 is not supported; convert it to 2.0");
  }
}

TEST(GltfWarnings, AMissingExternalFileIsNamedByItsResolvedPath) {
  const std::filesystem::path bin = kFixtures / "bad_missing_bin.gltf";
  EXPECT_EQ(error_of(bin), bin.string() + ": buffers[0]: the file " + (kFixtures / "no_such_file.bin").string() +
                               " does not exist (uri \"no_such_file.bin\")");
  const std::filesystem::path image = kFixtures / "bad_image_missing.gltf";
  EXPECT_EQ(error_of(image), image.string() + ": images[0]: the file " + (kFixtures / "no_such_image.png").string() +
                                 " does not exist (uri \"no_such_image.png\")");
}

}  // namespace
}  // namespace gltf_warnings_test
}  // namespace tilelight
