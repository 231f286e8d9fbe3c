#include "tilelight/scene/local_light_placement.h"

#include <array>
#include <cassert>
#include <cmath>

namespace tilelight {
namespace {

// The gaps between make_demo_scene()'s columns of boxes (7 m apart, at x = 7 * column) and its
// rows (from z = -8 m, 7 m apart, to z = -85 m).
constexpr float kStreetX = 3.5f;  // the "street" camera's gap
constexpr float kGapSpacing = 7.0f;
constexpr std::uint32_t kLampsPerGap = 13;
constexpr float kFirstLampZ = -12.0f;  // beyond the street camera (z = -9 m)
constexpr float kLampSpacing = 6.0f;

// Warm sodium, cool white, amber, pale green: neighbours differ, so overlaps are easy to see.
constexpr std::array<glm::vec3, 4> kColours{glm::vec3(1.0f, 0.72f, 0.42f), glm::vec3(0.80f, 0.88f, 1.0f),
                                            glm::vec3(1.0f, 0.55f, 0.25f), glm::vec3(0.70f, 1.0f, 0.75f)};

// Gap 0 is the street; then 1 left, 1 right, 2 left... (-1, 1, -2, 2, ...).
float gap_x(std::uint32_t gap) {
  const std::uint32_t steps = (gap + 1) / 2;  // whole gaps from the street
  const float offset = kGapSpacing * static_cast<float>(steps);
  return kStreetX + (gap % 2 == 1 ? -offset : offset);
}

// The lamp's foot on the ground.
glm::vec3 lamp_base(std::uint32_t index) {
  const std::uint32_t gap = index / kLampsPerGap;
  const std::uint32_t along = index % kLampsPerGap;
  return {gap_x(gap), 0.0f, kFirstLampZ - kLampSpacing * static_cast<float>(along)};
}

// A point lamp 4 m up: its 6 m range meets the ground in a pool 4.5 m across either way.
LocalLight point_lamp(glm::vec3 base) {
  LocalLight light;
  light.type = LocalLightType::point;
  light.position = base + glm::vec3(0.0f, 4.0f, 0.0f);
  light.intensity = 24.0f;  // 1.5 at the ground below, before the fade to the range
  light.range = 6.0f;
  return light;
}

// A spot 5 m up, pointing down: a cone of 40 degrees (full light inside 25), 4.2 m across the ground.
LocalLight spot_lamp(glm::vec3 base) {
  LocalLight light;
  light.type = LocalLightType::spot;
  light.position = base + glm::vec3(0.0f, 5.0f, 0.0f);
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.intensity = 40.0f;  // 1.6 at the ground below
  light.range = 8.0f;
  light.inner_cone_cos = std::cos(glm::radians(25.0f));
  light.outer_cone_cos = std::cos(glm::radians(40.0f));
  return light;
}

// A box of light shining down from 4.5 m to below the ground, 4 m by 5 m across.
LocalLight box_lamp(glm::vec3 base) {
  LocalLight light;
  light.type = LocalLightType::box;
  light.position = base + glm::vec3(0.0f, 2.0f, 0.0f);
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.intensity = 0.8f;  // no distance falloff: about the sun's light on the ground
  light.box_half_extent = glm::vec3(2.0f, 2.5f, 2.5f);
  light.box_falloff = 0.5f;
  return light;
}

}  // namespace

std::vector<LocalLight> make_demo_lights(std::uint32_t count, std::uint32_t globe_texture) {
  assert(count <= kMaxDemoLights);
  std::vector<LocalLight> lights;
  lights.reserve(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const glm::vec3 base = lamp_base(i);
    const std::uint32_t kind = i % 3;
    LocalLight light = kind == 0 ? point_lamp(base) : kind == 1 ? spot_lamp(base) : box_lamp(base);
    light.color = kColours[i % kColours.size()];
    light.casts_shadows = true;
    // Every other box light lights the faces turned away from it too, dimly and bluish.
    if (kind == 2 && (i / 3) % 2 == 0) light.extras.back_color = glm::vec3(0.10f, 0.12f, 0.20f);
    // One in four projects the globe: period 4 against the types' 3, so every type gets one.
    if (i % 4 == 1) light.extras.globe_texture = globe_texture;
    lights.push_back(light);
  }
  return lights;
}

Texture make_demo_globe_texture() {
  constexpr std::uint32_t kSize = 32;
  constexpr std::uint32_t kPane = 8;  // 4 x 4 panes
  constexpr std::array<std::array<std::uint8_t, 3>, 4> kGlass{
      {{230, 60, 50}, {60, 110, 230}, {240, 200, 60}, {70, 190, 90}}};
  Texture texture;
  texture.name = "demo globe";
  texture.width = kSize;
  texture.height = kSize;
  texture.rgba.resize(std::size_t{kSize} * kSize * 4);
  for (std::uint32_t y = 0; y < kSize; ++y) {
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const bool leading = x % kPane == 0 || y % kPane == 0;
      const auto& glass = kGlass[(x / kPane + 3 * (y / kPane)) % kGlass.size()];
      std::uint8_t* texel = &texture.rgba[(std::size_t{y} * kSize + x) * 4];
      for (int c = 0; c < 3; ++c) texel[c] = leading ? 20 : glass[static_cast<std::size_t>(c)];
      texel[3] = 255;
    }
  }
  texture.sampling.wrap_u = TextureWrap::clamp_to_edge;
  texture.sampling.wrap_v = TextureWrap::clamp_to_edge;
  return texture;
}

void add_demo_lights(Scene& scene, std::uint32_t count) {
  if (count == 0) return;
  const auto globe = static_cast<std::uint32_t>(scene.textures.size());
  scene.textures.push_back(make_demo_globe_texture());
  const std::vector<LocalLight> lights = make_demo_lights(count, globe);
  scene.local_lights.insert(scene.local_lights.end(), lights.begin(), lights.end());
}

}  // namespace tilelight
