#include "tilelight/scene/local_light_counts.h"

namespace tilelight {

LocalLightCounts count_local_lights(const std::vector<LocalLight>& lights) {
  LocalLightCounts counts;
  for (const LocalLight& light : lights) {
    switch (light.type) {
      case LocalLightType::point: ++counts.point; break;
      case LocalLightType::spot: ++counts.spot; break;
      case LocalLightType::box: ++counts.box; break;
    }
  }
  return counts;
}

}  // namespace tilelight
