// KHR_lights_punctual (docs/scene-input.md, "Local lights"): lights.gltf (make_fixtures.py) has
// one of each kind the loader reads. Each light is placed by its node through its parents and
// the scene's framing, in the sun's units (1 lux per unit), with candela kept inverse-square in
// the file's metres; a missing range is bounded against the sun; the first directional light is
// the sun. Every broken light is an error naming the file and the element, exactly.
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace tilelight {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace gltf_lights_test {
namespace {

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;
const std::string kLights = "extensions.KHR_lights_punctual.lights";

void expect_near(const glm::vec3& actual, const glm::vec3& expected, float tolerance, const char* what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << what << "[" << i << "]";
}

class GltfLights : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { loaded_ = new GltfScene(load_gltf(kFixtures / "lights.gltf")); }
  static void TearDownTestSuite() { delete loaded_; }

  const Scene& scene() const { return loaded_->scene; }
  // The file's point at its coordinates, in the renderer's world.
  glm::vec3 world(const glm::vec3& file) const { return glm::vec3(scene().world_from_file * glm::vec4(file, 1.0f)); }
  float scale() const { return glm::length(glm::vec3(scene().world_from_file[0])); }

  static GltfScene* loaded_;
};

GltfScene* GltfLights::loaded_ = nullptr;

TEST_F(GltfLights, PointSpotAndBoxLightsAreLoadedInTheFilesNodeOrder) {
  ASSERT_EQ(scene().local_lights.size(), 4u) << "two directional lights are not local lights";
  EXPECT_EQ(scene().local_lights[0].type, LocalLightType::point) << "nodes[6], the first root's child, comes first";
  EXPECT_EQ(scene().local_lights[1].type, LocalLightType::point);
  EXPECT_EQ(scene().local_lights[2].type, LocalLightType::spot);
  EXPECT_EQ(scene().local_lights[3].type, LocalLightType::box);
}

TEST_F(GltfLights, APointLightKeepsItsColourAndRangeScaledWithTheScene) {
  const LocalLight& light = scene().local_lights[1];
  expect_near(light.position, world({0, 3, 0}), 1e-4f, "position");
  expect_near(light.color, {1.0f, 0.5f, 0.25f}, 0.0f, "color");
  EXPECT_FLOAT_EQ(light.range, 5.0f * scale());
  EXPECT_TRUE(light.casts_shadows);
  EXPECT_FALSE(light.extras.back_color);
  EXPECT_FALSE(light.extras.globe_texture);
}

TEST_F(GltfLights, CandelaStayInverseSquareInTheFilesMetres) {
  // 40 cd at 1 m of the file: what a surface receives at d file metres, 40 / d^2 lux, is what the
  // renderer computes at d * scale of its metres (1 lux per unit of the sun's scale).
  const LocalLight& light = scene().local_lights[1];
  const float d_file = 2.0f;
  const float d_world = d_file * scale();
  EXPECT_NEAR(light.intensity / (d_world * d_world), 40.0f / (d_file * d_file), 1e-3f);
}

TEST_F(GltfLights, AChildNodesLightFollowsItsParentsTransform) {
  // nodes[6] at (0, 0, 1) under nodes[0]: scale (1, 1, 2), 90 degrees about y, then (0, 0.5, 0).
  const LocalLight& light = scene().local_lights[0];
  expect_near(light.position, world({2.0f, 0.5f, 0.0f}), 1e-4f, "position");
  // The node's scale does not scale the light (glTF: a light's properties ignore it).
  EXPECT_FLOAT_EQ(light.intensity, 1.0f * scale() * scale());
}

TEST_F(GltfLights, ASpotLightPointsDownItsNodesMinusZWithTheFilesCones) {
  const LocalLight& light = scene().local_lights[2];
  expect_near(light.position, world({2, 4, 0}), 1e-4f, "position");
  expect_near(light.direction, {0.0f, -1.0f, 0.0f}, 1e-5f, "direction");
  EXPECT_FLOAT_EQ(light.inner_cone_cos, std::cos(0.2f));
  EXPECT_FLOAT_EQ(light.outer_cone_cos, std::cos(0.6f));
  EXPECT_FLOAT_EQ(light.intensity, 100.0f * scale() * scale());
}

TEST_F(GltfLights, AnUndefinedRangeEndsAt1Over256OfTheSun) {
  // White, 100 cd: its illuminance max(colour) * intensity / d^2 is 1/256 of the sun's brightest
  // channel (the file's sun: 2 lux times [1, 0.9, 0.8]) at the bound.
  const LocalLight& light = scene().local_lights[2];
  const float sun = 2.0f;
  EXPECT_NEAR(light.intensity / (light.range * light.range), sun / 256.0f, 1e-5f);
  EXPECT_NEAR(light.range, std::sqrt(100.0f * 256.0f / sun) * scale(), 1e-2f);
}

TEST_F(GltfLights, ABoxLightIsADirectionalLightWithTilelightBoxInItsExtras) {
  const LocalLight& light = scene().local_lights[3];
  expect_near(light.position, world({1, 1, -1}), 1e-4f, "position");
  // 90 degrees about y turns -z to -x.
  expect_near(light.direction, {-1.0f, 0.0f, 0.0f}, 1e-5f, "direction");
  expect_near(light.box_half_extent, glm::vec3(1, 2, 3) * scale(), 1e-4f, "half extent");
  EXPECT_FLOAT_EQ(light.box_falloff, 0.5f * scale());
  EXPECT_FLOAT_EQ(light.intensity, 3.0f) << "lux, 1 per unit of the sun's scale, at any distance";
  ASSERT_TRUE(light.extras.back_color);
  expect_near(*light.extras.back_color, {0.1f, 0.2f, 0.3f}, 1e-6f, "back colour");
  EXPECT_FALSE(light.casts_shadows);
}

TEST_F(GltfLights, AGlobeMapIsTheTextureItsExtrasName) {
  const LocalLight& light = scene().local_lights[3];
  ASSERT_TRUE(light.extras.globe_texture);
  ASSERT_LT(*light.extras.globe_texture, scene().textures.size());
  const Texture& globe = scene().textures[*light.extras.globe_texture];
  EXPECT_EQ(globe.width, 2u);
  EXPECT_EQ(globe.rgba[0], 255) << "the fixture's top-left texel is red";
}

TEST_F(GltfLights, TheFirstDirectionalLightIsTheSunAndTheSecondIsWarnedAbout) {
  expect_near(scene().sun.sun_direction, {0.0f, 1.0f, 0.0f}, 1e-5f, "towards the sun: against its light");
  expect_near(scene().sun.sun_color, {2.0f, 1.8f, 1.6f}, 1e-5f, "colour times lux");
  const std::string file = "warning: " + (kFixtures / "lights.gltf").string() + ": ";
  EXPECT_EQ(loaded_->warnings,
            (std::vector<std::string>{
                file + "1 more directional light ignored: the first one is the sun, and there is one sun"}));
}

TEST(GltfLightsAbsent, AFileWithoutLightsKeepsTheDemoSunAndHasNoLocalLights) {
  const Scene scene = load_gltf_scene(kFixtures / "box.gltf");
  EXPECT_TRUE(scene.local_lights.empty());
  EXPECT_EQ(scene.sun.sun_color, make_demo_sun().sun_color);
}

// lights.gltf changed by `edit`, loaded from memory as "edited.gltf".
GltfScene load_edited(const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(kFixtures / "lights.gltf"));
  edit(gltf);
  const std::string text = gltf.dump();
  return load_gltf_from_memory(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()),
                               "edited.gltf", {});
}

nlohmann::json& light_of_file(nlohmann::json& gltf, int index) {
  return gltf["extensions"]["KHR_lights_punctual"]["lights"][index];
}

TEST(GltfLightsEdited, ALightTwoNodesReferenceIsPlacedTwiceAndOneNoNodeReferencesIsNot) {
  const GltfScene twice =
      load_edited([](nlohmann::json& g) { g["nodes"][7]["extensions"]["KHR_lights_punctual"]["light"] = 0; });
  EXPECT_EQ(twice.scene.local_lights.size(), 5u) << "nodes[7] places light 0 a second time";
  const GltfScene unplaced = load_edited([](nlohmann::json& g) { g["nodes"][3].erase("extensions"); });
  EXPECT_EQ(unplaced.scene.local_lights.size(), 3u) << "the spot light is placed by no node";
}

TEST(GltfLightsEdited, APointLightOnANodeThatFlattensItsZAxisStillLoads) {
  const GltfScene flat = load_edited([](nlohmann::json& g) { g["nodes"][2]["scale"] = {1, 1, 0}; });
  EXPECT_EQ(flat.scene.local_lights.size(), 4u);
}

TEST(GltfLightsEdited, AFileWhoseOnlyLightIsTheSunHasNoLocalLightsAndNoWarning) {
  const GltfScene sun_only = load_edited([](nlohmann::json& g) {
    for (auto& node : g["nodes"]) {
      if (node.contains("extensions") && node["extensions"]["KHR_lights_punctual"]["light"] != 2)
        node.erase("extensions");
    }
  });
  EXPECT_TRUE(sun_only.scene.local_lights.empty());
  EXPECT_EQ(sun_only.warnings, std::vector<std::string>{});
  EXPECT_NEAR(sun_only.scene.sun.sun_color.x, 2.0f, 1e-6f);
}

TEST(GltfLightsEdited, AnIntensityNoFloatHoldsIsNamed) {
  try {
    (void)load_edited([](nlohmann::json& g) { light_of_file(g, 0)["intensity"] = 1e39; });
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "edited.gltf: " + kLights + "[0].intensity: 1e+39 is too large for a 32-bit float");
  }
}

struct BadLight {
  const char* file;
  std::string says;  // the whole message after "PATH: "
};

void PrintTo(const BadLight& b, std::ostream* os) { *os << b.file; }

class GltfBadLight : public ::testing::TestWithParam<BadLight> {};

TEST_P(GltfBadLight, IsAnErrorNamingTheFileAndTheElement) {
  const std::filesystem::path path = kFixtures / GetParam().file;
  try {
    (void)load_gltf(path);
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": " + GetParam().says);
  }
}

std::string name_of(const ::testing::TestParamInfo<BadLight>& info) {
  std::string name = info.param.file;
  return name.substr(0, name.find('.'));
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, GltfBadLight,
    ::testing::Values(
        BadLight{"bad_light_type.gltf",
                 kLights + "[0].type: \"area\" is not a punctual light type (\"point\", \"spot\" or \"directional\")"},
        BadLight{"bad_light_color.gltf", kLights + "[0].color: expected an array of 3 numbers, got [1,1]"},
        BadLight{"bad_light_intensity.gltf", kLights + "[0].intensity: expected a number, got \"bright\""},
        BadLight{"bad_light_range.gltf", kLights + "[0].range: -1 is not a positive distance"},
        BadLight{"bad_light_outer_cone.gltf",
                 kLights + "[1].spot.outerConeAngle: 2 is not an angle above 0 and at most pi/2 radians"},
        BadLight{"bad_light_inner_cone.gltf",
                 kLights + "[1].spot.innerConeAngle: 0.7 is not below outerConeAngle (0.6)"},
        BadLight{"bad_light_node_reference.gltf",
                 "nodes[2].extensions.KHR_lights_punctual.light: light 9 does not exist (the file has 6)"},
        BadLight{
            "bad_light_box_on_point.gltf",
            kLights + "[0].extras.tilelight_box: only a directional light can be a box light (this is a point light)"},
        BadLight{"bad_light_box_falloff.gltf",
                 kLights + "[3].extras.tilelight_box.falloff: 5 is more than the smallest half extent (1)"},
        BadLight{
            "bad_light_back_color_on_spot.gltf",
            kLights + "[1].extras.tilelight_back_color: only box lights have a back colour (this is a spot light)"},
        BadLight{"bad_light_globe_missing.gltf",
                 kLights + "[3].extras.tilelight_globe.index: texture 7 does not exist (the file has 1)"},
        BadLight{"bad_light_extras_typo.gltf",
                 kLights +
                     "[3].extras.tilelight_bax: not a tilelight light property (tilelight_box, tilelight_back_color, "
                     "tilelight_globe, tilelight_casts_shadows)"}),
    name_of);

}  // namespace
}  // namespace gltf_lights_test
}  // namespace tilelight
