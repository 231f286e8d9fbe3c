#pragma once
// The local lights' shadow maps on the CPU (docs/local-lights.md, "Shadows"): which lights get
// maps within the pool's memory cap, where each face lies in the shadow atlas, and each face's
// transform, snapped to its texel grid. Pure functions of their arguments, independent of Vulkan.
//
// Faces: a point light has 6 (a cube: +x, -x, +y, -y, +z, -z, 90° perspective each, chosen in the
// shader by the major axis of the direction from the light); a spot 1 (a perspective map over its
// outer cone), or 6 when its outer cone is wider than kMaxSpotFaceHalfAngle; a box 1 (an
// orthographic map along `direction` covering the box). Every face reaches kFaceBorderTexels
// beyond its shape, so the jittered taps of a point inside the shape stay inside the face.
//
// Snapping (the Tabula Rasa chapter's Listing 19-2 idea, done our own way): a face's eye is
// moved to the corner of its cell of a grid of texel-sized cells in the light's frame (the
// world's axes for a cube): the texel itself for an orthographic face, the texel's footprint at
// the near plane for a perspective one (nothing nearer is drawn, so the snap moves no receiver by
// more than a texel, which the faces' border absorbs). A light that moves within one cell keeps
// bit-identical matrices, so its shadows do not shimmer.

#include "tilelight/scene/local_light.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tilelight {

inline constexpr std::uint32_t kFaceBorderTexels = 3;
inline constexpr float kMaxSpotFaceHalfAngleDegrees = 60.0f;
inline constexpr std::uint32_t kShadowDepthBytes = 4;  // D32_SFLOAT
inline constexpr std::uint32_t kNoShadow = 0xFFFFFFFFu;

// One face as the shader reads it: LocalShadowFace of uber/include/local_shadow.glsl (std430).
struct LocalShadowFaceBlock {
  glm::mat4 view_proj;   // world -> the face's clip space (Vulkan: y down, depth 0..1)
  glm::vec4 eye_offset;  // xyz the snapped eye; w the normal offset (per metre of distance when perspective)
  glm::uvec4 rect;       // xy the face's first texel in the atlas, z its size, w 1 perspective / 0 orthographic
};
static_assert(sizeof(LocalShadowFaceBlock) == 96, "std430 layout of LocalShadowFace (local_shadow.glsl)");

// 6 (point, wide spot) or 1 (spot, box).
std::uint32_t shadow_face_count(const LocalLight& light);

// The faces' blocks of one light, their rects' xy left 0 (the pool places them).
// Preconditions: `face_size` > 2 * kFaceBorderTexels; the light is valid (local_light.h).
std::vector<LocalShadowFaceBlock> shadow_faces(const LocalLight& light, std::uint32_t face_size);

// The spacing of the light's snapping grid (above), in metres.
float shadow_snap_cell(const LocalLight& light, std::uint32_t face_size);

// `position` moved to the corner of its cell of a grid of spacing `step` along the orthonormal
// axes x, y, z (through the world origin). Precondition: step > 0.
glm::vec3 snap_to_grid(glm::vec3 position, glm::vec3 x, glm::vec3 y, glm::vec3 z, float step);

// The pool: which lights get maps, in scene order, while their faces fit under the cap (a light
// whose faces do not fit is drawn unshadowed, and a later, smaller one may still fit).
struct LocalShadowPlan {
  std::vector<std::uint32_t> first_face;  // per light: its first face, or kNoShadow
  std::vector<std::uint32_t> face_count;  // per light: 0, 1 or 6
  std::uint32_t maps = 0;                 // lights with a map
  std::uint32_t faces = 0;
  std::uint32_t unshadowed = 0;  // lights that cast shadows but got no map (over the cap)
  std::uint32_t face_size = 0;
  std::uint32_t columns = 0, rows = 0;  // the atlas, in faces (0 without faces)
  std::uint64_t bytes = 0;              // the atlas's depth texels
  std::uint64_t cap_bytes = 0;
};

// Lights with casts_shadows get maps when `enabled`. `max_atlas_texels`: the largest atlas side
// the device allows (image and framebuffer). Preconditions: face_size > 2 * kFaceBorderTexels and
// <= max_atlas_texels.
LocalShadowPlan plan_local_shadows(const std::vector<LocalLight>& lights, bool enabled, std::uint32_t face_size,
                                   std::uint64_t cap_bytes, std::uint32_t max_atlas_texels);

// Every face of the plan, placed in the atlas (row-major, `columns` per row).
std::vector<LocalShadowFaceBlock> place_shadow_faces(const std::vector<LocalLight>& lights,
                                                     const LocalShadowPlan& plan);

}  // namespace tilelight
