#include "primitive_mesh.h"

#include "accessor_reader.h"
#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {
namespace {

// A strip or fan as a triangle list; both keep the winding of the first triangle.
std::vector<std::uint32_t> to_triangle_list(const std::vector<std::uint32_t>& indices, int mode) {
  std::vector<std::uint32_t> list;
  if (indices.size() < 3) return list;
  list.reserve((indices.size() - 2) * 3);
  for (std::size_t i = 2; i < indices.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      list.insert(list.end(), {indices[0], indices[i - 1], indices[i]});
    } else if (i % 2 == 0) {
      list.insert(list.end(), {indices[i - 2], indices[i - 1], indices[i]});
    } else {
      list.insert(list.end(), {indices[i - 1], indices[i - 2], indices[i]});
    }
  }
  return list;
}

glm::vec3 face_normal(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float length = glm::length(n);
  // A degenerate triangle covers no pixel; any unit normal will do.
  return length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

bool usable_normals(const std::vector<glm::vec3>& normals) {
  for (const glm::vec3& n : normals) {
    const float length = glm::length(n);
    if (!(length > 1e-20f) || !std::isfinite(length)) return false;
  }
  return true;
}

// The attribute `name` of `primitive` (VEC3 or texture coordinates), with POSITION's count.
template <typename Reader>
auto read_attribute(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                    const std::string& primitive_name, const std::string& attribute, std::size_t vertex_count,
                    Reader read) {
  const auto found = primitive.attributes.find(attribute);
  decltype(read(model, 0, std::string())) values;
  if (found == primitive.attributes.end()) return values;
  values = read(model, found->second, primitive_name + ".attributes." + attribute);
  if (values.size() != vertex_count) {
    throw Error(fmt::format("{}.attributes: {} has {} elements, POSITION {}", primitive_name, attribute, values.size(),
                            vertex_count));
  }
  return values;
}

}  // namespace

std::optional<Mesh> primitive_mesh(const tinygltf::Model& model, int mesh_index, int primitive_index,
                                   std::optional<int> texcoord_set) {
  const tinygltf::Primitive& primitive =
      model.meshes[static_cast<std::size_t>(mesh_index)].primitives[static_cast<std::size_t>(primitive_index)];
  const std::string name = fmt::format("meshes[{}].primitives[{}]", mesh_index, primitive_index);
  const int mode = primitive.mode;
  if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN) {
    throw Error(fmt::format("{}.mode: {} is not a glTF primitive mode (0 to 6)", name, mode));
  }
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    return std::nullopt;  // points and lines
  }
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end()) throw Error(name + ": no POSITION attribute");
  const std::vector<glm::vec3> positions = read_positions(model, position->second, name + ".attributes.POSITION");

  std::vector<std::uint32_t> indices;
  if (primitive.indices >= 0) {
    indices = read_indices(model, primitive.indices, name + ".indices", positions.size());
  } else {
    indices.resize(positions.size());
    std::iota(indices.begin(), indices.end(), 0u);
  }
  if (mode != TINYGLTF_MODE_TRIANGLES) indices = to_triangle_list(indices, mode);
  if (indices.size() > kMaxPrimitiveIndices) {
    throw Error(fmt::format("{}: {} triangles, more than this loader draws in one primitive ({})", name,
                            indices.size() / 3, kMaxPrimitiveIndices / 3));
  }
  if (indices.size() % 3 != 0) {
    throw Error(fmt::format("{}: {} {}, not a multiple of 3 (triangles)", name, indices.size(),
                            primitive.indices >= 0 ? "indices" : "vertices"));
  }
  if (indices.empty()) return std::nullopt;

  const std::vector<glm::vec3> normals =
      read_attribute(model, primitive, name, "NORMAL", positions.size(), &read_normals);
  std::vector<glm::vec2> uvs;
  if (texcoord_set) {
    const std::string attribute = fmt::format("TEXCOORD_{}", *texcoord_set);
    uvs = read_attribute(model, primitive, name, attribute, positions.size(), &read_texcoords);
    if (uvs.empty()) {
      throw Error(fmt::format("{}: its material's base colour texture reads {}, which the primitive does not have",
                              name, attribute));
    }
  }
  const auto uv = [&](std::size_t vertex) { return uvs.empty() ? glm::vec2(0.0f) : uvs[vertex]; };

  Mesh mesh{name, {}, {}};
  if (!normals.empty() && usable_normals(normals)) {
    mesh.vertices.reserve(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
      mesh.vertices.push_back({positions[i], glm::normalize(normals[i]), uv(i)});
    mesh.indices = std::move(indices);
    return mesh;
  }
  // Flat shading: three vertices of its own per triangle.
  mesh.vertices.reserve(indices.size());
  mesh.indices.resize(indices.size());
  for (std::size_t t = 0; t < indices.size(); t += 3) {
    const glm::vec3 a = positions[indices[t]], b = positions[indices[t + 1]], c = positions[indices[t + 2]];
    const glm::vec3 n = face_normal(a, b, c);
    for (std::size_t k = 0; k < 3; ++k) {
      mesh.indices[t + k] = static_cast<std::uint32_t>(t + k);
      mesh.vertices.push_back({positions[indices[t + k]], n, uv(indices[t + k])});
    }
  }
  return mesh;
}

}  // namespace tilelight::gltf_detail
