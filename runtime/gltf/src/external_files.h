#pragma once
// The files a glTF file names by URI (external buffers and images), found beside it. A missing
// one is named by its resolved path, so the user sees where the loader looked, before
// tinygltf is asked to read it (tinygltf would say "File not found : name.bin", with no path).

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace tilelight::gltf_detail {

// The file `uri` (a relative URI reference, %XX escapes decoded) names in `base_dir`, as an
// absolute path. Throws tilelight::Error "<element>: the file <path> does not exist (uri
// "<uri>")" when there is no such file, "... is not a file" when it is something else.
std::filesystem::path external_file(const std::filesystem::path& base_dir, const std::string& uri,
                                    const std::string& element);

// Every external buffer of `root` (checked by check_json_schema()) exists, through
// external_file(). `base_dir` empty (a load from memory): any external buffer is an error.
void check_external_buffers(const nlohmann::json& root, const std::filesystem::path& base_dir);

}  // namespace tilelight::gltf_detail
