#include "accessor_elements.h"

#include "accessor_reader.h"
#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace tilelight::gltf_detail {
namespace {

// Where `count` elements of `element_bytes` are, `stride` apart from `data`; every byte of
// them is inside the loaded buffer.
struct ElementRange {
  const std::uint8_t* data = nullptr;
  std::size_t count = 0;
  std::size_t stride = 0;
};

// `count` elements of `element_bytes` from `offset` in buffer view `view_index`, which `user`
// reads. `strided`: the view's byteStride applies (an accessor's own data); else the elements
// are tightly packed and the view may not have one (sparse indices and values, glTF 2.0 5.1.3).
ElementRange locate(const tinygltf::Model& model, int view_index, std::uint64_t offset, std::size_t count,
                    std::size_t element_bytes, bool strided, const std::string& user) {
  const std::span<const std::uint8_t> bytes = buffer_view_bytes(model, view_index, user);
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(view_index)];
  const std::string view_name = fmt::format("bufferViews[{}]", view_index);
  if (!strided && view.byteStride != 0) {
    throw Error(fmt::format("{} (used by {}): byteStride {} is not allowed here: sparse data is tightly packed",
                            view_name, user, view.byteStride));
  }
  const std::size_t stride = view.byteStride != 0 ? view.byteStride : element_bytes;
  if (stride < element_bytes) {
    throw Error(fmt::format("{}: byteStride {} is smaller than an element of {} ({} bytes)", view_name, view.byteStride,
                            user, element_bytes));
  }
  ElementRange range{bytes.data(), count, stride};
  if (count == 0) return range;
  // count - 1 strides plus one element, without overflow: count is checked against the view
  // before it is multiplied.
  const std::uint64_t available = bytes.size();
  const bool fits = offset <= available && element_bytes <= available - offset &&
                    count - 1 <= (available - offset - element_bytes) / stride;
  if (!fits) {
    throw Error(fmt::format("{}: {} elements of {} bytes, {} apart, from byte {} do not fit in {} ({} bytes)", user,
                            count, element_bytes, stride, offset, view_name, available));
  }
  range.data += offset;
  return range;
}

template <typename T>
T load(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
}

float float_component(const std::uint8_t* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = load<std::int8_t>(p);
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0f : *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float v = load<std::int16_t>(p);
      return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float v = load<std::uint16_t>(p);
      return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      const auto v = static_cast<float>(load<std::uint32_t>(p));
      return normalized ? v / 4294967295.0f : v;
    }
    default: return load<float>(p);
  }
}

std::uint32_t uint_component(const std::uint8_t* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(p);
    default: return load<std::uint32_t>(p);
  }
}

// Sparse indices: one of the unsigned integer types, strictly increasing, each below `count`.
std::vector<std::uint32_t> sparse_indices(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                                          const std::string& name) {
  const auto& sparse = accessor.sparse;
  const int type = sparse.indices.componentType;
  if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    throw Error(
        fmt::format("{}.indices.componentType: {} is not an unsigned 8, 16 or 32-bit integer type", name, type));
  }
  const ElementRange range =
      locate(model, sparse.indices.bufferView, static_cast<std::uint64_t>(sparse.indices.byteOffset),
             static_cast<std::size_t>(sparse.count), component_bytes(type), false, name + ".indices");
  std::vector<std::uint32_t> indices(range.count);
  for (std::size_t k = 0; k < range.count; ++k) {
    indices[k] = uint_component(range.data + k * range.stride, type);
    if (indices[k] >= accessor.count) {
      throw Error(fmt::format("{}.indices: index {} at element {} is out of range (the accessor has {} elements)", name,
                              indices[k], k, accessor.count));
    }
    if (k > 0 && indices[k] <= indices[k - 1]) {
      throw Error(fmt::format("{}.indices: index {} at element {} does not increase (the one before is {})", name,
                              indices[k], k, indices[k - 1]));
    }
  }
  return indices;
}

// Overwrites the elements the accessor's sparse substitution names.
template <typename T, typename Decode>
void apply_sparse(const tinygltf::Model& model, int index, std::size_t components, Decode decode,
                  std::vector<T>& values) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const std::string name = fmt::format("accessors[{}].sparse", index);
  const auto& sparse = accessor.sparse;
  if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > accessor.count) {
    throw Error(fmt::format("{}.count: {} elements replaced, but the accessor has {} (1 to {} may be)", name,
                            sparse.count, accessor.count, accessor.count));
  }
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
    throw Error(name + ": a negative byteOffset");
  }
  const std::vector<std::uint32_t> indices = sparse_indices(model, accessor, name);
  const std::size_t bytes = component_bytes(accessor.componentType);
  const ElementRange range =
      locate(model, sparse.values.bufferView, static_cast<std::uint64_t>(sparse.values.byteOffset), indices.size(),
             bytes * components, false, name + ".values");
  for (std::size_t k = 0; k < indices.size(); ++k) {
    for (std::size_t c = 0; c < components; ++c)
      values[indices[k] * components + c] = decode(range.data + k * range.stride + c * bytes);
  }
}

// The accessor's elements: dense from its buffer view or zeros, then its sparse substitution.
template <typename T, typename Decode>
std::vector<T> read_components(const tinygltf::Model& model, int index, std::size_t components, Decode decode) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const std::string name = fmt::format("accessors[{}]", index);
  const std::size_t bytes = component_bytes(accessor.componentType);
  if (bytes == 0) throw Error(fmt::format("{}: {} is not a glTF component type", name, accessor.componentType));
  std::vector<T> values;
  if (accessor.bufferView < 0) {
    if (accessor.count > kMaxZeroAccessorElements) {
      throw Error(fmt::format("{}: {} elements without a bufferView, more than this loader makes ({})", name,
                              accessor.count, kMaxZeroAccessorElements));
    }
    values.assign(accessor.count * components, T{});
  } else {
    const ElementRange range =
        locate(model, accessor.bufferView, accessor.byteOffset, accessor.count, bytes * components, true, name);
    values.resize(range.count * components);
    for (std::size_t i = 0; i < range.count; ++i) {
      for (std::size_t c = 0; c < components; ++c)
        values[i * components + c] = decode(range.data + i * range.stride + c * bytes);
    }
  }
  if (accessor.sparse.isSparse) apply_sparse(model, index, components, decode, values);
  return values;
}

}  // namespace

std::size_t component_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

std::vector<float> read_float_components(const tinygltf::Model& model, int index, std::size_t components) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const int type = accessor.componentType;
  const bool normalized = accessor.normalized;
  return read_components<float>(model, index, components,
                                [=](const std::uint8_t* p) { return float_component(p, type, normalized); });
}

std::vector<std::uint32_t> read_uint_components(const tinygltf::Model& model, int index) {
  const int type = model.accessors[static_cast<std::size_t>(index)].componentType;
  return read_components<std::uint32_t>(model, index, 1,
                                        [=](const std::uint8_t* p) { return uint_component(p, type); });
}

}  // namespace tilelight::gltf_detail
