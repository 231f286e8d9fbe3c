#pragma once
// KHR_draco_mesh_compression: primitives whose indices and attributes are stored as one Draco
// stream in a buffer view, decoded with Debian's libdraco (its decoder only).
//
// libdraco cannot be fixed here, so what reaches it and what comes back are both bounded: the
// extension's JSON (bufferView, the attributes map of glTF name -> Draco unique id, TRIANGLES,
// an indices accessor), the compressed range inside its buffer as loaded, the accessors' counts
// (at most kMaxDracoVertices vertices and kMaxDracoTriangles triangles a primitive, kMaxDracoBytes
// decoded in all) and the counts the stream's header declares (draco_stream_header.h) before
// decoding; after it, a triangle mesh whose vertex and index counts are
// the accessors' counts (the glTF specification says they must match) and whose attributes have
// the accessors' component count and type, every index within the vertices and its type.
//
// tinygltf refuses an indices accessor without a buffer view, which is how Draco files store
// them, so such accessors are pointed at their primitive's compressed view before tinygltf reads
// the JSON; decoding replaces that view.
//
// Each decoded accessor gets a buffer and a buffer view of its own, appended to the model: the
// rest of the loader reads ordinary accessors. Errors are tilelight::Error naming the element
// ("meshes[0].primitives[0].extensions.KHR_draco_mesh_compression.attributes.POSITION: ..."),
// without the file.

#include "tinygltf.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tilelight::gltf_detail {

inline constexpr std::size_t kMaxDracoVertices = std::size_t{1} << 24;
inline constexpr std::size_t kMaxDracoTriangles = std::size_t{1} << 24;
inline constexpr std::size_t kMaxDracoBytes = std::size_t{1} << 30;

struct DracoPrimitive {
  std::size_t mesh = 0, primitive = 0, buffer_view = 0, indices = 0;
  std::vector<std::pair<std::string, std::uint32_t>> attributes;  // glTF name -> Draco unique id
};

// The Draco-compressed primitives of `root` (checked by check_json_schema()), their extension
// objects checked against the primitive.
std::vector<DracoPrimitive> draco_primitives(const nlohmann::json& root);

// Gives each compressed primitive's indices accessor without a bufferView its primitive's
// compressed view, for tinygltf. Returns whether `root` changed.
bool point_draco_indices_at_streams(nlohmann::json& root, const std::vector<DracoPrimitive>& primitives);

// Decodes each primitive and points its indices and compressed attributes' accessors at the
// decoded bytes.
void decode_draco_primitives(tinygltf::Model& model, const std::vector<DracoPrimitive>& primitives);

}  // namespace tilelight::gltf_detail
