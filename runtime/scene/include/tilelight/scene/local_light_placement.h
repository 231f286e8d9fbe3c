#pragma once
// Local lights for the procedural scene (tilelight --lights N): street lamps, the same N lights on
// every run. They stand in the gaps between the columns of boxes and pillars (make_demo_scene()),
// first down the street the "street" camera looks along (x = 3.5 m), then in the gaps either side
// of it, alternately left and right, 13 lamps to a gap, 6 m apart from z = -12 m to z = -84 m, so
// both the "default" and the "street" cameras see the first ones. The types cycle point, spot, box;
// every light casts shadows, every other box light has a back colour, and one light in four
// projects the procedural globe map (make_demo_globe_texture()).
//
// Brightness: a lamp's pool of light on the ground is about as bright as the sun's light on it
// (make_demo_sun()'s colour, about 1.5, times the sun's elevation), assuming the inverse-square
// falloff of local_light.h's units; ranges of 6 to 8 m reach the ground and overlap a neighbour's
// a little.

#include "tilelight/scene/local_light.h"
#include "tilelight/scene/scene.h"

#include <cstdint>
#include <vector>

namespace tilelight {

// The most lights make_demo_lights() places (79 gaps of 13 lamps, all on the demo's ground).
inline constexpr std::uint32_t kMaxDemoLights = 1024;

// The lamps, the first `count` of the sequence above (count <= kMaxDemoLights); the lights with a
// globe map use Scene::textures[globe_texture].
std::vector<LocalLight> make_demo_lights(std::uint32_t count, std::uint32_t globe_texture);

// The globe map: a 32 x 32 stained-glass pattern, coloured panes between dark leading, read with
// clamped edges, so a projected pattern is plain to see where the light falls.
Texture make_demo_globe_texture();

// Appends the globe texture (when count > 0) and make_demo_lights(count) to `scene` (the demo
// scene). Precondition: count <= kMaxDemoLights.
void add_demo_lights(Scene& scene, std::uint32_t count);

}  // namespace tilelight
