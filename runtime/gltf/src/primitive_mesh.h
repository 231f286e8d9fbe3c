#pragma once
// One glTF mesh primitive as a triangle-list Mesh in the primitive's own space.

#include "tilelight/scene/scene.h"
#include "tinygltf.h"

#include <cstddef>
#include <optional>

namespace tilelight::gltf_detail {

// The most triangle-list indices one primitive may have (16.7 million triangles).
inline constexpr std::size_t kMaxPrimitiveIndices = std::size_t{3} << 24;

// Triangles (mode 4), triangle strips (5) and fans (6) become a triangle list; the other modes
// (points, lines) have no surface and give std::nullopt, as does a primitive with no triangle.
// Normals come from NORMAL, renormalised; where it is absent or any of its vectors is zero,
// every triangle gets its flat face normal. Errors (tilelight::Error, naming the primitive):
// no POSITION, accessors as accessor_reader.h checks them, a NORMAL count that differs from
// POSITION's, an index count not a multiple of 3, an unknown mode.
// `texcoord_set` n: the vertices' uv come from TEXCOORD_n (the material's base colour texture
// reads it), which must then exist with POSITION's count; none: every uv is 0.
std::optional<Mesh> primitive_mesh(const tinygltf::Model& model, int mesh_index, int primitive_index,
                                   std::optional<int> texcoord_set);

}  // namespace tilelight::gltf_detail
