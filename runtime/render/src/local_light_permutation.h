#pragma once
// Which permutation of permutations/local_lights.json draws a light: its type, its globe map,
// its back colour (box lights only: the domain prunes it elsewhere, and local_light.h gives it to
// box lights alone, so a back colour on another type is ignored), and MSAA_EDGE on a
// multisampled G-buffer (the shader then shades every sample where a pixel's samples may
// differ, as the global pass does), and SHADOWED where the light got a shadow map
// (local_light_shadows.h: not every light that casts shadows gets one).

#include "tilelight/scene/local_light.h"

#include <cstdint>

namespace tilelight {

// The raw ID, valid in both builds of the domain (local_lights and local_lights_1x).
std::uint32_t local_light_raw_id(const LocalLight& light, bool multisampled_gbuffer, bool shadowed = false);

}  // namespace tilelight
