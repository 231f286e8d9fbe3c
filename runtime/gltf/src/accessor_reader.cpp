#include "accessor_reader.h"

#include "accessor_elements.h"
#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace tilelight::gltf_detail {
namespace {

enum class Use { position, normal, texcoord };

std::string accessor_name(int index) { return fmt::format("accessors[{}]", index); }

const tinygltf::Accessor& find_accessor(const tinygltf::Model& model, int index, const std::string& user) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    throw Error(fmt::format("{}: accessor {} does not exist (the file has {})", user, index, model.accessors.size()));
  }
  return model.accessors[static_cast<std::size_t>(index)];
}

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "an unknown type";
  }
}

std::string component_name(int component) {
  switch (component) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "signed 8-bit integers";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "unsigned 8-bit integers";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "signed 16-bit integers";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "unsigned 16-bit integers";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "unsigned 32-bit integers";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "32-bit floats";
    default: return fmt::format("component type {}", component);
  }
}

std::string format_name(const tinygltf::Accessor& a) {
  return fmt::format("{} of {}{}", type_name(a.type), component_name(a.componentType),
                     a.normalized ? " (normalized)" : "");
}

bool small_integer(int component) {
  return component == TINYGLTF_COMPONENT_TYPE_BYTE || component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         component == TINYGLTF_COMPONENT_TYPE_SHORT || component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

// The component formats core glTF 2.0 allows for the use ("Meshes", attribute table).
bool core_format(Use use, int component, bool normalized) {
  if (component == TINYGLTF_COMPONENT_TYPE_FLOAT) return true;
  return use == Use::texcoord && normalized &&
         (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
}

// Those KHR_mesh_quantization adds: normals stay unit vectors, so only as normalized signed
// integers; positions and texture coordinates in any 8 or 16-bit form (the node's transform or
// the texture transform scales them back).
bool quantized_format(Use use, int component, bool normalized) {
  if (use == Use::normal) {
    return normalized && (component == TINYGLTF_COMPONENT_TYPE_BYTE || component == TINYGLTF_COMPONENT_TYPE_SHORT);
  }
  return small_integer(component);
}

const char* expected_formats(Use use) {
  switch (use) {
    case Use::position: return "VEC3 of 32-bit floats (or, with KHR_mesh_quantization, of 8 or 16-bit integers)";
    case Use::normal:
      return "VEC3 of 32-bit floats (or, with KHR_mesh_quantization, of normalized signed 8 or 16-bit integers)";
    case Use::texcoord:
      return "VEC2 of 32-bit floats or of normalized unsigned 8 or 16-bit integers (or, with "
             "KHR_mesh_quantization, of 8 or 16-bit integers)";
  }
  return "";
}

bool lists_quantization(const tinygltf::Model& model) {
  return std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_mesh_quantization") !=
         model.extensionsUsed.end();
}

// The accessor's type and format suit the use; a quantized format only where the file says so.
void check_format(const tinygltf::Model& model, int index, const std::string& user, Use use) {
  const tinygltf::Accessor& a = find_accessor(model, index, user);
  const int expected_type = use == Use::texcoord ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3;
  const std::string name = accessor_name(index);
  const bool quantized = quantized_format(use, a.componentType, a.normalized);
  if (a.type != expected_type || (!core_format(use, a.componentType, a.normalized) && !quantized)) {
    throw Error(fmt::format("{} (used as {}): expected {}, got {}", name, user, expected_formats(use), format_name(a)));
  }
  if (!core_format(use, a.componentType, a.normalized) && !lists_quantization(model)) {
    throw Error(
        fmt::format("{} (used as {}): {} needs KHR_mesh_quantization, which the file does not list in "
                    "extensionsUsed",
                    name, user, format_name(a)));
  }
}

// Components as read, `N` per element, every one finite.
template <int N>
std::vector<glm::vec<N, float>> read_vectors(const tinygltf::Model& model, int index, const std::string& user) {
  const std::vector<float> components = read_float_components(model, index, N);
  std::vector<glm::vec<N, float>> values(components.size() / N);
  for (std::size_t i = 0; i < values.size(); ++i) {
    bool finite = true;
    for (int c = 0; c < N; ++c) {
      values[i][c] = components[i * N + static_cast<std::size_t>(c)];
      finite = finite && std::isfinite(values[i][c]);
    }
    if (!finite) {
      std::string shown;
      for (int c = 0; c < N; ++c) shown += fmt::format("{}{}", c == 0 ? "" : ", ", values[i][c]);
      throw Error(fmt::format("{} (used as {}): element {} is not finite ({})", accessor_name(index), user, i, shown));
    }
  }
  return values;
}

}  // namespace

std::span<const std::uint8_t> buffer_view_bytes(const tinygltf::Model& model, int index, const std::string& user) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.bufferViews.size()) {
    throw Error(
        fmt::format("{}: bufferView {} does not exist (the file has {})", user, index, model.bufferViews.size()));
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(index)];
  const std::string view_name = fmt::format("bufferViews[{}]", index);
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    throw Error(
        fmt::format("{}: buffer {} does not exist (the file has {})", view_name, view.buffer, model.buffers.size()));
  }
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  // Sizes are at most the file's, so these sums of two cannot overflow 64 bits.
  if (static_cast<std::uint64_t>(view.byteOffset) + view.byteLength > buffer.size()) {
    throw Error(fmt::format("{}: bytes {}..{} are past the end of buffers[{}], which has {} bytes", view_name,
                            view.byteOffset, static_cast<std::uint64_t>(view.byteOffset) + view.byteLength, view.buffer,
                            buffer.size()));
  }
  return {buffer.data() + view.byteOffset, view.byteLength};
}

std::vector<glm::vec3> read_positions(const tinygltf::Model& model, int index, const std::string& user) {
  check_format(model, index, user, Use::position);
  return read_vectors<3>(model, index, user);
}

std::vector<glm::vec3> read_normals(const tinygltf::Model& model, int index, const std::string& user) {
  check_format(model, index, user, Use::normal);
  return read_vectors<3>(model, index, user);
}

std::vector<glm::vec2> read_texcoords(const tinygltf::Model& model, int index, const std::string& user) {
  check_format(model, index, user, Use::texcoord);
  return read_vectors<2>(model, index, user);
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& user,
                                        std::size_t vertex_count) {
  const tinygltf::Accessor& accessor = find_accessor(model, index, user);
  const std::string name = accessor_name(index);
  const int component = accessor.componentType;
  const bool unsigned_integer = component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  if (accessor.type != TINYGLTF_TYPE_SCALAR || !unsigned_integer) {
    throw Error(fmt::format("{} (used as {}): expected SCALAR of unsigned 8, 16 or 32-bit integers, got {}", name, user,
                            format_name(accessor)));
  }
  std::vector<std::uint32_t> indices = read_uint_components(model, index);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= vertex_count) {
      throw Error(fmt::format("{} (used as {}): index {} at element {} is out of range (the primitive has {} vertices)",
                              name, user, indices[i], i, vertex_count));
    }
  }
  return indices;
}

}  // namespace tilelight::gltf_detail
