// Materials as the loader hands them to the renderer: alphaMode MASK and its cutoff, BLEND for the
// forward pass (no mask, no warning), doubleSided, KHR_texture_transform baked into the uvs,
// KHR_materials_pbrSpecularGlossiness's diffuse as the base colour, mirrored instances rewound,
// and bad values named. Each file is built by the test (gltf_builder.h).
#include "gltf_builder.h"
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace tilelight {
namespace {

using test::GltfBuilder;

GltfScene load_with_warnings(const GltfBuilder& file) { return load_gltf_from_memory(file.bytes(), "m.gltf", {}); }
Scene load(const GltfBuilder& file) { return load_with_warnings(file).scene; }

// One quad with material `members`, and a 2x1 texture when the material refers to texture 0.
GltfBuilder one_quad(const std::string& members) {
  GltfBuilder file;
  file.add_texture(2, 1, {255, 0, 0, 255, 255, 255, 255, 0});
  file.add_quad({-1, -1}, {1, 1}, 0, file.add_material(members));
  return file;
}
Scene load_one(const std::string& members) { return load(one_quad(members)); }

std::string error_of(const std::string& members) {
  try {
    (void)load_one(members);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(GltfMaterial, OpaqueIsTheDefaultAndSingleSidedToo) {
  const Scene scene = load_one(R"("name": "plain")");
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_FALSE(scene.meshes[0].alpha_mask);
  EXPECT_FALSE(scene.meshes[0].double_sided);
  EXPECT_EQ(scene.instances[0].alpha_mask, glm::vec2(1.0f, 0.0f));
  EXPECT_TRUE(load_with_warnings(one_quad(R"("name": "plain")")).warnings.empty());
}

TEST(GltfMaterial, MaskCarriesItsCutoffAndTheFactorsAlpha) {
  const Scene scene = load_one(
      R"("alphaMode": "MASK", "alphaCutoff": 0.25, "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.75]})");
  EXPECT_TRUE(scene.meshes[0].alpha_mask);
  EXPECT_EQ(scene.instances[0].alpha_mask, glm::vec2(0.75f, 0.25f));
  EXPECT_EQ(load_one(R"("alphaMode": "MASK")").instances[0].alpha_mask, glm::vec2(1.0f, 0.5f)) << "default cutoff";
}

TEST(GltfMaterial, DoubleSidedIsHonoured) {
  EXPECT_TRUE(load_one(R"("doubleSided": true)").meshes[0].double_sided);
  EXPECT_FALSE(load_one(R"("doubleSided": false)").meshes[0].double_sided);
}

// BLEND meshes go to the forward pass: blended, not masked (glTF: alphaCutoff does not apply),
// with the base colour factor's alpha on the instance, and nothing to warn about.
TEST(GltfMaterial, BlendIsBlendedWithoutAMaskOrAWarning) {
  GltfBuilder file;
  file.add_quad({-1, -1}, {0, 1}, 0,
                file.add_material(R"("alphaMode": "BLEND", "alphaCutoff": 0.9, "pbrMetallicRoughness":
                    {"baseColorFactor": [1, 0, 0, 0.25]})"));
  file.add_quad({0, -1}, {1, 1}, 0, file.add_material(R"("alphaMode": "BLEND")"));
  const Scene scene = load(file);
  ASSERT_EQ(scene.meshes.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(scene.meshes[i].blend);
    EXPECT_FALSE(scene.meshes[i].alpha_mask);
    EXPECT_EQ(scene.instances[i].alpha_mask.y, 0.0f) << "BLEND ignores alphaCutoff";
  }
  EXPECT_EQ(scene.instances[0].alpha_mask.x, 0.25f) << "the base colour factor's alpha";
  EXPECT_EQ(scene.instances[1].alpha_mask.x, 1.0f);
  EXPECT_TRUE(load_with_warnings(file).warnings.empty());
  EXPECT_FALSE(load_one(R"("alphaMode": "MASK")").meshes[0].blend);
  EXPECT_FALSE(load_one(R"("alphaMode": "OPAQUE")").meshes[0].blend);
}

// Offset (0.5, 0.25) after scale (0.5, 2): uv (u, v) -> (0.5 u + 0.5, 2 v + 0.25).
TEST(GltfMaterial, TextureTransformMovesTheUvs) {
  const Scene scene = load_one(R"("pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions":
      {"KHR_texture_transform": {"offset": [0.5, 0.25], "scale": [0.5, 2]}}}})");
  ASSERT_EQ(scene.meshes[0].base_colour_texture, std::optional<std::uint32_t>(0));
  const std::vector<MeshVertex>& v = scene.meshes[0].vertices;
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[0].uv, glm::vec2(0.5f, 0.25f));  // uv (0, 0)
  EXPECT_EQ(v[1].uv, glm::vec2(0.5f, 2.25f));  // uv (0, 1)
  EXPECT_EQ(v[2].uv, glm::vec2(1.0f, 2.25f));  // uv (1, 1)
}

// glTF's rotation turns (1, 0) to (cos r, -sin r): a quarter turn gives (0, -1).
TEST(GltfMaterial, TextureTransformRotatesAndOverridesTheTexcoordSet) {
  const Scene scene = load_one(R"("pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions":
      {"KHR_texture_transform": {"rotation": 1.5707963267948966, "texCoord": 1}}}})");
  const std::vector<MeshVertex>& v = scene.meshes[0].vertices;
  // Vertex 3 has TEXCOORD_0 (1, 0), so TEXCOORD_1 (0, 1), which turns to (1, 0).
  EXPECT_NEAR(v[3].uv.x, 1.0f, 1e-6f);
  EXPECT_NEAR(v[3].uv.y, 0.0f, 1e-6f);
  // Vertex 1: TEXCOORD_1 (1, 0) -> (0, -1).
  EXPECT_NEAR(v[1].uv.x, 0.0f, 1e-6f);
  EXPECT_NEAR(v[1].uv.y, -1.0f, 1e-6f);
}

TEST(GltfMaterial, SpecularGlossinessDiffuseBecomesTheBaseColour) {
  const Scene scene = load_one(R"("pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]}, "alphaMode": "MASK",
      "extensions": {"KHR_materials_pbrSpecularGlossiness": {"diffuseFactor": [0.5, 0.25, 1, 0.75],
      "diffuseTexture": {"index": 0}, "glossinessFactor": 1, "specularFactor": [0, 0, 0]}})");
  EXPECT_EQ(glm::vec3(scene.instances[0].albedo_spec), glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(scene.instances[0].alpha_mask, glm::vec2(0.75f, 0.5f));
  EXPECT_EQ(scene.meshes[0].base_colour_texture, std::optional<std::uint32_t>(0));
  EXPECT_FLOAT_EQ(scene.instances[0].material.x, 128.0f) << "glossiness 1: the sharpest highlight";
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.textures[0].rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 255, 255, 255, 0}));
}

TEST(GltfMaterial, AMirroredInstanceGetsItsTrianglesWoundTheOtherWay) {
  GltfBuilder file;
  const int material = file.add_material(R"("name": "m")");
  file.add_quad({-1, -1}, {1, 1}, 0, material);
  file.add_quad({-1, -1}, {1, 1}, 0, material, false,
                glm::mat4(glm::vec4(-1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, 0, 1)));
  const Scene scene = load(file);
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(scene.meshes[1].indices, (std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2}));
}

TEST(GltfMaterial, BadValuesAreNamed) {
  EXPECT_EQ(error_of(R"("alphaMode": "CUTOUT")"),
            "m.gltf: materials[0].alphaMode: \"CUTOUT\" is not OPAQUE, MASK or BLEND");
  EXPECT_EQ(error_of(R"("alphaMode": "MASK", "alphaCutoff": -1)"),
            "m.gltf: materials[0].alphaCutoff: -1 is not a finite number of at least 0");
  EXPECT_EQ(error_of(R"("pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions":
      {"KHR_texture_transform": {"scale": [1]}}}})"),
            "m.gltf: materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.scale: "
            "expected 2 numbers");
  EXPECT_EQ(error_of(R"("extensions": {"KHR_materials_pbrSpecularGlossiness": {"diffuseTexture": {"index": 7}}})"),
            "m.gltf: materials[0].extensions.KHR_materials_pbrSpecularGlossiness.diffuseTexture.index: texture 7 "
            "does not exist (the file has 1)");
}

}  // namespace
}  // namespace tilelight
