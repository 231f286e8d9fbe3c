#pragma once
// EXT_meshopt_compression: buffer views whose bytes are stored compressed by meshoptimizer's
// codecs, decoded with Debian's libmeshoptimizer (its decoder only: the loader writes nothing).
// Everything that reaches the decoder is checked first: the extension's properties, the
// compressed range inside its buffer as loaded, the decoded size (the view's byteLength, at
// most kMaxMeshoptExpansion times the compressed bytes and kMaxMeshoptBytes in all), and the
// stride each codec and filter accepts. Errors are tilelight::Error naming the view
// ("bufferViews[2].extensions.EXT_meshopt_compression.mode: ..."), without the file.
//
// A fallback buffer (the extension's "fallback": true, no uri) holds no bytes: its views are
// all compressed ones. tinygltf cannot load a buffer without a uri outside a .glb's first, so
// such buffers are given an empty data URI before tinygltf reads the JSON.

#include "tinygltf.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {

inline constexpr std::size_t kMaxMeshoptExpansion = 256;
inline constexpr std::size_t kMaxMeshoptBytes = std::size_t{1} << 30;

struct MeshoptView {
  enum class Mode { attributes, triangles, indices };
  enum class Filter { none, octahedral, quaternion, exponential };
  int view = 0;
  std::size_t buffer = 0, byte_offset = 0, byte_length = 0, byte_stride = 0, count = 0;
  Mode mode = Mode::attributes;
  Filter filter = Filter::none;
};

// The compressed views of `root` (checked by check_json_schema()), their extension objects
// checked: types, mode and filter names, the strides each accepts.
std::vector<MeshoptView> meshopt_views(const nlohmann::json& root);

// Gives every fallback buffer without a uri an empty data URI and byteLength 0, so tinygltf
// loads it (as no bytes). Returns whether `root` changed.
bool empty_fallback_buffers(nlohmann::json& root);

// Decodes each view into a buffer of its own, appended to model.buffers, and points the view
// at it (byteOffset 0): the rest of the loader reads an ordinary buffer view.
void decode_meshopt_views(tinygltf::Model& model, const std::vector<MeshoptView>& views);

}  // namespace tilelight::gltf_detail
