#include "scenes/hall_scene.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace tilelight::bench {
namespace {

constexpr float kBayLength = 5.0f;
constexpr float kHalfWidth = 12.0f;  // outer walls at x = +-12
constexpr float kColumnX = 6.0f;     // the two colonnades
constexpr float kColumnHeight = 11.0f;
constexpr float kArchRadius = kBayLength / 2.0f;
constexpr float kCeiling = 16.0f;
constexpr float kSkylightHalfWidth = 3.0f;

enum Material : std::uint32_t { stone, floor_tiles, plaster, wood, ceiling };

struct SurfacePoint {
  glm::vec3 position;
  glm::vec3 outward;  // any length; the normal stored is this, normalised
};

// Appends vertices and triangles to one mesh. Every triangle is wound counter-clockwise seen
// from the side its vertices' normals point to, whatever order the caller builds it in: the
// renderer culls back faces of single-sided glTF materials, so a wrong winding would show as a
// hole, not as a wrong shade.
class MeshBuilder {
 public:
  explicit MeshBuilder(HallMesh& mesh) : mesh_(mesh) {}

  std::uint32_t vertex(const SurfacePoint& p) {
    mesh_.positions.push_back(p.position);
    mesh_.normals.push_back(glm::normalize(p.outward));
    return static_cast<std::uint32_t>(mesh_.positions.size() - 1);
  }

  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const auto& p = mesh_.positions;
    const glm::vec3 face = glm::cross(p[b] - p[a], p[c] - p[a]);
    const glm::vec3 facing = mesh_.normals[a] + mesh_.normals[b] + mesh_.normals[c];
    if (glm::dot(face, facing) < 0.0f) std::swap(b, c);
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
  }

  // A rows x columns patch of quads over a parametric surface sampled at (i, j), 0 <= i <= rows,
  // 0 <= j <= columns; with `wrap`, column `columns` is column 0 (a closed ring).
  void surface(std::uint32_t rows, std::uint32_t columns, bool wrap,
               const std::function<SurfacePoint(std::uint32_t, std::uint32_t)>& at) {
    const std::uint32_t stored_columns = wrap ? columns : columns + 1;
    const std::uint32_t first = static_cast<std::uint32_t>(mesh_.positions.size());
    for (std::uint32_t i = 0; i <= rows; ++i)
      for (std::uint32_t j = 0; j < stored_columns; ++j) vertex(at(i, j));
    const auto index = [&](std::uint32_t i, std::uint32_t j) {
      return first + i * stored_columns + j % stored_columns;
    };
    for (std::uint32_t i = 0; i < rows; ++i)
      for (std::uint32_t j = 0; j < columns; ++j) {
        triangle(index(i, j), index(i + 1, j), index(i, j + 1));
        triangle(index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
      }
  }

  // An axis-aligned box from `lo` to `hi`, flat faces.
  void box(glm::vec3 lo, glm::vec3 hi) {
    for (int axis = 0; axis < 3; ++axis)
      for (float side : {-1.0f, 1.0f}) {
        glm::vec3 n(0.0f);
        n[axis] = side;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        std::uint32_t corner[4];
        for (int k = 0; k < 4; ++k) {
          glm::vec3 p;
          p[axis] = side > 0 ? hi[axis] : lo[axis];
          p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
          p[v] = (k >= 2) ? hi[v] : lo[v];
          corner[k] = vertex({p, n});
        }
        triangle(corner[0], corner[1], corner[2]);
        triangle(corner[0], corner[2], corner[3]);
      }
  }

 private:
  HallMesh& mesh_;
};

HallMesh& add_mesh(HallScene& hall, HallMesh mesh) {
  hall.meshes.push_back(std::move(mesh));
  return hall.meshes.back();
}

// Column radius at height y and angle theta: plinth, torus, tapering fluted shaft, flared capital.
float column_radius(float y, float theta) {
  if (y < 0.5f) return 0.85f;
  if (y < 0.8f) return 0.72f + 0.1f * std::sin(glm::pi<float>() * (y - 0.5f) / 0.3f);
  if (y < 9.8f) {
    const float along = (y - 0.8f) / 9.0f;
    const float fade = std::min({1.0f, along * 8.0f, (1.0f - along) * 8.0f});
    return 0.6f - 0.06f * along + 0.03f * fade * std::cos(20.0f * theta);
  }
  const float t = (y - 9.8f) / (kColumnHeight - 9.8f);
  return 0.55f + 0.35f * t * t;
}

SurfacePoint column_point(glm::vec3 base, float y, float theta) {
  const auto at = [&](float yy, float tt) {
    const float r = column_radius(yy, tt);
    return base + glm::vec3(r * std::cos(tt), yy, r * std::sin(tt));
  };
  // The normal from central differences of the parametric surface: d/dy x d/dtheta points out.
  const float h = 1e-3f;
  const glm::vec3 along_y = at(y + h, theta) - at(y - h, theta);
  const glm::vec3 around = at(y, theta + h) - at(y, theta - h);
  glm::vec3 outward = glm::cross(along_y, around);
  if (glm::dot(outward, outward) < 1e-20f) outward = glm::vec3(std::cos(theta), 0.0f, std::sin(theta));
  return {at(y, theta), outward};
}

HallMesh column(const HallOptions& options, glm::vec3 base, std::string name) {
  HallMesh mesh{std::move(name), stone, {}, {}, {}};
  MeshBuilder(mesh).surface(options.column_rings, options.column_segments, true, [&](std::uint32_t i, std::uint32_t j) {
    const float y = kColumnHeight * static_cast<float>(i) / static_cast<float>(options.column_rings);
    const float theta = glm::two_pi<float>() * static_cast<float>(j) / static_cast<float>(options.column_segments);
    return column_point(base, y, theta);
  });
  return mesh;
}

// A semicircular arch of square-ish section (a tube of 16 sides) in the plane x = `x`, from
// column centre z0 to z0 + bay length, springing from the capitals.
void arch(MeshBuilder& builder, float x, float z0) {
  constexpr std::uint32_t kAlong = 48, kAround = 16;
  constexpr float kTube = 0.4f;
  const glm::vec3 centre(x, kColumnHeight, z0 + kArchRadius);
  builder.surface(kAlong, kAround, true, [&](std::uint32_t i, std::uint32_t j) {
    const float phi = glm::pi<float>() * static_cast<float>(i) / kAlong;
    const float psi = glm::two_pi<float>() * static_cast<float>(j) / kAround;
    const glm::vec3 radial(0.0f, std::sin(phi), -std::cos(phi));  // from the arch's centre to the path
    const glm::vec3 across(1.0f, 0.0f, 0.0f);
    const glm::vec3 out = std::cos(psi) * radial + std::sin(psi) * across;
    return SurfacePoint{centre + kArchRadius * radial + kTube * out, out};
  });
}

// A side wall of one bay at x = side * kHalfWidth with a window opening in its middle.
void side_wall(MeshBuilder& builder, float side, float z0, float z1) {
  const float inner = side * kHalfWidth, outer = side * (kHalfWidth + 0.4f);
  const float x0 = std::min(inner, outer), x1 = std::max(inner, outer);
  const float zc = 0.5f * (z0 + z1);
  builder.box({x0, 0.0f, z0}, {x1, 3.0f, z1});
  builder.box({x0, 8.0f, z0}, {x1, kCeiling, z1});
  builder.box({x0, 3.0f, z0}, {x1, 8.0f, zc - 1.2f});
  builder.box({x0, 3.0f, zc + 1.2f}, {x1, 8.0f, z1});
}

void bay(const HallOptions& options, std::uint32_t k, float z0, HallScene& hall) {
  const float z1 = z0 + kBayLength, zc = z0 + 0.5f * kBayLength;
  const std::string tag = "bay " + std::to_string(k);
  for (float side : {-1.0f, 1.0f})
    hall.meshes.push_back(
        column(options, {side * kColumnX, 0.0f, zc}, tag + (side < 0 ? " column west" : " column east")));

  HallMesh& floor = add_mesh(hall, HallMesh{tag + " floor", floor_tiles, {}, {}, {}});
  MeshBuilder(floor).box({-kHalfWidth, -0.3f, z0}, {kHalfWidth, 0.0f, z1});

  HallMesh& walls = add_mesh(hall, HallMesh{tag + " walls", plaster, {}, {}, {}});
  MeshBuilder wall_builder(walls);
  for (float side : {-1.0f, 1.0f}) side_wall(wall_builder, side, z0, z1);

  HallMesh& roof = add_mesh(hall, HallMesh{tag + " ceiling", ceiling, {}, {}, {}});
  MeshBuilder roof_builder(roof);
  roof_builder.box({-kHalfWidth, kCeiling, z0}, {-kSkylightHalfWidth, kCeiling + 0.5f, z1});
  roof_builder.box({kSkylightHalfWidth, kCeiling, z0}, {kHalfWidth, kCeiling + 0.5f, z1});
  roof_builder.box({-kSkylightHalfWidth, kCeiling - 0.4f, z0}, {kSkylightHalfWidth, kCeiling + 0.5f, z0 + 0.4f});

  HallMesh& benches = add_mesh(hall, HallMesh{tag + " benches", wood, {}, {}, {}});
  MeshBuilder bench_builder(benches);
  for (float side : {-1.0f, 1.0f}) {
    const float xa = side * 1.0f, xb = side * 4.5f;
    bench_builder.box({std::min(xa, xb), 0.4f, zc - 0.25f}, {std::max(xa, xb), 0.5f, zc + 0.25f});
    bench_builder.box({std::min(xa, xb), 0.5f, zc + 0.2f}, {std::max(xa, xb), 1.0f, zc + 0.3f});
    for (float x : {xa + side * 0.2f, xb - side * 0.2f})
      bench_builder.box({x - 0.05f, 0.0f, zc - 0.2f}, {x + 0.05f, 0.4f, zc + 0.2f});
  }

  if (k + 1 < options.bays) {  // the arches to the next bay's columns
    HallMesh& arches = add_mesh(hall, HallMesh{tag + " arches", stone, {}, {}, {}});
    MeshBuilder arch_builder(arches);
    for (float side : {-1.0f, 1.0f}) arch(arch_builder, side * kColumnX, zc);
  }
}

}  // namespace

std::uint64_t HallScene::triangle_count() const {
  std::uint64_t triangles = 0;
  for (const HallMesh& mesh : meshes) triangles += mesh.indices.size() / 3;
  return triangles;
}

HallScene make_hall(const HallOptions& options) {
  HallScene hall;
  hall.materials = {{"stone", {0.85f, 0.82f, 0.75f, 1.0f}, 0.6f},
                    {"floor tiles", {0.45f, 0.40f, 0.38f, 1.0f}, 0.5f},
                    {"plaster", {0.78f, 0.64f, 0.50f, 1.0f}, 0.9f},
                    {"wood", {0.40f, 0.25f, 0.15f, 1.0f}, 0.7f},
                    {"ceiling", {0.70f, 0.70f, 0.72f, 1.0f}, 0.9f}};
  const float length = kBayLength * static_cast<float>(options.bays);
  const float start = -0.5f * length;
  for (std::uint32_t k = 0; k < options.bays; ++k) bay(options, k, start + kBayLength * static_cast<float>(k), hall);
  for (float z : {start - 0.4f, -start}) {  // the end walls close the hall
    HallMesh& end = add_mesh(hall, HallMesh{z < 0 ? "south wall" : "north wall", plaster, {}, {}, {}});
    MeshBuilder(end).box({-kHalfWidth, 0.0f, z}, {kHalfWidth, kCeiling + 0.5f, z + 0.4f});
  }
  hall.suggested_eye = {1.5f, 1.7f, start + length / 3.0f};
  hall.suggested_target = {0.0f, 5.0f, -start};
  return hall;
}

}  // namespace tilelight::bench
