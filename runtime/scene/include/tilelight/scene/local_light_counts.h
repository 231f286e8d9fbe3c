#pragma once
// How many lights of each type a scene has: report.json's "local_lights".

#include "tilelight/scene/local_light.h"

#include <vector>

namespace tilelight {

LocalLightCounts count_local_lights(const std::vector<LocalLight>& lights);

}  // namespace tilelight
