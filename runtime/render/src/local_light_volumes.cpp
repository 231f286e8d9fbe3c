#include "local_light_volumes.h"

#include <cmath>
#include <numbers>

namespace tilelight {
namespace {

constexpr std::uint32_t kSegments = 16;  // around the sphere and the cone
constexpr std::uint32_t kRings = 8;      // from pole to pole

// Appends triangle (a, b, c) wound counter-clockwise seen from outside a convex mesh whose
// inside holds `centre`.
void add_outward(VolumeMeshes& m, glm::vec3 centre, std::uint32_t base, std::uint32_t a, std::uint32_t b,
                 std::uint32_t c) {
  const glm::vec3 pa = m.vertices[base + a], pb = m.vertices[base + b], pc = m.vertices[base + c];
  const bool outward = glm::dot(glm::cross(pb - pa, pc - pa), (pa + pb + pc) / 3.0f - centre) > 0.0f;
  m.indices.insert(m.indices.end(), {base + a, outward ? base + b : base + c, outward ? base + c : base + b});
}

// A UV sphere whose every face lies outside the unit sphere: vertices on a sphere of radius
// 1 / (cos(half a ring step) * cos(half a segment step)), plus the margin.
void add_sphere(VolumeMeshes& m) {
  const float ring_step = std::numbers::pi_v<float> / kRings;
  const float segment_step = 2.0f * std::numbers::pi_v<float> / kSegments;
  const float radius = (1.0f + kVolumeMargin) / (std::cos(ring_step / 2.0f) * std::cos(segment_step / 2.0f));
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (std::uint32_t r = 0; r <= kRings; ++r) {
    for (std::uint32_t s = 0; s < kSegments; ++s) {
      const float polar = ring_step * static_cast<float>(r), azimuth = segment_step * static_cast<float>(s);
      m.vertices.push_back(radius * glm::vec3(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                                              std::sin(polar) * std::sin(azimuth)));
    }
  }
  for (std::uint32_t r = 0; r < kRings; ++r) {
    for (std::uint32_t s = 0; s < kSegments; ++s) {
      const std::uint32_t a = r * kSegments + s, b = r * kSegments + (s + 1) % kSegments;
      const std::uint32_t c = a + kSegments, d = b + kSegments;
      if (r > 0) add_outward(m, glm::vec3(0.0f), base, a, b, c);
      if (r + 1 < kRings) add_outward(m, glm::vec3(0.0f), base, b, d, c);
    }
  }
}

// Apex behind the origin, base polygon around the unit circle at z = 1 (both with the margin).
void add_cone(VolumeMeshes& m) {
  const float segment_step = 2.0f * std::numbers::pi_v<float> / kSegments;
  const float radius = (1.0f + kVolumeMargin) / std::cos(segment_step / 2.0f);
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.push_back({0.0f, 0.0f, -kVolumeMargin});        // 0: apex
  m.vertices.push_back({0.0f, 0.0f, 1.0f + kVolumeMargin});  // 1: base centre
  for (std::uint32_t s = 0; s < kSegments; ++s) {
    const float azimuth = segment_step * static_cast<float>(s);
    m.vertices.push_back({radius * std::cos(azimuth), radius * std::sin(azimuth), 1.0f + kVolumeMargin});
  }
  const glm::vec3 centre{0.0f, 0.0f, 0.6f};
  for (std::uint32_t s = 0; s < kSegments; ++s) {
    const std::uint32_t a = 2 + s, b = 2 + (s + 1) % kSegments;
    add_outward(m, centre, base, 0, a, b);
    add_outward(m, centre, base, 1, a, b);
  }
}

void add_box(VolumeMeshes& m) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  const float e = 1.0f + kVolumeMargin;
  for (std::uint32_t i = 0; i < 8; ++i) {
    m.vertices.push_back({(i & 1u) ? e : -e, (i & 2u) ? e : -e, (i & 4u) ? e : -e});
  }
  // Two triangles per face: the corners whose coordinate on `axis` is `side`.
  for (std::uint32_t axis = 0; axis < 3; ++axis) {
    for (std::uint32_t side = 0; side < 2; ++side) {
      std::uint32_t corners[4];
      std::uint32_t n = 0;
      for (std::uint32_t i = 0; i < 8; ++i) {
        if (((i >> axis) & 1u) == side) corners[n++] = i;
      }
      // corners[0..3] differ in the other two axes' bits: 0 and 3 are opposite.
      add_outward(m, glm::vec3(0.0f), base, corners[0], corners[1], corners[3]);
      add_outward(m, glm::vec3(0.0f), base, corners[0], corners[3], corners[2]);
    }
  }
}

}  // namespace

LightVolume volume_of(const LocalLight& light) {
  switch (light.type) {
    case LocalLightType::box: return LightVolume::box;
    case LocalLightType::spot: return light.outer_cone_cos >= kWidestConeCos ? LightVolume::cone : LightVolume::sphere;
    case LocalLightType::point: break;
  }
  return LightVolume::sphere;
}

bool may_cross_far_plane(const LocalLight& light, const glm::mat4& view_proj) {
  const float reach = 1.1f * (light.type == LocalLightType::box ? glm::length(light.box_half_extent) : light.range);
  for (std::uint32_t i = 0; i < 8; ++i) {
    const glm::vec3 corner =
        light.position + reach * glm::vec3((i & 1u) ? 1.0f : -1.0f, (i & 2u) ? 1.0f : -1.0f, (i & 4u) ? 1.0f : -1.0f);
    const glm::vec4 clip = view_proj * glm::vec4(corner, 1.0f);
    if (clip.z > clip.w) return true;
  }
  return false;
}

VolumeMeshes make_volume_meshes() {
  VolumeMeshes m;
  auto add = [&m](LightVolume volume, void (*build)(VolumeMeshes&)) {
    const auto first = static_cast<std::uint32_t>(m.indices.size());
    build(m);
    m.meshes[static_cast<std::uint32_t>(volume)] = {first, static_cast<std::uint32_t>(m.indices.size()) - first};
  };
  add(LightVolume::sphere, add_sphere);
  add(LightVolume::cone, add_cone);
  add(LightVolume::box, add_box);
  return m;
}

}  // namespace tilelight
