// The demo scene. Placement is procedural but seeded, so every run renders the same frame.
#include "tilelight/scene/scene.h"

#include "tilelight/base/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

namespace tilelight {
namespace {

constexpr float kPi = 3.14159265358979f;

void add_quad_face(Mesh& mesh, glm::vec3 centre, glm::vec3 u, glm::vec3 v) {
  const glm::vec3 normal = glm::normalize(glm::cross(u, v));
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back({centre - u - v, normal});
  mesh.vertices.push_back({centre + u - v, normal});
  mesh.vertices.push_back({centre + u + v, normal});
  mesh.vertices.push_back({centre - u + v, normal});
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

// Unit cube from -0.5 to 0.5, one flat-shaded quad per face.
Mesh make_cube() {
  Mesh mesh{"cube", {}, {}, true};
  const glm::vec3 x{0.5f, 0, 0}, y{0, 0.5f, 0}, z{0, 0, 0.5f};
  add_quad_face(mesh, x, -z, y);
  add_quad_face(mesh, -x, z, y);
  add_quad_face(mesh, y, z, x);
  add_quad_face(mesh, -y, x, z);
  add_quad_face(mesh, z, x, y);
  add_quad_face(mesh, -z, -x, y);
  return mesh;
}

// Unit sphere (radius 1) as a latitude/longitude grid with smooth normals.
Mesh make_sphere(std::uint32_t rings, std::uint32_t segments) {
  Mesh mesh{"sphere", {}, {}};
  for (std::uint32_t r = 0; r <= rings; ++r) {
    const float theta = kPi * static_cast<float>(r) / static_cast<float>(rings);
    for (std::uint32_t s = 0; s <= segments; ++s) {
      const float phi = 2.0f * kPi * static_cast<float>(s) / static_cast<float>(segments);
      const glm::vec3 p{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
      mesh.vertices.push_back({p, p});
    }
  }
  for (std::uint32_t r = 0; r < rings; ++r) {
    for (std::uint32_t s = 0; s < segments; ++s) {
      const std::uint32_t a = r * (segments + 1) + s;
      const std::uint32_t b = a + segments + 1;
      for (std::uint32_t i : {a, a + 1, b, a + 1, b + 1, b}) mesh.indices.push_back(i);
    }
  }
  return mesh;
}

// Ground: one large quad at y = 0 facing up.
Mesh make_ground(float half_size) {
  Mesh mesh{"ground", {}, {}, true};
  add_quad_face(mesh, {0, 0, 0}, {0, 0, half_size}, {half_size, 0, 0});
  return mesh;
}

struct InstanceMaker {
  std::uint32_t next_motion_id = 1;

  Instance make(const glm::mat4& model, glm::vec3 albedo, float spec_amount, float spec_power, float checker) {
    const auto motion = static_cast<float>(next_motion_id);
    next_motion_id = next_motion_id % 127u + 1u;  // 1..127; 0 means sky
    return Instance{model, glm::vec4(albedo, spec_amount), glm::vec4(spec_power, motion, checker, 0.0f)};
  }
};

glm::mat4 box_transform(glm::vec3 base_centre, glm::vec3 size, float yaw) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), base_centre + glm::vec3(0, size.y * 0.5f, 0));
  m = glm::rotate(m, yaw, glm::vec3(0, 1, 0));
  return glm::scale(m, size);
}

void add_boxes(Scene& scene, InstanceMaker& maker, std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // Rows of boxes and pillars in front of the default camera, thinning out with distance.
  for (int row = 0; row < 12; ++row) {
    for (int column = -6; column <= 6; ++column) {
      if (unit(rng) < 0.35f) continue;
      const glm::vec3 base{static_cast<float>(column) * 7.0f + (unit(rng) - 0.5f) * 3.0f, 0.0f,
                           -8.0f - static_cast<float>(row) * 7.0f + (unit(rng) - 0.5f) * 3.0f};
      const bool pillar = unit(rng) < 0.3f;
      const glm::vec3 size = pillar
                                 ? glm::vec3(0.8f, 6.0f + unit(rng) * 8.0f, 0.8f)
                                 : glm::vec3(1.0f + unit(rng) * 2.5f, 0.8f + unit(rng) * 3.5f, 1.0f + unit(rng) * 2.5f);
      const glm::vec3 albedo =
          pillar ? glm::vec3(0.75f, 0.72f, 0.65f)
                 : glm::vec3(0.35f + 0.5f * unit(rng), 0.3f + 0.3f * unit(rng), 0.25f + 0.3f * unit(rng));
      scene.instances.push_back(maker.make(box_transform(base, size, unit(rng) * kPi), albedo, pillar ? 0.2f : 0.5f,
                                           pillar ? 8.0f : 32.0f, 0.0f));
    }
  }
  // Distant buildings, beyond the shadow-fade and scattering start distances.
  for (int i = 0; i < 18; ++i) {
    const float angle = -1.1f + 2.2f * static_cast<float>(i) / 17.0f;
    const float distance = 130.0f + unit(rng) * 120.0f;
    const glm::vec3 base{std::sin(angle) * distance, 0.0f, -std::cos(angle) * distance};
    const glm::vec3 size{8.0f + unit(rng) * 14.0f, 12.0f + unit(rng) * 30.0f, 8.0f + unit(rng) * 14.0f};
    scene.instances.push_back(
        maker.make(box_transform(base, size, unit(rng) * kPi), glm::vec3(0.55f, 0.55f, 0.6f), 0.3f, 16.0f, 4.0f));
  }
  // The canopy: a wide slab on four legs whose shadow covers a large patch of ground, seen
  // by the "shadow" camera.
  const glm::vec3 canopy{140.0f, 30.0f, 40.0f};
  scene.instances.push_back(
      maker.make(box_transform(canopy, {60.0f, 2.0f, 60.0f}, 0.0f), glm::vec3(0.4f, 0.4f, 0.45f), 0.1f, 4.0f, 0.0f));
  for (float dx : {-28.0f, 28.0f}) {
    for (float dz : {-28.0f, 28.0f}) {
      scene.instances.push_back(
          maker.make(box_transform({canopy.x + dx, 0.0f, canopy.z + dz}, {1.5f, 30.0f, 1.5f}, 0.0f),
                     glm::vec3(0.4f, 0.4f, 0.45f), 0.1f, 4.0f, 0.0f));
    }
  }
}

void add_spheres(Scene& scene, InstanceMaker& maker, std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 14; ++i) {
    const float radius = 0.8f + unit(rng) * 1.8f;
    const glm::vec3 centre{(unit(rng) - 0.5f) * 60.0f, radius, -6.0f - unit(rng) * 60.0f};
    glm::mat4 model = glm::translate(glm::mat4(1.0f), centre);
    model = glm::scale(model, glm::vec3(radius));
    const glm::vec3 albedo{0.2f + 0.7f * unit(rng), 0.2f + 0.7f * unit(rng), 0.2f + 0.7f * unit(rng)};
    scene.instances.push_back(maker.make(model, albedo, 0.8f, 64.0f, 0.0f));
  }
}

}  // namespace

SunAndAtmosphere make_demo_sun() {
  SunAndAtmosphere sun{};
  sun.sun_direction = glm::normalize(glm::vec3(-0.55f, 0.62f, 0.35f));
  sun.sun_color = glm::vec3(1.55f, 1.45f, 1.25f);
  sun.fog_color = glm::vec3(0.62f, 0.70f, 0.80f);
  sun.fog_density = 0.012f;
  sun.shadow_fade_start = 55.0f;
  sun.shadow_fade_length = 30.0f;
  sun.scattering_start = 75.0f;
  sun.shadow_depth_bias = 0.0004f;
  sun.shadow_half_extent = 90.0f;
  sun.shadow_depth_range = 400.0f;
  sun.shadow_map_size = 2048;
  sun.sky_zenith = glm::vec3(0.22f, 0.42f, 0.78f);
  sun.sky_horizon = glm::vec3(0.70f, 0.78f, 0.88f);
  sun.ambient_sky = glm::vec3(0.36f, 0.40f, 0.48f);
  sun.ambient_ground = glm::vec3(0.16f, 0.15f, 0.13f);
  return sun;
}

namespace {

std::vector<Camera> demo_cameras(const SunAndAtmosphere& sun) {
  std::vector<Camera> cameras;
  // One camera per entry, name and description first.
  // clang-format off
  cameras.push_back({"default", "over the boxes towards the distant buildings: all seven properties",
                     {0.0f, 7.0f, 22.0f}, {0.0f, 1.5f, -40.0f}, {0, 1, 0}, 60.0f, {0.0f, 0.0f, -30.0f}});
  // Far from every object, looking straight up: nothing but sky.
  cameras.push_back({"sky", "straight up from an empty corner of the ground: only sky",
                     {280.0f, 1.7f, 280.0f}, {280.0f, 100.0f, 280.0f}, {0, 0, -1}, 60.0f,
                     {280.0f, 0.0f, 280.0f}});
  // Looking down at the middle of the canopy's shadow on the ground.
  const glm::vec3 canopy_underside{140.0f, 29.0f, 40.0f};
  const glm::vec3 shadow_centre = canopy_underside - sun.sun_direction * (canopy_underside.y / sun.sun_direction.y);
  cameras.push_back({"shadow", "straight down into the canopy's shadow: only ground in solid shadow",
                     shadow_centre + glm::vec3(0.0f, 9.0f, 0.0f), shadow_centre, {0, 0, -1}, 45.0f,
                     shadow_centre});
  cameras.push_back({"low", "a grazing view across the boxes into the sun",
                     {-30.0f, 1.8f, 5.0f}, {10.0f, 3.0f, -60.0f}, {0, 1, 0}, 70.0f, {-5.0f, 0.0f, -35.0f}});
  // The two views below show little or no sky, where every tile needs lighting: the default
  // camera's 37 % sky flatters tile classification (a sky tile costs almost nothing).
  // Inside the field, down the gap between two columns of boxes and pillars, pitched down 12 degrees.
  cameras.push_back({"street", "down the street between the boxes and pillars: little sky",
                     {3.5f, 1.7f, -9.0f}, {3.5f, -8.9f, -59.0f}, {0, 1, 0}, 60.0f, {3.5f, 0.0f, -40.0f}});
  // A canopy leg from 8 m, pitched down 25 degrees: the leg and the ground at its foot, all in the
  // canopy's shadow but for the far edge.
  cameras.push_back({"closeup", "close-up of a canopy leg in the canopy's shadow: no sky, mostly shadowed",
                     {163.0f, 3.0f, 19.0f}, {168.0f, -0.8f, 12.0f}, {0, 1, 0}, 40.0f, {166.0f, 0.0f, 18.0f}});
  // clang-format on
  return cameras;
}

}  // namespace

const Camera& Scene::camera(std::string_view name) const {
  for (const Camera& c : cameras) {
    if (c.name == name) return c;
  }
  std::string known;
  for (const Camera& c : cameras) known += (known.empty() ? "" : ", ") + c.name;
  throw Error("unknown camera '" + std::string(name) + "' (known: " + known + ")");
}

std::uint64_t Scene::triangle_count() const {
  std::uint64_t triangles = 0;
  for (const MeshBatch& batch : batches) {
    triangles += static_cast<std::uint64_t>(meshes.at(batch.mesh).indices.size() / 3) * batch.instance_count;
  }
  return triangles;
}

std::vector<std::string> Scene::camera_names() const {
  std::vector<std::string> names;
  for (const Camera& c : cameras) names.push_back(c.name);
  return names;
}

// material.w of every instance of a flat_faces mesh (see Mesh).
void mark_flat_faced_instances(Scene& scene) {
  for (const MeshBatch& batch : scene.batches) {
    const float flat = scene.meshes[batch.mesh].flat_faces ? 1.0f : 0.0f;
    for (std::uint32_t i = 0; i < batch.instance_count; ++i)
      scene.instances[batch.first_instance + i].material.w = flat;
  }
}

Scene make_demo_scene() {
  Scene scene;
  scene.sun = make_demo_sun();
  scene.meshes.push_back(make_ground(300.0f));
  scene.meshes.push_back(make_cube());
  scene.meshes.push_back(make_sphere(24, 48));

  std::mt19937 rng(20101);  // fixed seed: the same frame on every run
  InstanceMaker maker;
  scene.instances.push_back(maker.make(glm::mat4(1.0f), glm::vec3(0.42f, 0.45f, 0.36f), 0.15f, 12.0f, 2.0f));
  scene.batches.push_back({0, 0, 1});

  const auto first_box = static_cast<std::uint32_t>(scene.instances.size());
  add_boxes(scene, maker, rng);
  scene.batches.push_back({1, first_box, static_cast<std::uint32_t>(scene.instances.size()) - first_box});

  const auto first_sphere = static_cast<std::uint32_t>(scene.instances.size());
  add_spheres(scene, maker, rng);
  scene.batches.push_back({2, first_sphere, static_cast<std::uint32_t>(scene.instances.size()) - first_sphere});

  mark_flat_faced_instances(scene);
  scene.cameras = demo_cameras(scene.sun);
  return scene;
}

CameraMatrices camera_matrices(const Camera& camera, float aspect) {
  const glm::mat4 view = glm::lookAtRH(camera.position, camera.target, camera.up);
  glm::mat4 proj =
      glm::perspectiveRH_ZO(glm::radians(camera.vertical_fov_degrees), aspect, camera.near_plane, camera.far_plane);
  proj[1][1] = -proj[1][1];  // Vulkan: NDC y points down
  const glm::mat4 view_proj = proj * view;
  return {view_proj, glm::inverse(view_proj), glm::normalize(camera.target - camera.position)};
}

glm::mat4 sun_view_proj(const SunAndAtmosphere& sun, const Camera& camera) {
  const glm::vec3 eye = camera.shadow_focus + sun.sun_direction * (sun.shadow_depth_range * 0.5f);
  const glm::vec3 up = std::abs(sun.sun_direction.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  const glm::mat4 view = glm::lookAtRH(eye, camera.shadow_focus, up);
  const float e = sun.shadow_half_extent;
  const glm::mat4 proj = glm::orthoRH_ZO(-e, e, -e, e, 0.0f, sun.shadow_depth_range);
  return proj * view;
}

}  // namespace tilelight
