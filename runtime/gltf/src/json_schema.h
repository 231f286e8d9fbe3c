#pragma once
// The JSON types of the glTF properties, checked before tinygltf reads them: tinygltf skips an
// optional property of the wrong type without a word ("scene": "hello" would silently mean
// scene 0), and this library treats every wrong type as an error.

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string_view>

namespace tilelight::gltf_detail {

// The deepest nesting of JSON arrays and objects a file may have (glTF's own structure needs
// fewer than 10 levels; the rest is room for "extras" and extensions).
inline constexpr std::size_t kMaxJsonDepth = 64;

// The whole message for a glTF 1.0 file (JSON or binary), which this loader does not read.
inline constexpr const char* kGltf1Refused = "glTF 1.0 is not supported; convert it to 2.0";

// Parses `json_text` (no NUL byte in it, at most kMaxJsonDepth levels deep) and checks the type of every glTF 2.0 core property it has (integers
// non-negative, fixed-length number arrays of their length, required properties present),
// "name" being a string and "extensions" an object of objects everywhere, that every embedded
// (base64 data URI) buffer holds exactly its "byteLength" bytes, and that the file requires no
// extension this loader cannot honour. Throws tilelight::Error naming the property
// ("meshes[0].primitives: expected an array, got an object"), without the file's name; a
// glTF 1.0 file is refused as such (kGltf1Refused) before any type is checked. Returns the
// parsed document.
nlohmann::json check_json_schema(std::string_view json_text);

}  // namespace tilelight::gltf_detail
