#pragma once
// A generated interior for measuring big scenes (docs/results.md, section m): a basilica-like
// hall of stone bays, each with two fluted columns, the arches between them, a floor slab, side
// walls with window openings, a coffered ceiling with a skylight slot along the nave, and
// benches. Every bay is its own set of meshes, as an asset pipeline would emit a level, so a
// view from inside leaves many of them outside the frustum (batch culling has something to
// do). Columns carry most of the triangles: `column_segments` x `column_rings` x 2 each.
//
// Coordinates are metres, y up; the nave runs along z, centred on the origin.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tilelight::bench {

struct HallOptions {
  std::uint32_t bays = 24;             // >= 1; each bay is 5 m long
  std::uint32_t column_segments = 96;  // >= 8: around each column
  std::uint32_t column_rings = 128;    // >= 4: up each column
};

struct HallMaterial {
  std::string name;
  glm::vec4 base_color;
  float roughness = 0.8f;
};

// One mesh: a triangle list wound counter-clockwise seen from outside, with unit normals.
struct HallMesh {
  std::string name;
  std::uint32_t material = 0;  // index into HallScene::materials
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<std::uint32_t> indices;
};

struct HallScene {
  std::vector<HallMaterial> materials;
  std::vector<HallMesh> meshes;  // one node each, identity transform
  // A view down the nave from inside, a third of the way along, at eye height.
  glm::vec3 suggested_eye{};
  glm::vec3 suggested_target{};

  std::uint64_t triangle_count() const;
};

// Precondition: options within the ranges above.
HallScene make_hall(const HallOptions& options);

}  // namespace tilelight::bench
