// Nothing a file holds is dropped silently: every feature the renderer does not draw is one
// warning line naming the file, glTF 1.0 is named as such, and a missing external file is
// named by the path the loader looked at.
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace tilelight {
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
  const std::string file = "warning: " + path.string() + ": ";
  const std::vector<std::string> expected{
      file + "2 animations ignored: drawn in the rest pose",
      file + "1 skin ignored: meshes are drawn as stored, unskinned",
      file + "1 camera cannot be chosen: orthographic, or placed by no node (--list-cameras says why)",
      file + "morph targets (1 primitive) ignored: drawn in the base shape",
      file + "points and lines (1 primitive) ignored: they have no surface",
      file + "vertex colours (1 primitive) ignored",
      file + "normalTexture (1 material) ignored",
      file + "emissiveFactor (1 material) ignored",
      file + "EXT_unknown_thing ignored",
      file + "KHR_lights_punctual (2 lights) ignored: the sun alone lights the scene",
      file + "KHR_materials_sheen (2 materials) ignored",
      file + "1 material uses alphaMode BLEND: drawn as MASK at 0.5; a deferred G-buffer cannot blend",
  };
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
}  // namespace tilelight
