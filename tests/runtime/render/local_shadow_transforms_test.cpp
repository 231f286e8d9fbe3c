// The local lights' shadow transforms and pool (runtime/render/src/local_shadow_transforms.h, an
// internal part of tilelight::render): a light that moves within one texel-sized cell keeps
// bit-identical face matrices (no shimmer) and one that moves a cell does not; each face covers
// its light's shape with the taps' border to spare; the pool gives maps in scene order while the
// faces fit under the cap and places every face in its own square of the atlas.
#include "local_shadow_transforms.h"
#include "local_light_block.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstring>
#include <set>
#include <utility>
#include <vector>

namespace tilelight {
namespace {

constexpr std::uint32_t kSize = 512;

LocalLight point_light(glm::vec3 position) {
  LocalLight l;
  l.type = LocalLightType::point;
  l.position = position;
  l.range = 8.0f;
  return l;
}

LocalLight spot_light(glm::vec3 position, float outer_degrees) {
  LocalLight l;
  l.type = LocalLightType::spot;
  l.position = position;
  l.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.3f));
  l.range = 10.0f;
  l.outer_cone_cos = std::cos(glm::radians(outer_degrees));
  l.inner_cone_cos = std::cos(glm::radians(outer_degrees * 0.5f));
  return l;
}

LocalLight box_light(glm::vec3 position) {
  LocalLight l;
  l.type = LocalLightType::box;
  l.position = position;
  l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
  l.box_half_extent = {4.0f, 3.0f, 2.0f};
  return l;
}

bool same_bits(const std::vector<LocalShadowFaceBlock>& a, const std::vector<LocalShadowFaceBlock>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(LocalShadowFaceBlock)) == 0;
}

// The light's snapping axes (local_shadow_transforms.cpp): the world's for a cube, else its frame.
struct Axes {
  glm::vec3 x, y, z;
};

Axes axes_of(const LocalLight& light) {
  if (shadow_face_count(light) == 6) return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const glm::vec3 x = local_light_frame_x(light.direction);
  return {x, glm::cross(light.direction, x), light.direction};
}

TEST(LocalShadowTransforms, MovesWithinACellKeepTheMatricesAndACellChangesThem) {
  for (LocalLight light : {point_light({1.234f, 3.21f, -7.7f}), spot_light({-2.5f, 6.1f, 3.3f}, 35.0f),
                           spot_light({0.7f, 4.0f, 1.0f}, 75.0f), box_light({3.3f, 1.7f, -4.2f})}) {
    const Axes a = axes_of(light);
    const float cell = shadow_snap_cell(light, kSize);
    // The corner of the light's cell, then two points well inside the same cell.
    const glm::vec3 corner = snap_to_grid(light.position, a.x, a.y, a.z, cell);
    light.position = corner + 0.2f * cell * (a.x + a.y + a.z);
    const std::vector<LocalShadowFaceBlock> first = shadow_faces(light, kSize);
    light.position = corner + 0.7f * cell * (a.x + a.y + a.z);
    EXPECT_TRUE(same_bits(first, shadow_faces(light, kSize))) << static_cast<int>(light.type);
    light.position = corner + 1.5f * cell * a.x;
    EXPECT_FALSE(same_bits(first, shadow_faces(light, kSize))) << static_cast<int>(light.type);
  }
}

TEST(LocalShadowTransforms, FaceCountsFollowTheType) {
  EXPECT_EQ(shadow_face_count(point_light({})), 6u);
  EXPECT_EQ(shadow_face_count(spot_light({}, 40.0f)), 1u);
  EXPECT_EQ(shadow_face_count(spot_light({}, 75.0f)), 6u);  // wider than one map serves
  EXPECT_EQ(shadow_face_count(box_light({})), 1u);
}

// Where `p` lands in a face, in texels from its edge: every coordinate in [0, size).
glm::vec3 face_texel(const LocalShadowFaceBlock& face, glm::vec3 p) {
  const glm::vec4 clip = face.view_proj * glm::vec4(p, 1.0f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * kSize, (ndc.y * 0.5f + 0.5f) * kSize, ndc.z};
}

void expect_inside_with_border(const LocalShadowFaceBlock& face, glm::vec3 p, const char* what) {
  const glm::vec3 t = face_texel(face, p);
  const float border = static_cast<float>(kFaceBorderTexels) - 1.0f;  // the snap moves a receiver < a texel
  EXPECT_GE(t.x, border) << what;
  EXPECT_LE(t.x, kSize - border) << what;
  EXPECT_GE(t.y, border) << what;
  EXPECT_LE(t.y, kSize - border) << what;
  EXPECT_GE(t.z, 0.0f) << what;
  EXPECT_LE(t.z, 1.0f) << what;
}

TEST(LocalShadowTransforms, FacesCoverTheLightsShapeWithTheTapsBorder) {
  // A point light: any direction, through the face its major axis picks (local_shadow.glsl).
  const LocalLight point = point_light({0.5f, 2.0f, -1.0f});
  const std::vector<LocalShadowFaceBlock> cube = shadow_faces(point, kSize);
  for (int i = 0; i < 200; ++i) {
    const float u = static_cast<float>(i) * 0.618034f, v = static_cast<float>(i) * 0.1234f;
    const glm::vec3 d = glm::normalize(glm::vec3(std::sin(u * 6.3f), std::cos(v * 5.1f), std::sin(u * 2.7f + v)));
    const glm::vec3 p = point.position + d * (point.range * 0.9f);
    const glm::vec3 offset = p - glm::vec3(cube[0].eye_offset);
    const glm::vec3 m = glm::abs(offset);
    const std::uint32_t f = m.x >= m.y && m.x >= m.z ? (offset.x >= 0 ? 0 : 1)
                            : m.y >= m.z             ? (offset.y >= 0 ? 2 : 3)
                                                     : (offset.z >= 0 ? 4 : 5);
    expect_inside_with_border(cube[f], p, "point");
  }
  // A spot: the outer cone's rim, near and far.
  const LocalLight spot = spot_light({1.0f, 5.0f, 2.0f}, 35.0f);
  const LocalShadowFaceBlock face = shadow_faces(spot, kSize).front();
  const glm::vec3 x = local_light_frame_x(spot.direction), y = glm::cross(spot.direction, x);
  const float tan_outer = std::tan(std::acos(spot.outer_cone_cos));
  for (const float along : {0.5f, 9.5f}) {
    for (int k = 0; k < 16; ++k) {
      const float a = static_cast<float>(k) * 0.3927f;
      const glm::vec3 p = spot.position + along * (spot.direction + tan_outer * (std::cos(a) * x + std::sin(a) * y));
      expect_inside_with_border(face, p, "spot");
    }
  }
  // A box: its corners.
  const LocalLight box = box_light({-2.0f, 1.0f, 4.0f});
  const LocalShadowFaceBlock box_face = shadow_faces(box, kSize).front();
  const glm::vec3 bx = local_light_frame_x(box.direction), by = glm::cross(box.direction, bx);
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 s{(c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, (c & 4) ? 1.0f : -1.0f};
    const glm::vec3 h = box.box_half_extent * s;
    expect_inside_with_border(box_face, box.position + h.x * bx + h.y * by + h.z * box.direction, "box");
  }
}

TEST(LocalShadowPool, MapsInSceneOrderWhileTheFacesFitUnderTheCap) {
  std::vector<LocalLight> lights{spot_light({}, 30.0f), point_light({}), box_light({}), point_light({}),
                                 spot_light({}, 30.0f)};
  lights[2].casts_shadows = false;
  const std::uint64_t face_bytes = std::uint64_t{kSize} * kSize * kShadowDepthBytes;
  // 8 faces: the spot (1), the first point (6), not the box (casts none), not the second point
  // (7 + 6 > 8), the last spot (8).
  const LocalShadowPlan plan = plan_local_shadows(lights, true, kSize, 8 * face_bytes, 16384);
  EXPECT_EQ(plan.first_face, (std::vector<std::uint32_t>{0, 1, kNoShadow, kNoShadow, 7}));
  EXPECT_EQ(plan.face_count, (std::vector<std::uint32_t>{1, 6, 0, 0, 1}));
  EXPECT_EQ(plan.maps, 3u);
  EXPECT_EQ(plan.faces, 8u);
  EXPECT_EQ(plan.unshadowed, 1u);
  EXPECT_EQ(plan.columns * plan.rows * face_bytes, plan.bytes);
  EXPECT_GE(plan.columns * plan.rows, plan.faces);

  // Every face in its own square of the atlas.
  const std::vector<LocalShadowFaceBlock> placed = place_shadow_faces(lights, plan);
  ASSERT_EQ(placed.size(), 8u);
  std::set<std::pair<std::uint32_t, std::uint32_t>> corners;
  for (const LocalShadowFaceBlock& face : placed) {
    EXPECT_EQ(face.rect.x % kSize, 0u);
    EXPECT_EQ(face.rect.y % kSize, 0u);
    EXPECT_LT(face.rect.x, plan.columns * kSize);
    EXPECT_LT(face.rect.y, plan.rows * kSize);
    corners.insert({face.rect.x, face.rect.y});
  }
  EXPECT_EQ(corners.size(), 8u);

  // Off: no maps, nothing counted as left out.
  const LocalShadowPlan off = plan_local_shadows(lights, false, kSize, 8 * face_bytes, 16384);
  EXPECT_EQ(off.maps, 0u);
  EXPECT_EQ(off.unshadowed, 0u);
  EXPECT_EQ(off.bytes, 0u);
}

// The issue's scale: 256 shadowed point lights at 1024² would be 1,536 faces, about 6.4 GB;
// under the default cap (256 MiB) at 512², 256 faces: 42 point lights get maps.
TEST(LocalShadowPool, TheDefaultCapAtTheIssuesScale) {
  const std::vector<LocalLight> lights(256, point_light({}));
  const LocalShadowPlan plan = plan_local_shadows(lights, true, 512, 256ull << 20, 16384);
  EXPECT_EQ(plan.maps, 42u);
  EXPECT_EQ(plan.faces, 252u);
  EXPECT_EQ(plan.unshadowed, 214u);
  EXPECT_LE(plan.bytes, plan.cap_bytes);
}

}  // namespace
}  // namespace tilelight
