#include "ignored_features.h"

#include <fmt/format.h>

#include <functional>
#include <map>
#include <set>
#include <string_view>

namespace tilelight::gltf_detail {
namespace {

using Json = nlohmann::json;

// An extension's name as the file spells it, made one short line: it is any JSON string.
std::string printable(const std::string& name) {
  constexpr std::size_t kLongest = 64;
  std::string shown = name.size() > kLongest ? name.substr(0, kLongest) + "..." : name;
  for (char& c : shown) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  }
  return shown;
}

// "1 material", "2 materials", "1 mesh".
std::string counted(std::size_t n, std::string_view plural) {
  if (n != 1) return fmt::format("{} {}", n, plural);
  const std::size_t cut = plural == "meshes" ? 2 : 1;
  return fmt::format("1 {}", plural.substr(0, plural.size() - cut));
}

const Json& array_of(const Json& object, const char* key) {
  static const Json empty = Json::array();
  const auto found = object.find(key);
  return found != object.end() && found->is_array() ? *found : empty;
}

// Calls `visit` with every primitive of every mesh.
void for_each_primitive(const Json& root, const std::function<void(const Json&)>& visit) {
  for (const Json& mesh : array_of(root, "meshes")) {
    for (const Json& primitive : array_of(mesh, "primitives")) visit(primitive);
  }
}

std::size_t count_primitives(const Json& root, const std::function<bool(const Json&)>& test) {
  std::size_t n = 0;
  for_each_primitive(root, [&](const Json& primitive) { n += test(primitive) ? 1 : 0; });
  return n;
}

std::size_t count_materials(const Json& root, const std::function<bool(const Json&)>& test) {
  std::size_t n = 0;
  for (const Json& material : array_of(root, "materials")) n += test(material) ? 1 : 0;
  return n;
}

bool has(const Json& object, const char* key) { return object.is_object() && object.contains(key); }

// Cameras that are not perspective, or that no node references.
std::size_t unusable_cameras(const Json& root) {
  std::set<std::uint64_t> placed;
  for (const Json& node : array_of(root, "nodes")) {
    if (has(node, "camera") && node["camera"].is_number_unsigned()) placed.insert(node["camera"].get<std::uint64_t>());
  }
  const Json& cameras = array_of(root, "cameras");
  std::size_t n = 0;
  for (std::uint64_t i = 0; i < cameras.size(); ++i) {
    const bool perspective = has(cameras[i], "type") && cameras[i]["type"] == "perspective";
    n += perspective && placed.count(i) != 0 ? 0 : 1;
  }
  return n;
}

// The core features, each: how many of what the file has, and the line when it has any.
void core_features(const Json& root, std::vector<std::string>& lines) {
  const auto add = [&](std::size_t n, const std::string& line) {
    if (n > 0) lines.push_back(line);
  };
  const std::size_t animations = array_of(root, "animations").size();
  add(animations, fmt::format("{} ignored: drawn in the rest pose", counted(animations, "animations")));
  const std::size_t skins = array_of(root, "skins").size();
  add(skins, fmt::format("{} ignored: meshes are drawn as stored, unskinned", counted(skins, "skins")));
  // A perspective camera that a node places is --camera gltf:N; the others stay in the list,
  // marked not usable (gltf_cameras.cpp says why, in more cases than these two).
  const std::size_t unusable = unusable_cameras(root);
  add(unusable, fmt::format("{} cannot be chosen: orthographic, or placed by no node (--list-cameras says why)",
                            counted(unusable, "cameras")));
  const std::size_t morphed = count_primitives(root, [](const Json& p) { return has(p, "targets"); });
  add(morphed, fmt::format("morph targets ({}) ignored: drawn in the base shape", counted(morphed, "primitives")));
  const std::size_t no_surface =
      count_primitives(root, [](const Json& p) { return has(p, "mode") && p["mode"].get<std::uint64_t>() < 4; });
  add(no_surface,
      fmt::format("points and lines ({}) ignored: they have no surface", counted(no_surface, "primitives")));
  const std::size_t coloured = count_primitives(root, [](const Json& p) {
    for (const auto& [name, accessor] : p["attributes"].items()) {
      if (name.rfind("COLOR_", 0) == 0) return true;
    }
    return false;
  });
  add(coloured, fmt::format("vertex colours ({}) ignored", counted(coloured, "primitives")));
}

void material_features(const Json& root, std::vector<std::string>& lines) {
  const auto add = [&](const std::string& what, const std::string& why, const std::function<bool(const Json&)>& test) {
    const std::size_t n = count_materials(root, test);
    if (n > 0) lines.push_back(fmt::format("{} ({}) ignored{}", what, counted(n, "materials"), why));
  };
  // alphaMode MASK and BLEND are both drawn (BLEND by the forward pass): nothing to report.
  for (const char* texture : {"normalTexture", "occlusionTexture", "emissiveTexture"}) {
    add(texture, "", [&](const Json& m) { return has(m, texture); });
  }
  add("metallicRoughnessTexture", "", [](const Json& m) {
    return has(m, "pbrMetallicRoughness") && has(m["pbrMetallicRoughness"], "metallicRoughnessTexture");
  });
  add("emissiveFactor", "", [](const Json& m) {
    if (!has(m, "emissiveFactor")) return false;
    for (const Json& v : m["emissiveFactor"]) {
      if (v.get<double>() != 0.0) return true;
    }
    return false;
  });
}

// Where each extension is used: per top-level collection ("materials"), the elements whose
// JSON has it somewhere inside (a material's texture info counts for the material).
using ExtensionUses = std::map<std::string, std::map<std::string, std::set<std::size_t>>>;

void find_extensions(const Json& value, const std::string& collection, std::size_t element, ExtensionUses& uses) {
  if (value.is_object()) {
    if (const auto extensions = value.find("extensions"); extensions != value.end() && extensions->is_object()) {
      for (const auto& [name, ignored] : extensions->items()) {
        auto& where = uses[name];
        if (!collection.empty()) where[collection].insert(element);
      }
    }
    for (const auto& [key, item] : value.items()) {
      if (key != "extensions" && key != "extras") find_extensions(item, collection, element, uses);
    }
  } else if (value.is_array()) {
    for (const Json& item : value) find_extensions(item, collection, element, uses);
  }
}

ExtensionUses extension_uses(const Json& root) {
  ExtensionUses uses;
  for (const Json& name : array_of(root, "extensionsUsed")) uses[name.get<std::string>()];
  if (const auto extensions = root.find("extensions"); extensions != root.end() && extensions->is_object()) {
    for (const auto& [name, ignored] : extensions->items()) uses[name];
  }
  for (const auto& [key, collection] : root.items()) {
    if (!collection.is_array() || key.rfind("extensions", 0) == 0) continue;
    for (std::size_t i = 0; i < collection.size(); ++i) find_extensions(collection[i], key, i, uses);
  }
  return uses;
}

void extension_features(const Json& root, std::vector<std::string>& lines) {
  for (const auto& [name, where] : extension_uses(root)) {
    if (implemented_extension(name)) continue;
    std::string counts;
    for (const auto& [collection, elements] : where) counts += counted(elements.size(), collection) + ", ";
    if (counts.empty()) {
      lines.push_back(printable(name) + " ignored");
    } else {
      counts.resize(counts.size() - 2);
      lines.push_back(fmt::format("{} ({}) ignored", printable(name), counts));
    }
  }
}

}  // namespace

bool implemented_extension(std::string_view name) {
  return name == "KHR_mesh_quantization" || name == "EXT_meshopt_compression" || name == "KHR_draco_mesh_compression" ||
         name == "KHR_texture_transform" || name == "KHR_materials_pbrSpecularGlossiness" ||
         name == "KHR_lights_punctual";  // gltf_lights.h, which also says what is not drawn yet
}

std::vector<std::string> ignored_features(const nlohmann::json& root) {
  std::vector<std::string> lines;
  core_features(root, lines);
  material_features(root, lines);
  extension_features(root, lines);
  return lines;
}

}  // namespace tilelight::gltf_detail
