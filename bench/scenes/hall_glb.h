#pragma once
// A HallScene as a binary glTF 2.0 file (.glb): one node and one mesh per HallMesh, metallic-
// roughness materials of a base colour factor each (single-sided), positions, normals and
// 32-bit indices in one buffer. No textures, cameras or lights: the renderer places the camera.

#include "scenes/hall_scene.h"

#include <cstdint>
#include <vector>

namespace tilelight::bench {

std::vector<std::uint8_t> encode_hall_glb(const HallScene& hall);

}  // namespace tilelight::bench
