#include "meshopt_views.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>
#include <meshoptimizer.h>

#include <cstdint>
#include <limits>
#include <string_view>

namespace tilelight::gltf_detail {
namespace {

using Json = nlohmann::json;

constexpr const char* kExtension = "EXT_meshopt_compression";

// Four zero bytes: tinygltf refuses an empty data URI, and a fallback buffer's bytes are never read.
constexpr const char* kPlaceholderUri = "data:application/octet-stream;base64,AAAAAA==";

std::size_t uint_property(const Json& object, const char* key, const std::string& path, bool required,
                          std::size_t otherwise = 0) {
  const auto found = object.find(key);
  if (found == object.end()) {
    if (required) throw Error(fmt::format("{}.{}: missing (required)", path, key));
    return otherwise;
  }
  if (!found->is_number_unsigned() && !(found->is_number_integer() && found->get<std::int64_t>() >= 0)) {
    throw Error(fmt::format("{}.{}: expected a non-negative integer", path, key));
  }
  const auto value = found->get<std::uint64_t>();
  if (value > std::numeric_limits<std::uint32_t>::max()) {
    throw Error(fmt::format("{}.{}: {} is larger than this loader reads", path, key, value));
  }
  return static_cast<std::size_t>(value);
}

std::string string_property(const Json& object, const char* key, const std::string& path, const char* otherwise) {
  const auto found = object.find(key);
  if (found == object.end()) {
    if (otherwise == nullptr) throw Error(fmt::format("{}.{}: missing (required)", path, key));
    return otherwise;
  }
  if (!found->is_string()) throw Error(fmt::format("{}.{}: expected a string", path, key));
  return found->get<std::string>();
}

MeshoptView::Mode mode_of(const std::string& name, const std::string& path) {
  if (name == "ATTRIBUTES") return MeshoptView::Mode::attributes;
  if (name == "TRIANGLES") return MeshoptView::Mode::triangles;
  if (name == "INDICES") return MeshoptView::Mode::indices;
  throw Error(fmt::format("{}.mode: \"{}\" is not ATTRIBUTES, TRIANGLES or INDICES", path, name));
}

MeshoptView::Filter filter_of(const std::string& name, const std::string& path) {
  if (name == "NONE") return MeshoptView::Filter::none;
  if (name == "OCTAHEDRAL") return MeshoptView::Filter::octahedral;
  if (name == "QUATERNION") return MeshoptView::Filter::quaternion;
  if (name == "EXPONENTIAL") return MeshoptView::Filter::exponential;
  throw Error(fmt::format("{}.filter: \"{}\" is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL", path, name));
}

// The strides the codecs and filters accept (the extension's specification, "Codecs").
void check_stride(const MeshoptView& v, const std::string& path) {
  const std::size_t s = v.byte_stride;
  if (v.mode == MeshoptView::Mode::attributes && (s == 0 || s % 4 != 0 || s > 256)) {
    throw Error(fmt::format("{}.byteStride: {} (ATTRIBUTES needs a multiple of 4 up to 256)", path, s));
  }
  if (v.mode != MeshoptView::Mode::attributes && s != 2 && s != 4) {
    throw Error(fmt::format("{}.byteStride: {} (TRIANGLES and INDICES need 2 or 4)", path, s));
  }
  if (v.mode == MeshoptView::Mode::triangles && v.count % 3 != 0) {
    throw Error(fmt::format("{}.count: {} is not a multiple of 3 (TRIANGLES)", path, v.count));
  }
  if (v.filter != MeshoptView::Filter::none && v.mode != MeshoptView::Mode::attributes) {
    throw Error(fmt::format("{}.filter: only ATTRIBUTES may be filtered", path));
  }
  const bool filter_fits =
      v.filter == MeshoptView::Filter::none || (v.filter == MeshoptView::Filter::octahedral && (s == 4 || s == 8)) ||
      (v.filter == MeshoptView::Filter::quaternion && s == 8) || v.filter == MeshoptView::Filter::exponential;
  if (!filter_fits) throw Error(fmt::format("{}.byteStride: {} does not suit the filter", path, s));
}

MeshoptView view_of(const Json& extension, int index, const std::string& path) {
  if (!extension.is_object()) throw Error(path + ": expected an object");
  MeshoptView v;
  v.view = index;
  v.buffer = uint_property(extension, "buffer", path, true);
  v.byte_offset = uint_property(extension, "byteOffset", path, false);
  v.byte_length = uint_property(extension, "byteLength", path, true);
  v.byte_stride = uint_property(extension, "byteStride", path, true);
  v.count = uint_property(extension, "count", path, true);
  v.mode = mode_of(string_property(extension, "mode", path, nullptr), path);
  v.filter = filter_of(string_property(extension, "filter", path, "NONE"), path);
  check_stride(v, path);
  return v;
}

// The compressed bytes, inside the buffer as loaded. `file_buffers`: the file's own buffers,
// before any decoded one was appended.
const std::uint8_t* compressed_bytes(const tinygltf::Model& model, std::size_t file_buffers, const MeshoptView& v,
                                     const std::string& path) {
  if (v.buffer >= file_buffers) {
    throw Error(fmt::format("{}.buffer: buffer {} does not exist (the file has {})", path, v.buffer, file_buffers));
  }
  const std::vector<unsigned char>& data = model.buffers[v.buffer].data;
  if (static_cast<std::uint64_t>(v.byte_offset) + v.byte_length > data.size()) {
    throw Error(fmt::format("{}: bytes {}..{} are past the end of buffers[{}], which has {} bytes", path, v.byte_offset,
                            static_cast<std::uint64_t>(v.byte_offset) + v.byte_length, v.buffer, data.size()));
  }
  return data.data() + v.byte_offset;
}

std::vector<unsigned char> decode(const std::uint8_t* source, const MeshoptView& v, const std::string& path) {
  std::vector<unsigned char> out(v.count * v.byte_stride);
  int result = 0;
  switch (v.mode) {
    case MeshoptView::Mode::attributes:
      result = meshopt_decodeVertexBuffer(out.data(), v.count, v.byte_stride, source, v.byte_length);
      break;
    case MeshoptView::Mode::triangles:
      result = meshopt_decodeIndexBuffer(out.data(), v.count, v.byte_stride, source, v.byte_length);
      break;
    case MeshoptView::Mode::indices:
      result = meshopt_decodeIndexSequence(out.data(), v.count, v.byte_stride, source, v.byte_length);
      break;
  }
  if (result != 0) {
    throw Error(fmt::format("{}: the compressed data is corrupt (meshoptimizer's decoder returned {})", path, result));
  }
  switch (v.filter) {
    case MeshoptView::Filter::none: break;
    case MeshoptView::Filter::octahedral: meshopt_decodeFilterOct(out.data(), v.count, v.byte_stride); break;
    case MeshoptView::Filter::quaternion: meshopt_decodeFilterQuat(out.data(), v.count, v.byte_stride); break;
    case MeshoptView::Filter::exponential: meshopt_decodeFilterExp(out.data(), v.count, v.byte_stride); break;
  }
  return out;
}

}  // namespace

std::vector<MeshoptView> meshopt_views(const nlohmann::json& root) {
  std::vector<MeshoptView> views;
  const auto buffer_views = root.find("bufferViews");
  if (buffer_views == root.end()) return views;
  for (std::size_t i = 0; i < buffer_views->size(); ++i) {
    const Json& view = (*buffer_views)[i];
    const auto extensions = view.find("extensions");
    if (extensions == view.end() || !extensions->contains(kExtension)) continue;
    const std::string path = fmt::format("bufferViews[{}].extensions.{}", i, kExtension);
    views.push_back(view_of((*extensions)[kExtension], static_cast<int>(i), path));
    const std::size_t decoded = views.back().count * views.back().byte_stride;
    if (decoded != view["byteLength"].get<std::uint64_t>()) {
      throw Error(fmt::format("{}: count {} x byteStride {} is {} bytes, but the view's byteLength is {}", path,
                              views.back().count, views.back().byte_stride, decoded,
                              view["byteLength"].get<std::uint64_t>()));
    }
  }
  return views;
}

bool empty_fallback_buffers(nlohmann::json& root) {
  bool changed = false;
  const auto buffers = root.find("buffers");
  if (buffers == root.end()) return false;
  for (Json& buffer : *buffers) {
    const auto extensions = buffer.find("extensions");
    if (buffer.contains("uri") || extensions == buffer.end() || !extensions->contains(kExtension)) continue;
    const Json& ext = (*extensions)[kExtension];
    const auto fallback = ext.find("fallback");
    if (fallback == ext.end() || !fallback->is_boolean() || !fallback->get<bool>()) continue;
    buffer["uri"] = kPlaceholderUri;
    buffer["byteLength"] = 4;
    changed = true;
  }
  return changed;
}

void decode_meshopt_views(tinygltf::Model& model, const std::vector<MeshoptView>& views) {
  std::size_t total = 0;
  const std::size_t file_buffers = model.buffers.size();
  for (const MeshoptView& v : views) {
    const std::string path = fmt::format("bufferViews[{}].extensions.{}", v.view, kExtension);
    const std::size_t decoded = v.count * v.byte_stride;
    total += decoded;
    if (decoded > kMaxMeshoptExpansion * v.byte_length + 4096 || total > kMaxMeshoptBytes) {
      throw Error(
          fmt::format("{}: {} bytes from {} compressed ones, more than this loader decodes (at most {} "
                      "times as many, {} in all)",
                      path, decoded, v.byte_length, kMaxMeshoptExpansion, kMaxMeshoptBytes));
    }
    tinygltf::Buffer buffer;
    buffer.data = decode(compressed_bytes(model, file_buffers, v, path), v, path);
    model.buffers.push_back(std::move(buffer));
    tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(v.view)];
    view.buffer = static_cast<int>(model.buffers.size() - 1);
    view.byteOffset = 0;
  }
}

}  // namespace tilelight::gltf_detail
