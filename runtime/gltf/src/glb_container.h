#pragma once
// The binary glTF container (.glb): a 12-byte header, a JSON chunk, an optional BIN chunk.
// Checked here before tinygltf sees it, so that a truncated or malformed file gets a message
// that says which length is wrong.

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace tilelight::gltf_detail {

// True when `bytes` start with the GLB magic "glTF" (then they must be a valid GLB).
bool is_glb(std::span<const std::uint8_t> bytes);

struct GlbChunks {
  std::string_view json;              // the JSON chunk's text
  std::span<const std::uint8_t> bin;  // the BIN chunk's payload; empty when there is none
};

// Throws tilelight::Error saying what is wrong ("truncated: the GLB header says 1200 bytes, the
// file has 1000"), without the file's name. Precondition: is_glb(bytes).
GlbChunks split_glb(std::span<const std::uint8_t> bytes);

// A GLB of `json` (padded with spaces) and, when not empty, `bin` (padded with zeros): how a
// .glb whose JSON the loader had to change (meshopt_views.h) is given to tinygltf.
std::vector<std::uint8_t> make_glb(std::string_view json, std::span<const std::uint8_t> bin);

}  // namespace tilelight::gltf_detail
