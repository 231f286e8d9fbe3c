#include "draco_primitives.h"

#include "draco_stream_header.h"
#include "tilelight/base/error.h"

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <draco/mesh/mesh.h>
#include <fmt/format.h>

#include <cstring>
#include <limits>
#include <memory>
#include <span>

namespace tilelight::gltf_detail {
namespace {

using Json = nlohmann::json;

constexpr const char* kExtension = "KHR_draco_mesh_compression";

std::string path_of(std::size_t mesh, std::size_t primitive) {
  return fmt::format("meshes[{}].primitives[{}].extensions.{}", mesh, primitive, kExtension);
}

// A non-negative integer up to 2^32 - 1 (Draco's unique ids and glTF's indices both fit).
std::uint32_t index_value(const Json& value, const std::string& path) {
  if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0)) {
    throw Error(path + ": expected a non-negative integer");
  }
  const auto n = value.get<std::uint64_t>();
  if (n > std::numeric_limits<std::uint32_t>::max()) {
    throw Error(fmt::format("{}: {} is larger than this loader reads", path, n));
  }
  return static_cast<std::uint32_t>(n);
}

// What the extension needs of its primitive: triangles, with indices (Draco stores faces).
void check_primitive(const Json& primitive, const std::string& primitive_path) {
  const auto mode = primitive.find("mode");
  if (mode != primitive.end() && !(mode->is_number_integer() && mode->get<std::int64_t>() == TINYGLTF_MODE_TRIANGLES)) {
    throw Error(primitive_path + ".mode: a Draco-compressed primitive must be TRIANGLES (4)");
  }
  if (!primitive.contains("indices")) {
    throw Error(primitive_path + ".indices: missing (a Draco-compressed primitive needs its indices accessor)");
  }
}

DracoPrimitive primitive_of(const Json& root, const Json& primitive, std::size_t mesh, std::size_t k) {
  const std::string path = path_of(mesh, k);
  check_primitive(primitive, fmt::format("meshes[{}].primitives[{}]", mesh, k));
  const Json& extension = primitive["extensions"][kExtension];
  if (!extension.is_object()) throw Error(path + ": expected an object");
  DracoPrimitive p{
      mesh, k, 0, index_value(primitive["indices"], fmt::format("meshes[{}].primitives[{}].indices", mesh, k)), {}};
  const auto view = extension.find("bufferView");
  if (view == extension.end()) throw Error(path + ".bufferView: missing (required)");
  p.buffer_view = index_value(*view, path + ".bufferView");
  const std::size_t views = root.contains("bufferViews") ? root["bufferViews"].size() : 0;
  if (p.buffer_view >= views) {
    throw Error(
        fmt::format("{}.bufferView: buffer view {} does not exist (the file has {})", path, p.buffer_view, views));
  }
  const auto attributes = extension.find("attributes");
  if (attributes == extension.end()) throw Error(path + ".attributes: missing (required)");
  if (!attributes->is_object()) throw Error(path + ".attributes: expected an object");
  const Json& plain = primitive["attributes"];
  for (const auto& [name, id] : attributes->items()) {
    const std::string attribute_path = path + ".attributes." + name;
    if (!plain.contains(name)) throw Error(attribute_path + ": not one of the primitive's attributes");
    p.attributes.emplace_back(name, index_value(id, attribute_path));
  }
  return p;
}

const tinygltf::Accessor& accessor_at(const tinygltf::Model& model, int index, const std::string& path) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    throw Error(fmt::format("{}: accessor {} does not exist (the file has {})", path, index, model.accessors.size()));
  }
  return model.accessors[static_cast<std::size_t>(index)];
}

std::size_t element_bytes(const tinygltf::Accessor& accessor) {
  const int component = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
  const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
  return component > 0 && components > 0 ? static_cast<std::size_t>(component * components) : 0;
}

// The compressed stream, inside its buffer as loaded (after any meshopt view was decoded).
std::span<const char> compressed_bytes(const tinygltf::Model& model, const DracoPrimitive& p, const std::string& path) {
  const tinygltf::BufferView& view = model.bufferViews[p.buffer_view];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    throw Error(fmt::format("{}.bufferView: its buffer {} does not exist", path, view.buffer));
  }
  const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const std::uint64_t end = static_cast<std::uint64_t>(view.byteOffset) + view.byteLength;
  if (end > data.size()) {
    throw Error(
        fmt::format("{}.bufferView: bytes {}..{} of bufferViews[{}] are past the end of buffers[{}], which "
                    "has {} bytes",
                    path, view.byteOffset, end, p.buffer_view, view.buffer, data.size()));
  }
  return {reinterpret_cast<const char*>(data.data()) + view.byteOffset, view.byteLength};
}

// The accessors the decoded data replaces, checked before anything is decoded: counts within
// the caps, the decoded bytes within kMaxDracoBytes over the whole file (`total`).
void check_counts(const tinygltf::Model& model, const DracoPrimitive& p, std::size_t& total, const std::string& path) {
  const tinygltf::Primitive& primitive = model.meshes[p.mesh].primitives[p.primitive];
  const tinygltf::Accessor& indices = accessor_at(model, primitive.indices, path + ".indices");
  if (indices.count % 3 != 0 || indices.count / 3 > kMaxDracoTriangles) {
    throw Error(fmt::format("{}: the indices accessor's count {} is not 3 x at most {} triangles", path, indices.count,
                            kMaxDracoTriangles));
  }
  total += indices.count * element_bytes(indices);
  for (const auto& [name, id] : p.attributes) {
    const tinygltf::Accessor& accessor =
        accessor_at(model, primitive.attributes.at(name), path + ".attributes." + name);
    if (accessor.count > kMaxDracoVertices) {
      throw Error(fmt::format("{}.attributes.{}: count {} is more than this loader decodes ({} vertices)", path, name,
                              accessor.count, kMaxDracoVertices));
    }
    total += accessor.count * element_bytes(accessor);
  }
  if (total > kMaxDracoBytes) {
    throw Error(
        fmt::format("{}: {} decoded bytes in all, more than this loader decodes ({})", path, total, kMaxDracoBytes));
  }
}

// The counts the stream declares, against the accessors', before libdraco allocates for them.
void check_declared_counts(const tinygltf::Model& model, const DracoPrimitive& p, std::span<const char> bytes,
                           const std::string& path) {
  const DracoStreamCounts declared =
      draco_stream_counts({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, path);
  const tinygltf::Primitive& primitive = model.meshes[p.mesh].primitives[p.primitive];
  const std::size_t indices = model.accessors[static_cast<std::size_t>(primitive.indices)].count;
  if (declared.faces * 3 != indices) {
    throw Error(fmt::format("{}: the Draco stream declares {} triangles, but accessors[{}] has count {}", path,
                            declared.faces, primitive.indices, indices));
  }
  for (const auto& [name, id] : p.attributes) {
    const int index = primitive.attributes.at(name);
    const std::size_t count = model.accessors[static_cast<std::size_t>(index)].count;
    if (declared.vertices_are_points ? declared.vertices != count : declared.vertices > count) {
      throw Error(fmt::format("{}.attributes.{}: the Draco stream declares {} vertices, but accessors[{}] has count {}",
                              path, name, declared.vertices, index, count));
    }
  }
}

std::unique_ptr<draco::Mesh> decode_mesh(std::span<const char> bytes, const std::string& path) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok()) throw Error(fmt::format("{}: not a Draco stream (libdraco: {})", path, type.status().error_msg()));
  if (type.value() != draco::TRIANGULAR_MESH) throw Error(path + ": the Draco stream is not a triangle mesh");
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) {
    throw Error(fmt::format("{}: the compressed data is corrupt (libdraco: {})", path, decoded.status().error_msg()));
  }
  return std::move(decoded).value();
}

// Puts `bytes` in a buffer and a view of their own and points the accessor at them.
void substitute(tinygltf::Model& model, int accessor, std::vector<unsigned char> bytes) {
  tinygltf::BufferView view;
  view.buffer = static_cast<int>(model.buffers.size());
  view.byteLength = bytes.size();
  model.buffers.emplace_back().data = std::move(bytes);
  model.bufferViews.push_back(std::move(view));
  tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor)];
  a.bufferView = static_cast<int>(model.bufferViews.size() - 1);
  a.byteOffset = 0;
}

draco::DataType draco_type(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return draco::DT_INT8;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return draco::DT_UINT8;
    case TINYGLTF_COMPONENT_TYPE_SHORT: return draco::DT_INT16;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return draco::DT_UINT16;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return draco::DT_UINT32;
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return draco::DT_FLOAT32;
    default: return draco::DT_INVALID;
  }
}

const char* draco_type_name(draco::DataType type) {
  switch (type) {
    case draco::DT_INT8: return "int8";
    case draco::DT_UINT8: return "uint8";
    case draco::DT_INT16: return "int16";
    case draco::DT_UINT16: return "uint16";
    case draco::DT_INT32: return "int32";
    case draco::DT_UINT32: return "uint32";
    case draco::DT_FLOAT32: return "float32";
    default: return "unusual";
  }
}

const char* component_type_name(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "unknown";
  }
}

void decode_attribute(tinygltf::Model& model, const draco::Mesh& mesh, int index, std::uint32_t id,
                      const std::string& path) {
  const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id);
  if (attribute == nullptr) throw Error(fmt::format("{}: Draco attribute {} is not in the compressed data", path, id));
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
  const std::size_t bytes = element_bytes(accessor);
  if (attribute->num_components() != components || attribute->data_type() != draco_type(accessor.componentType) ||
      static_cast<std::size_t>(attribute->byte_stride()) != bytes || bytes == 0) {
    throw Error(fmt::format("{}: decodes to {} {} components a vertex, which do not fit accessors[{}] ({} {})", path,
                            attribute->num_components(), draco_type_name(attribute->data_type()), index, components,
                            component_type_name(accessor.componentType)));
  }
  if (mesh.num_points() != accessor.count) {
    throw Error(fmt::format("{}: decodes to {} vertices, but accessors[{}] has count {}", path, mesh.num_points(),
                            index, accessor.count));
  }
  std::vector<unsigned char> out(accessor.count * bytes);
  for (std::uint32_t i = 0; i < mesh.num_points(); ++i)
    attribute->GetMappedValue(draco::PointIndex(i), &out[i * bytes]);
  substitute(model, index, std::move(out));
}

void decode_indices(tinygltf::Model& model, const draco::Mesh& mesh, int index, const std::string& path) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  if (static_cast<std::size_t>(mesh.num_faces()) * 3 != accessor.count) {
    throw Error(fmt::format("{}: decodes to {} indices, but accessors[{}] has count {}", path,
                            static_cast<std::size_t>(mesh.num_faces()) * 3, index, accessor.count));
  }
  const std::size_t bytes = element_bytes(accessor);
  if (accessor.type != TINYGLTF_TYPE_SCALAR || (bytes != 1 && bytes != 2 && bytes != 4) ||
      accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
    throw Error(fmt::format("{}: accessors[{}] is not an unsigned integer scalar", path, index));
  }
  const std::uint64_t largest = bytes == 4 ? 0xFFFFFFFFu : (std::uint64_t{1} << (8 * bytes)) - 1;
  std::vector<unsigned char> out(accessor.count * bytes);
  for (std::uint32_t f = 0; f < mesh.num_faces(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t value = mesh.face(draco::FaceIndex(f))[c].value();
      if (value >= mesh.num_points() || value > largest) {
        throw Error(fmt::format("{}: decoded index {} does not fit {} vertices and accessors[{}]", path, value,
                                mesh.num_points(), index));
      }
      std::memcpy(&out[(3 * f + c) * bytes], &value, bytes);  // little-endian, as glTF stores it
    }
  }
  substitute(model, index, std::move(out));
}

}  // namespace

std::vector<DracoPrimitive> draco_primitives(const nlohmann::json& root) {
  std::vector<DracoPrimitive> found;
  const auto meshes = root.find("meshes");
  if (meshes == root.end()) return found;
  for (std::size_t m = 0; m < meshes->size(); ++m) {
    const Json& primitives = (*meshes)[m]["primitives"];
    for (std::size_t k = 0; k < primitives.size(); ++k) {
      const auto extensions = primitives[k].find("extensions");
      if (extensions == primitives[k].end() || !extensions->contains(kExtension)) continue;
      found.push_back(primitive_of(root, primitives[k], m, k));
    }
  }
  return found;
}

bool point_draco_indices_at_streams(nlohmann::json& root, const std::vector<DracoPrimitive>& primitives) {
  bool changed = false;
  const auto accessors = root.find("accessors");
  for (const DracoPrimitive& p : primitives) {
    // An accessor that does not exist is reported by the loader's own checks.
    if (accessors == root.end() || p.indices >= accessors->size()) continue;
    Json& accessor = (*accessors)[p.indices];
    if (!accessor.is_object() || accessor.contains("bufferView")) continue;
    accessor["bufferView"] = p.buffer_view;
    changed = true;
  }
  return changed;
}

void decode_draco_primitives(tinygltf::Model& model, const std::vector<DracoPrimitive>& primitives) {
  std::size_t total = 0;
  for (const DracoPrimitive& p : primitives) {
    const std::string path = path_of(p.mesh, p.primitive);
    check_counts(model, p, total, path);
    const std::span<const char> bytes = compressed_bytes(model, p, path);
    check_declared_counts(model, p, bytes, path);
    const std::unique_ptr<draco::Mesh> mesh = decode_mesh(bytes, path);
    const tinygltf::Primitive& primitive = model.meshes[p.mesh].primitives[p.primitive];
    decode_indices(model, *mesh, primitive.indices, path);
    for (const auto& [name, id] : p.attributes) {
      decode_attribute(model, *mesh, primitive.attributes.at(name), id, path + ".attributes." + name);
    }
  }
}

}  // namespace tilelight::gltf_detail
