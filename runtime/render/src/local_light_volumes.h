#pragma once
// The unit meshes of the light volumes (§19.7.1) and which one each light is drawn with. Each
// mesh ENCLOSES its shape with a margin (kVolumeMargin), so that every point where a light's
// attenuation is not zero lies inside the placed mesh even after the rasteriser's rounding:
// the volume pass then shades every pixel the full-screen pass lights. local_light_volume.vert
// places them (local_light.glsl, local_light_volume_position()). Triangles wind counter-clockwise
// seen from outside, the scene's front faces: the volume pass culls them.

#include "tilelight/scene/local_light.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tilelight {

// LOCAL_LIGHT_VOLUME_* of local_light.glsl.
enum class LightVolume : std::uint32_t { sphere = 0, cone = 1, box = 2 };

// How far each unit mesh reaches beyond its shape, relatively (and the cone's apex behind the
// light): covers the polygonal approximation's rounding, the depth's, and RT3's sun bit.
inline constexpr float kVolumeMargin = 0.02f;
// The widest spot cone a cone mesh draws; wider ones (tan grows without bound) get the sphere.
inline constexpr float kWidestConeCos = 0.17364818f;  // cos(80 degrees)

LightVolume volume_of(const LocalLight& light);

struct VolumeMesh {
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
};

// The three unit meshes in one vertex and one index buffer (indices relative to the buffer's
// first vertex), in LightVolume order.
struct VolumeMeshes {
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;
  VolumeMesh meshes[3];
};

VolumeMeshes make_volume_meshes();

// Whether any point of the light's volume may lie beyond the far plane of `view_proj` (world ->
// Vulkan clip space): some corner of a box around the volume, with room for the mesh's margin,
// has clip z > w. Conservative; the volume pass draws such a light without the depth test where
// the device cannot clamp depth.
bool may_cross_far_plane(const LocalLight& light, const glm::mat4& view_proj);

}  // namespace tilelight
