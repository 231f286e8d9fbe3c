#include "accessor_reader.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace tilelight::gltf_detail {
namespace {

// Where an accessor's elements are: `count` elements of `element_bytes`, `stride` apart,
// starting at `data`. Every byte of it is inside the loaded buffer.
struct ElementRange {
  const std::uint8_t* data = nullptr;
  std::size_t count = 0;
  std::size_t stride = 0;
};

std::string accessor_name(int index) { return fmt::format("accessors[{}]", index); }

const tinygltf::Accessor& find_accessor(const tinygltf::Model& model, int index, const std::string& user) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    throw Error(fmt::format("{}: accessor {} does not exist (the file has {})", user, index, model.accessors.size()));
  }
  return model.accessors[static_cast<std::size_t>(index)];
}

ElementRange locate(const tinygltf::Model& model, int index, std::size_t element_bytes) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const std::string name = accessor_name(index);
  if (accessor.sparse.isSparse) throw Error(name + ": sparse accessors are not supported");
  if (accessor.bufferView < 0) throw Error(name + ": no bufferView (an all-zero accessor has nothing to draw)");
  const std::span<const std::uint8_t> bytes = buffer_view_bytes(model, accessor.bufferView, name);
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  const std::string view_name = fmt::format("bufferViews[{}]", accessor.bufferView);
  const std::size_t stride = view.byteStride != 0 ? view.byteStride : element_bytes;
  if (stride < element_bytes) {
    throw Error(fmt::format("{}: byteStride {} is smaller than an element of {} ({} bytes)", view_name, view.byteStride,
                            name, element_bytes));
  }
  ElementRange range{bytes.data(), accessor.count, stride};
  if (accessor.count == 0) return range;
  // count - 1 strides plus one element, without overflow: count is checked against the view
  // before it is multiplied.
  const std::uint64_t offset = accessor.byteOffset;
  const std::uint64_t available = view.byteLength;
  const bool fits = offset <= available && element_bytes <= available - offset &&
                    accessor.count - 1 <= (available - offset - element_bytes) / stride;
  if (!fits) {
    throw Error(fmt::format("{}: {} elements of {} bytes, {} apart, from byte {} do not fit in {} ({} bytes)", name,
                            accessor.count, element_bytes, stride, offset, view_name, available));
  }
  range.data += offset;
  return range;
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

std::vector<glm::vec3> read_vec3(const tinygltf::Model& model, int index, const std::string& user) {
  const tinygltf::Accessor& accessor = find_accessor(model, index, user);
  const std::string name = accessor_name(index);
  if (accessor.type != TINYGLTF_TYPE_VEC3 || accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
    throw Error(fmt::format("{} (used as {}): expected VEC3 of 32-bit floats, got {} of component type {}", name, user,
                            type_name(accessor.type), accessor.componentType));
  }
  const ElementRange range = locate(model, index, sizeof(float) * 3);
  std::vector<glm::vec3> values(range.count);
  for (std::size_t i = 0; i < range.count; ++i) {
    float xyz[3];
    std::memcpy(xyz, range.data + i * range.stride, sizeof xyz);
    if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
      throw Error(
          fmt::format("{} (used as {}): element {} is not finite ({}, {}, {})", name, user, i, xyz[0], xyz[1], xyz[2]));
    }
    values[i] = glm::vec3(xyz[0], xyz[1], xyz[2]);
  }
  return values;
}

std::vector<glm::vec2> read_texcoords(const tinygltf::Model& model, int index, const std::string& user) {
  const tinygltf::Accessor& accessor = find_accessor(model, index, user);
  const std::string name = accessor_name(index);
  const int component = accessor.componentType;
  const bool normalised_integer = accessor.normalized && (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                          component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  if (accessor.type != TINYGLTF_TYPE_VEC2 || (component != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalised_integer)) {
    throw Error(
        fmt::format("{} (used as {}): expected VEC2 of 32-bit floats or of normalized unsigned 8 or 16-bit integers, "
                    "got {} of component type {}{}",
                    name, user, type_name(accessor.type), component, accessor.normalized ? " (normalized)" : ""));
  }
  const std::size_t component_bytes = component == TINYGLTF_COMPONENT_TYPE_FLOAT            ? 4
                                      : component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                                                                            : 1;
  const ElementRange range = locate(model, index, component_bytes * 2);
  std::vector<glm::vec2> values(range.count);
  for (std::size_t i = 0; i < range.count; ++i) {
    const std::uint8_t* p = range.data + i * range.stride;
    if (component_bytes == 4) {
      float uv[2];
      std::memcpy(uv, p, sizeof uv);
      if (!std::isfinite(uv[0]) || !std::isfinite(uv[1])) {
        throw Error(fmt::format("{} (used as {}): element {} is not finite ({}, {})", name, user, i, uv[0], uv[1]));
      }
      values[i] = glm::vec2(uv[0], uv[1]);
    } else if (component_bytes == 2) {
      std::uint16_t uv[2];
      std::memcpy(uv, p, sizeof uv);
      values[i] = glm::vec2(uv[0], uv[1]) / 65535.0f;
    } else {
      values[i] = glm::vec2(p[0], p[1]) / 255.0f;
    }
  }
  return values;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& user,
                                        std::size_t vertex_count) {
  const tinygltf::Accessor& accessor = find_accessor(model, index, user);
  const std::string name = accessor_name(index);
  std::size_t bytes = 0;
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: bytes = 1; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: bytes = 2; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: bytes = 4; break;
    default: bytes = 0;
  }
  if (accessor.type != TINYGLTF_TYPE_SCALAR || bytes == 0) {
    throw Error(
        fmt::format("{} (used as {}): expected SCALAR of unsigned 8, 16 or 32-bit integers, got {} of component "
                    "type {}",
                    name, user, type_name(accessor.type), accessor.componentType));
  }
  const ElementRange range = locate(model, index, bytes);
  std::vector<std::uint32_t> indices(range.count);
  for (std::size_t i = 0; i < range.count; ++i) {
    const std::uint8_t* p = range.data + i * range.stride;
    std::uint32_t value = 0;
    if (bytes == 1) {
      value = *p;
    } else if (bytes == 2) {
      std::uint16_t v16 = 0;
      std::memcpy(&v16, p, 2);
      value = v16;
    } else {
      std::memcpy(&value, p, 4);
    }
    if (value >= vertex_count) {
      throw Error(fmt::format("{} (used as {}): index {} at element {} is out of range (the primitive has {} vertices)",
                              name, user, value, i, vertex_count));
    }
    indices[i] = value;
  }
  return indices;
}

}  // namespace tilelight::gltf_detail
