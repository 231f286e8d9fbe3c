#include "local_light_permutation.h"

#include "tilelight/vulkan/error.h"

#include <local_lights_shaders.h>

#include <optional>

namespace tilelight {
namespace {

local_lights::LIGHT_TYPE_value light_type_value(LocalLightType type) {
  switch (type) {
    case LocalLightType::point: return local_lights::LIGHT_TYPE_value::POINT;
    case LocalLightType::spot: return local_lights::LIGHT_TYPE_value::SPOT;
    case LocalLightType::box: return local_lights::LIGHT_TYPE_value::BOX;
  }
  throw Error("a local light of unknown type " + std::to_string(static_cast<int>(type)));
}

}  // namespace

std::uint32_t local_light_raw_id(const LocalLight& light, bool multisampled_gbuffer, bool shadowed) {
  local_lights::Features features;
  features.LIGHT_TYPE = light_type_value(light.type);
  features.GLOBE = light.extras.globe_texture.has_value();
  features.BACK_COLOUR = light.type == LocalLightType::box && light.extras.back_color.has_value();
  features.MSAA_EDGE = multisampled_gbuffer;
  features.SHADOWED = shadowed;
  const std::optional<local_lights::RawId> id = local_lights::raw_id(features);
  if (!id) throw Error("local_lights.json has no permutation for a local light of these features (pruned)");
  return id->value();
}

}  // namespace tilelight
