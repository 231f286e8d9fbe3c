#pragma once
// Local lights (the Tabula Rasa chapter, GPU Gems 3 ch. 19): point, spot and box lights that
// light what lies inside their volume, drawn after the global (sun) pass and added into the
// same light target. This is their description on the CPU, independent of Vulkan.
//
// Units are the renderer's: world coordinates in metres (a loaded scene's lights are moved and
// scaled with its meshes, Scene::world_from_file), and colours in the sun's scale: a surface
// facing a light at distance d receives `color * intensity * attenuation(d)` where a surface
// facing the sun receives `SunAndAtmosphere::sun_color`. Where these numbers come from (glTF's
// candela, an exposure) is the loader's business, documented in docs/scene-input.md.
//
// Every light reaches exactly zero at the edge of its volume (range, outer cone, box faces), so
// drawing its volume shades the same pixels as a full-screen pass does, per pixel.

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>

namespace tilelight {

enum class LocalLightType : std::uint8_t { point, spot, box };

// Optional parts of a light, each one a dimension of the local-light shader domain.
struct LocalLightExtras {
  // Bidirectional lighting (§19.4.1): surfaces facing away from the light receive this colour
  // (times the light's intensity and attenuation) instead of nothing. Box lights only here;
  // the sun's own back colour is SunAndAtmosphere's business.
  std::optional<glm::vec3> back_color;
  // Globe map (§19.4.2): index into Scene::textures, projected along the light's direction
  // (spot, box) or as a cube around it (point) and multiplied into its colour.
  std::optional<std::uint32_t> globe_texture;
};

struct LocalLight {
  LocalLightType type = LocalLightType::point;
  // Point, spot: the light's origin. Box: the centre of the box.
  glm::vec3 position{0.0f};
  // Spot: the cone's axis. Box: the direction its light travels. Normalised. Unused by points.
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  glm::vec3 color{1.0f};   // linear RGB
  float intensity = 1.0f;  // >= 0, in the sun's scale (see above)
  // Point, spot: the distance where the light has faded to zero; > 0 and finite (a glTF light
  // without a range is bounded by the loader).
  float range = 10.0f;
  // Spot: cosines of the inner (full light) and outer (no light) cone angles; 1 >= inner > outer.
  float inner_cone_cos = 1.0f;
  float outer_cone_cos = 0.0f;
  // Box: half sizes along the box's axes, and the distance inside each face over which the light
  // fades to zero; > 0. The box's z axis is `direction`; its x axis is perpendicular to it and
  // to world +y (world +x when `direction` is vertical); y completes a right-handed frame.
  glm::vec3 box_half_extent{1.0f};
  float box_falloff = 0.5f;
  // Whether the light casts shadows (a shadow map of its own).
  bool casts_shadows = true;
  LocalLightExtras extras;
};

// How many lights of each type a scene has (report.json's "local_lights").
struct LocalLightCounts {
  std::uint32_t point = 0;
  std::uint32_t spot = 0;
  std::uint32_t box = 0;
};

}  // namespace tilelight
