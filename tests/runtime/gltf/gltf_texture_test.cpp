// Base colour textures: the textured quad of tests/fixtures/gltf (a 2x2 PNG, nearest filtering,
// clamped) loads to the same texture and uvs whichever way its image is stored; the mip chain
// the renderer uploads averages in linear light.
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight/scene/texture_mips.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace tilelight {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace gltf_texture_test {
namespace {

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;
const std::filesystem::path kModels = TILELIGHT_ASSIMP_GLTF2_MODELS;

// make_fixtures.py's TEXELS: red, green / blue, white, rows from the top.
const std::vector<std::uint8_t> kQuadTexels{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};

class TexturedQuad : public ::testing::TestWithParam<const char*> {};

TEST_P(TexturedQuad, LoadsItsTextureSamplerAndUvs) {
  const Scene scene = load_gltf_scene(kFixtures / GetParam());
  ASSERT_EQ(scene.textures.size(), 1u);
  const Texture& texture = scene.textures[0];
  EXPECT_EQ(texture.name, "textures[0]");
  EXPECT_EQ(texture.width, 2u);
  EXPECT_EQ(texture.height, 2u);
  EXPECT_EQ(texture.rgba, kQuadTexels);
  EXPECT_EQ(texture.sampling.magnify, TextureFilter::nearest);
  EXPECT_EQ(texture.sampling.minify, TextureFilter::nearest);
  EXPECT_FALSE(texture.sampling.mipmapped);
  EXPECT_EQ(texture.sampling.wrap_u, TextureWrap::clamp_to_edge);
  EXPECT_EQ(texture.sampling.wrap_v, TextureWrap::clamp_to_edge);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].base_colour_texture, std::optional<std::uint32_t>(0));
  const std::vector<glm::vec2> expected{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  ASSERT_EQ(scene.meshes[0].vertices.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(scene.meshes[0].vertices[i].uv, expected[i]) << "vertex " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryImageStorage, TexturedQuad,
                         ::testing::Values("textured_quad.gltf",            // data URI
                                           "textured_quad.glb",             // buffer view
                                           "textured_quad_external.gltf",   // a file beside it
                                           "textured_quad_texcoord1.gltf")  // TEXCOORD_1, normalized bytes
);

TEST(GltfTextures, MeshesWithoutATextureHaveNone) {
  const Scene scene = load_gltf_scene(kFixtures / "box.gltf");
  EXPECT_TRUE(scene.textures.empty());
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_FALSE(scene.meshes[0].base_colour_texture.has_value());
}

TEST(GltfTextures, FromMemoryWithoutAFolderAnExternalImageIsAnError) {
  std::ifstream in(kFixtures / "textured_quad_external.gltf", std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  try {
    (void)load_gltf_scene_from_memory(bytes, "memory.gltf", {});
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "memory.gltf: images[0]: the external image \"textured_quad.png\" is not read (a load from memory "
                 "reads no files)");
  }
}

TEST(GltfTextures, AssimpsBoxTexturedSamplesTheCesiumLogoInEveryContainer) {
  ASSERT_TRUE(std::filesystem::is_directory(kModels)) << kModels << " is missing: install assimp-testmodels";
  std::vector<std::uint8_t> first;
  for (const char* file : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                           "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
    const Scene scene = load_gltf_scene(kModels / file);
    ASSERT_EQ(scene.textures.size(), 1u) << file;
    EXPECT_EQ(scene.textures[0].width, 211u) << file;  // CesiumLogoFlat.png
    EXPECT_EQ(scene.textures[0].height, 211u) << file;
    ASSERT_TRUE(scene.meshes[0].base_colour_texture.has_value()) << file;
    if (first.empty()) first = scene.textures[0].rgba;
    EXPECT_EQ(scene.textures[0].rgba, first) << file << " decodes to other pixels";
  }
}

TEST(TextureMips, EveryLevelDownToOneTexelHalvingEachSide) {
  Texture texture{"t", 5, 3, std::vector<std::uint8_t>(5 * 3 * 4, 128), {}};
  const std::vector<TextureMip> chain = srgb_mip_chain(texture);
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_EQ(mip_level_count(5, 3), 3u);
  EXPECT_EQ(mip_level_count(1, 1), 1u);
  EXPECT_EQ(mip_level_count(256, 16), 9u);
  EXPECT_EQ(chain[0].rgba, texture.rgba);
  EXPECT_EQ(chain[1].width, 2u);
  EXPECT_EQ(chain[1].height, 1u);
  EXPECT_EQ(chain[2].width, 1u);
  EXPECT_EQ(chain[2].height, 1u);
  for (const TextureMip& mip : chain) {
    ASSERT_EQ(mip.rgba.size(), std::size_t{mip.width} * mip.height * 4);
    for (std::uint8_t value : mip.rgba) EXPECT_EQ(value, 128) << "a uniform texture stays uniform";
  }
}

TEST(TextureMips, ColourIsAveragedInLinearLightAndAlphaDirectly) {
  // Black and white texels, alpha 0 and 255: linear mean 0.5 is sRGB 188 (0.7354 * 255); alpha 128.
  Texture texture{"t", 2, 1, {0, 0, 0, 0, 255, 255, 255, 255}, {}};
  const std::vector<TextureMip> chain = srgb_mip_chain(texture);
  ASSERT_EQ(chain.size(), 2u);
  EXPECT_EQ(chain[1].rgba, (std::vector<std::uint8_t>{188, 188, 188, 128}));
}

}  // namespace
}  // namespace gltf_texture_test
}  // namespace tilelight
