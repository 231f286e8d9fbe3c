#include "local_shadow_transforms.h"

#include "local_light_block.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace tilelight {
namespace {

// The receiver's normal offset, in texels of the face: with the caster's rasteriser bias, what
// keeps a lit surface from shadowing itself (acne).
constexpr float kNormalOffsetTexels = 1.5f;

// The tangent of a face's half angle that puts `base_tan` kFaceBorderTexels inside its edge.
float bordered(float base, std::uint32_t face_size) {
  return base * static_cast<float>(face_size) / static_cast<float>(face_size - 2 * kFaceBorderTexels);
}

float spot_half_angle(const LocalLight& light) { return std::acos(std::clamp(light.outer_cone_cos, -1.0f, 1.0f)); }

bool spot_needs_cube(const LocalLight& light) {
  return spot_half_angle(light) > glm::radians(kMaxSpotFaceHalfAngleDegrees);
}

// Near plane of a perspective face: casters nearer the light than this cast nothing.
float near_plane(float range) { return std::max(0.01f, range * 0.01f); }

LocalShadowFaceBlock perspective_face(glm::vec3 eye, glm::vec3 forward, glm::vec3 up, float tan_half, float range,
                                      std::uint32_t face_size) {
  const glm::mat4 view = glm::lookAtRH(eye, eye + forward, up);
  // The eye may sit up to a cell's diagonal from the light: the far plane reaches past the range.
  const float far = range * 1.02f + 0.1f;
  const glm::mat4 proj = glm::perspectiveRH_ZO(2.0f * std::atan(tan_half), 1.0f, near_plane(range), far);
  const float texel_at_1m = 2.0f * tan_half / static_cast<float>(face_size);
  LocalShadowFaceBlock face{};
  face.view_proj = proj * view;
  face.eye_offset = glm::vec4(eye, kNormalOffsetTexels * texel_at_1m);
  face.rect = glm::uvec4(0u, 0u, face_size, 1u);
  return face;
}

// A perspective face's tangent of its half angle, its border included.
float perspective_tan_half(const LocalLight& light, std::uint32_t face_size) {
  const bool cube = light.type != LocalLightType::spot || spot_needs_cube(light);
  return bordered(cube ? 1.0f : std::tan(spot_half_angle(light)), face_size);
}

// The texel of the box's orthographic face: square, the longer side sets it.
float box_texel(const LocalLight& light, std::uint32_t face_size) {
  const float half = bordered(std::max(light.box_half_extent.x, light.box_half_extent.y), face_size);
  return 2.0f * half / static_cast<float>(face_size);
}

std::vector<LocalShadowFaceBlock> cube_faces(const LocalLight& light, std::uint32_t face_size) {
  const float tan_half = perspective_tan_half(light, face_size);
  const glm::vec3 eye =
      snap_to_grid(light.position, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, shadow_snap_cell(light, face_size));
  // The order local_shadow_cube_face() numbers them in; any up vector not along the axis.
  const std::array<std::pair<glm::vec3, glm::vec3>, 6> axes{{{{1, 0, 0}, {0, 1, 0}},
                                                             {{-1, 0, 0}, {0, 1, 0}},
                                                             {{0, 1, 0}, {0, 0, 1}},
                                                             {{0, -1, 0}, {0, 0, 1}},
                                                             {{0, 0, 1}, {0, 1, 0}},
                                                             {{0, 0, -1}, {0, 1, 0}}}};
  std::vector<LocalShadowFaceBlock> faces;
  faces.reserve(axes.size());
  for (const auto& [forward, up] : axes) {
    faces.push_back(perspective_face(eye, forward, up, tan_half, light.range, face_size));
  }
  return faces;
}

LocalShadowFaceBlock spot_face(const LocalLight& light, std::uint32_t face_size) {
  const glm::vec3 z = light.direction;
  const glm::vec3 x = local_light_frame_x(z);
  const glm::vec3 y = glm::cross(z, x);
  const float tan_half = perspective_tan_half(light, face_size);
  const glm::vec3 eye = snap_to_grid(light.position, x, y, z, shadow_snap_cell(light, face_size));
  return perspective_face(eye, z, y, tan_half, light.range, face_size);
}

// Orthographic along the box's z (its light's travel), across its x and y; the centre snapped
// to the texel grid of the face (Listing 19-2's idea).
LocalShadowFaceBlock box_face(const LocalLight& light, std::uint32_t face_size) {
  const glm::vec3 z = light.direction;
  const glm::vec3 x = local_light_frame_x(z);
  const glm::vec3 y = glm::cross(z, x);
  const glm::vec3 h = light.box_half_extent;
  const float texel = box_texel(light, face_size);
  const glm::vec3 eye = snap_to_grid(light.position, x, y, z, texel);
  const glm::mat4 view = glm::lookAtRH(eye, eye + z, y);
  const float depth = h.z * 1.02f + texel;
  // The face is square in texels: the longer side sets the texel, the shorter is covered too.
  const float half = texel * static_cast<float>(face_size) * 0.5f;
  const glm::mat4 proj = glm::orthoRH_ZO(-half, half, -half, half, -depth, depth);
  LocalShadowFaceBlock face{};
  face.view_proj = proj * view;
  face.eye_offset = glm::vec4(eye, kNormalOffsetTexels * texel);
  face.rect = glm::uvec4(0u, 0u, face_size, 0u);
  return face;
}

}  // namespace

std::uint32_t shadow_face_count(const LocalLight& light) {
  switch (light.type) {
    case LocalLightType::point: return 6;
    case LocalLightType::spot: return spot_needs_cube(light) ? 6 : 1;
    case LocalLightType::box: return 1;
  }
  return 0;
}

float shadow_snap_cell(const LocalLight& light, std::uint32_t face_size) {
  if (light.type == LocalLightType::box) return box_texel(light, face_size);
  return 2.0f * perspective_tan_half(light, face_size) / static_cast<float>(face_size) * near_plane(light.range);
}

glm::vec3 snap_to_grid(glm::vec3 position, glm::vec3 x, glm::vec3 y, glm::vec3 z, float step) {
  const glm::vec3 q{glm::dot(position, x), glm::dot(position, y), glm::dot(position, z)};
  const glm::vec3 snapped = glm::floor(q / step) * step;
  return snapped.x * x + snapped.y * y + snapped.z * z;
}

std::vector<LocalShadowFaceBlock> shadow_faces(const LocalLight& light, std::uint32_t face_size) {
  if (light.type == LocalLightType::box) return {box_face(light, face_size)};
  if (light.type == LocalLightType::spot && !spot_needs_cube(light)) return {spot_face(light, face_size)};
  return cube_faces(light, face_size);
}

LocalShadowPlan plan_local_shadows(const std::vector<LocalLight>& lights, bool enabled, std::uint32_t face_size,
                                   std::uint64_t cap_bytes, std::uint32_t max_atlas_texels) {
  LocalShadowPlan plan;
  plan.face_size = face_size;
  plan.cap_bytes = cap_bytes;
  const std::uint64_t face_bytes = std::uint64_t{face_size} * face_size * kShadowDepthBytes;
  const std::uint64_t per_side = max_atlas_texels / face_size;
  const std::uint64_t max_faces = std::min<std::uint64_t>(cap_bytes / face_bytes, per_side * per_side);
  for (const LocalLight& light : lights) {
    const std::uint32_t count = enabled && light.casts_shadows ? shadow_face_count(light) : 0;
    if (count != 0 && plan.faces + count <= max_faces) {
      plan.first_face.push_back(plan.faces);
      plan.face_count.push_back(count);
      plan.faces += count;
      ++plan.maps;
    } else {
      plan.first_face.push_back(kNoShadow);
      plan.face_count.push_back(0);
      if (count != 0) ++plan.unshadowed;
    }
  }
  if (plan.faces != 0) {
    // As square as the faces allow, no side beyond the device's largest.
    plan.columns = static_cast<std::uint32_t>(std::min<std::uint64_t>(
        per_side, static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(plan.faces))))));
    plan.rows = (plan.faces + plan.columns - 1) / plan.columns;
    plan.bytes = std::uint64_t{plan.columns} * plan.rows * face_bytes;
  }
  return plan;
}

std::vector<LocalShadowFaceBlock> place_shadow_faces(const std::vector<LocalLight>& lights,
                                                     const LocalShadowPlan& plan) {
  std::vector<LocalShadowFaceBlock> placed;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (plan.first_face[i] == kNoShadow) continue;
    for (LocalShadowFaceBlock face : shadow_faces(lights[i], plan.face_size)) {
      const auto index = static_cast<std::uint32_t>(placed.size());
      face.rect.x = (index % plan.columns) * plan.face_size;
      face.rect.y = (index / plan.columns) * plan.face_size;
      placed.push_back(face);
    }
  }
  return placed;
}

}  // namespace tilelight
