#pragma once
// What a glTF file holds that the loader does not draw, as one line per feature, so that a
// user learns of it rather than wondering why the frame differs from another viewer's:
// "3 animations ignored: drawn in the rest pose", "KHR_materials_sheen (2 materials) ignored".
// Counted over the whole file (every scene), from its JSON, which check_json_schema() has
// checked. Each feature is one entry of a list in ignored_features.cpp: when the renderer
// learns a feature, its entry goes.

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace tilelight::gltf_detail {

// Whether the loader implements the extension (reads what it means): using it drops nothing.
bool implemented_extension(std::string_view name);

// The lines, without the file's name, in a fixed order: core features, then extensions by name.
std::vector<std::string> ignored_features(const nlohmann::json& root);

}  // namespace tilelight::gltf_detail
