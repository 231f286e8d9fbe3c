// The light-volume meshes (runtime/render/src/local_light_volumes.h, an internal part of
// tilelight::render): each encloses its unit shape, so the volume pass can shade every pixel the
// full-screen pass lights; every triangle faces outwards (counter-clockwise seen from outside),
// so culling front faces leaves the back faces; and the far-plane test the volume pass relies on
// where the device cannot clamp depth.
#include "local_light_volumes.h"
#include "tilelight/scene/scene.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace tilelight {
namespace {

struct Plane {
  glm::vec3 normal;  // outwards, not normalised
  float offset;      // dot(normal, a point of the plane)
};

std::vector<Plane> face_planes(const VolumeMeshes& m, LightVolume volume) {
  const VolumeMesh& mesh = m.meshes[static_cast<std::uint32_t>(volume)];
  std::vector<Plane> planes;
  for (std::uint32_t i = mesh.first_index; i < mesh.first_index + mesh.index_count; i += 3) {
    const glm::vec3 a = m.vertices[m.indices[i]], b = m.vertices[m.indices[i + 1]], c = m.vertices[m.indices[i + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    planes.push_back({n, glm::dot(n, a)});
  }
  return planes;
}

// Every point inside every face's half-space: inside the convex mesh.
std::string first_outside(const std::vector<Plane>& planes, const std::vector<glm::vec3>& points) {
  for (const glm::vec3& p : points) {
    for (const Plane& plane : planes) {
      if (glm::dot(plane.normal, p) > plane.offset) {
        return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
      }
    }
  }
  return "";
}

std::vector<glm::vec3> circle(float z, int count) {
  std::vector<glm::vec3> points;
  for (int i = 0; i < count; ++i) {
    const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(count);
    points.push_back({std::cos(a), std::sin(a), z});
  }
  return points;
}

TEST(LightVolumes, EachMeshEnclosesItsShapeAndFacesOutwards) {
  const VolumeMeshes m = make_volume_meshes();
  // Sphere: a dense set of unit-sphere points (the faces' planes are also checked to lie at a
  // distance of at least 1 from the centre, which is the whole sphere).
  const std::vector<Plane> sphere = face_planes(m, LightVolume::sphere);
  ASSERT_FALSE(sphere.empty());
  for (const Plane& p : sphere) EXPECT_GE(p.offset / glm::length(p.normal), 1.0f);
  // Cone: the apex and the base circle (the cone is their convex hull).
  std::vector<glm::vec3> cone_points = circle(1.0f, 720);
  cone_points.push_back(glm::vec3(0.0f));
  EXPECT_EQ(first_outside(face_planes(m, LightVolume::cone), cone_points), "");
  // Box: its corners.
  std::vector<glm::vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back({(i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f});
  EXPECT_EQ(first_outside(face_planes(m, LightVolume::box), corners), "");
  // Outwards: the shape's centre is behind every face (offset > normal . centre).
  for (LightVolume v : {LightVolume::sphere, LightVolume::cone, LightVolume::box}) {
    const glm::vec3 centre = v == LightVolume::cone ? glm::vec3(0.0f, 0.0f, 0.6f) : glm::vec3(0.0f);
    for (const Plane& p : face_planes(m, v)) EXPECT_GT(p.offset, glm::dot(p.normal, centre));
  }
}

TEST(LightVolumes, TheVolumeOfEachLight) {
  LocalLight light;
  EXPECT_EQ(volume_of(light), LightVolume::sphere);
  light.type = LocalLightType::box;
  EXPECT_EQ(volume_of(light), LightVolume::box);
  light.type = LocalLightType::spot;
  light.outer_cone_cos = std::cos(glm::radians(45.0f));
  EXPECT_EQ(volume_of(light), LightVolume::cone);
  light.outer_cone_cos = std::cos(glm::radians(85.0f));  // tan() too large: the sphere
  EXPECT_EQ(volume_of(light), LightVolume::sphere);
}

TEST(LightVolumes, FarPlaneCrossing) {
  Camera camera = make_demo_scene().camera("default");  // at (0, 7, 22), looking towards -z
  LocalLight light;
  light.position = {0.0f, 2.0f, 6.0f};  // about 16 m ahead
  light.range = 8.0f;
  EXPECT_FALSE(may_cross_far_plane(light, camera_matrices(camera, 1.5f).view_proj));
  camera.far_plane = 18.0f;
  EXPECT_TRUE(may_cross_far_plane(light, camera_matrices(camera, 1.5f).view_proj));
}

}  // namespace
}  // namespace tilelight
