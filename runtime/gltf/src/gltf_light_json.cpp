#include "gltf_light_json.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tilelight::gltf_detail {
namespace {

using Json = nlohmann::json;

constexpr double kHalfPi = 1.57079632679489661923;
constexpr const char* kLightsPath = "extensions.KHR_lights_punctual.lights";

// A JSON number that a float holds (JSON has no NaN or infinity, but 1e300 is a double).
bool float_sized(double v) { return std::isfinite(v) && std::fabs(v) <= std::numeric_limits<float>::max(); }

// A value as the message quotes it: its JSON, cut short.
std::string shown(const Json& value) {
  std::string text = value.dump();
  return text.size() > 48 ? text.substr(0, 45) + "..." : text;
}

const Json* member(const Json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto found = object.find(key);
  return found == object.end() ? nullptr : &*found;
}

// The number at object[key], or `fallback` when absent; `valid` says which values are allowed
// and `allowed` how the message words them.
double read_number(const Json& object, const char* key, const std::string& path, double fallback, bool (*valid)(double),
                   const char* allowed) {
  const Json* value = member(object, key);
  if (value == nullptr) return fallback;
  const std::string where = path + "." + key;
  if (!value->is_number()) throw Error(fmt::format("{}: expected a number, got {}", where, shown(*value)));
  const double v = value->get<double>();
  if (!float_sized(v)) throw Error(fmt::format("{}: {} is too large for a 32-bit float", where, v));
  if (!valid(v)) throw Error(fmt::format("{}: {} is not {}", where, v, allowed));
  return v;
}

// Three numbers, each allowed by `valid` (a colour, a box's half extent).
glm::vec3 read_triple(const Json& value, const std::string& where, bool (*valid)(double), const char* allowed) {
  if (!value.is_array() || value.size() != 3) {
    throw Error(fmt::format("{}: expected an array of 3 numbers, got {}", where, shown(value)));
  }
  glm::vec3 out{};
  for (int i = 0; i < 3; ++i) {
    const Json& v = value[static_cast<std::size_t>(i)];
    if (!v.is_number() || !float_sized(v.get<double>()) || !valid(v.get<double>())) {
      throw Error(fmt::format("{}[{}]: {} is not {}", where, i, shown(v), allowed));
    }
    out[i] = static_cast<float>(v.get<double>());
  }
  return out;
}

bool non_negative(double v) { return v >= 0.0; }
bool positive(double v) { return v > 0.0; }
bool outer_angle(double v) { return v > 0.0 && v <= kHalfPi; }

const char* kind_name(FileLightKind kind) {
  switch (kind) {
    case FileLightKind::point: return "a point light";
    case FileLightKind::spot: return "a spot light";
    case FileLightKind::directional: return "a directional light";
    case FileLightKind::box: return "a box light";
  }
  return "a light";
}

FileLightKind read_type(const Json& light, const std::string& path) {
  const Json* type = member(light, "type");
  if (type == nullptr) throw Error(path + ".type: missing (required)");
  if (type->is_string()) {
    const std::string name = type->get<std::string>();
    if (name == "point") return FileLightKind::point;
    if (name == "spot") return FileLightKind::spot;
    if (name == "directional") return FileLightKind::directional;
  }
  throw Error(fmt::format("{}.type: {} is not a punctual light type (\"point\", \"spot\" or \"directional\")", path,
                          shown(*type)));
}

void read_spot(const Json& light, const std::string& path, FileLight& out) {
  const Json* spot = member(light, "spot");
  if (spot == nullptr) return;  // glTF's defaults
  const std::string where = path + ".spot";
  if (!spot->is_object()) throw Error(fmt::format("{}: expected an object, got {}", where, shown(*spot)));
  out.outer_cone = read_number(*spot, "outerConeAngle", where, kDefaultOuterConeAngle, &outer_angle,
                               "an angle above 0 and at most pi/2 radians");
  out.inner_cone = read_number(*spot, "innerConeAngle", where, kDefaultInnerConeAngle, &non_negative,
                               "an angle of 0 radians or more");
  // LocalLight needs the inner cone's cosine above the outer one's, in floats.
  if (!(static_cast<float>(std::cos(out.inner_cone)) > static_cast<float>(std::cos(out.outer_cone)))) {
    throw Error(
        fmt::format("{}.innerConeAngle: {} is not below outerConeAngle ({})", where, out.inner_cone, out.outer_cone));
  }
}

// extras.tilelight_box: {"half_extent": [x, y, z], "falloff": f}, both required.
void read_box(const Json& box, const std::string& where, FileLight& out) {
  if (!box.is_object()) throw Error(fmt::format("{}: expected an object, got {}", where, shown(box)));
  const Json* half = member(box, "half_extent");
  if (half == nullptr) throw Error(where + ".half_extent: missing (required)");
  out.box_half_extent = read_triple(*half, where + ".half_extent", &positive, "a positive number");
  if (member(box, "falloff") == nullptr) throw Error(where + ".falloff: missing (required)");
  const double smallest = std::min({out.box_half_extent.x, out.box_half_extent.y, out.box_half_extent.z});
  out.box_falloff = read_number(box, "falloff", where, 0.0, &positive, "a positive number");
  if (out.box_falloff > smallest) {
    throw Error(
        fmt::format("{}.falloff: {} is more than the smallest half extent ({})", where, out.box_falloff, smallest));
  }
  out.kind = FileLightKind::box;
}

// The renderer's own properties of a light, all named "tilelight_*" in its "extras" (any other
// extras are another application's business and left alone).
void read_extras(const Json& light, const std::string& path, FileLight& out) {
  const Json* extras = member(light, "extras");
  if (extras == nullptr || !extras->is_object()) return;
  const std::string where = path + ".extras";
  for (const auto& [key, value] : extras->items()) {
    if (key.rfind("tilelight_", 0) != 0) continue;
    if (key != "tilelight_box" && key != "tilelight_back_color" && key != "tilelight_globe" &&
        key != "tilelight_casts_shadows") {
      throw Error(
          fmt::format("{}.{}: not a tilelight light property (tilelight_box, tilelight_back_color, tilelight_globe, "
                      "tilelight_casts_shadows)",
                      where, key.substr(0, 64)));
    }
  }
  if (const Json* box = member(*extras, "tilelight_box")) {
    if (out.kind != FileLightKind::directional) {
      throw Error(fmt::format("{}.tilelight_box: only a directional light can be a box light (this is {})", where,
                              kind_name(out.kind)));
    }
    read_box(*box, where + ".tilelight_box", out);
  }
  if (const Json* back = member(*extras, "tilelight_back_color")) {
    if (out.kind != FileLightKind::box) {
      throw Error(fmt::format("{}.tilelight_back_color: only box lights have a back colour (this is {})", where,
                              kind_name(out.kind)));
    }
    out.back_color = read_triple(*back, where + ".tilelight_back_color", &non_negative, "a number of 0 or more");
  }
  if (const Json* globe = member(*extras, "tilelight_globe")) {
    const std::string globe_path = where + ".tilelight_globe";
    if (out.kind == FileLightKind::directional) {
      throw Error(globe_path + ": a directional light without tilelight_box becomes the sun, which has no globe map");
    }
    const Json* index = member(*globe, "index");
    if (!globe->is_object() || index == nullptr) {
      throw Error(
          fmt::format("{}: expected an object with an \"index\" (a texture), got {}", globe_path, shown(*globe)));
    }
    if (!index->is_number_unsigned() || index->get<std::uint64_t>() > std::numeric_limits<std::int32_t>::max()) {
      throw Error(fmt::format("{}.index: expected a texture index, got {}", globe_path, shown(*index)));
    }
    out.globe_texture = static_cast<int>(index->get<std::uint64_t>());
  }
  if (const Json* shadows = member(*extras, "tilelight_casts_shadows")) {
    if (!shadows->is_boolean()) {
      throw Error(fmt::format("{}.tilelight_casts_shadows: expected a boolean, got {}", where, shown(*shadows)));
    }
    out.casts_shadows = shadows->get<bool>();
  }
}

FileLight read_light(const Json& light, const std::string& path) {
  if (!light.is_object()) throw Error(fmt::format("{}: expected an object, got {}", path, shown(light)));
  FileLight out;
  out.kind = read_type(light, path);
  if (const Json* color = member(light, "color")) {
    out.color = read_triple(*color, path + ".color", &non_negative, "a number of 0 or more");
  }
  out.intensity = read_number(light, "intensity", path, 1.0, &non_negative, "a number of 0 or more");
  if (member(light, "range") != nullptr) {
    out.range = read_number(light, "range", path, 0.0, &positive, "a positive distance");
  }
  if (out.kind == FileLightKind::spot) read_spot(light, path, out);
  read_extras(light, path, out);
  return out;
}

std::vector<FileLight> read_lights(const Json& root) {
  const Json* extensions = member(root, "extensions");
  const Json* punctual = extensions != nullptr ? member(*extensions, "KHR_lights_punctual") : nullptr;
  if (punctual == nullptr) return {};
  const Json* lights = member(*punctual, "lights");
  if (lights == nullptr) return {};
  if (!lights->is_array()) throw Error(fmt::format("{}: expected an array, got {}", kLightsPath, shown(*lights)));
  std::vector<FileLight> out;
  for (std::size_t i = 0; i < lights->size(); ++i) {
    out.push_back(read_light((*lights)[i], fmt::format("{}[{}]", kLightsPath, i)));
  }
  return out;
}

// Per node, the light its extensions.KHR_lights_punctual.light names, or -1.
std::vector<int> read_node_lights(const Json& root, std::size_t light_count) {
  const Json* nodes = member(root, "nodes");
  if (nodes == nullptr) return {};
  std::vector<int> light_of_node(nodes->size(), -1);
  for (std::size_t n = 0; n < nodes->size(); ++n) {
    const Json* extensions = member((*nodes)[n], "extensions");
    const Json* punctual = extensions != nullptr ? member(*extensions, "KHR_lights_punctual") : nullptr;
    if (punctual == nullptr) continue;
    const std::string where = fmt::format("nodes[{}].extensions.KHR_lights_punctual.light", n);
    const Json* light = member(*punctual, "light");
    if (light == nullptr) throw Error(where + ": missing (required)");
    if (!light->is_number_unsigned()) {
      throw Error(fmt::format("{}: expected a non-negative integer, got {}", where, shown(*light)));
    }
    if (light->get<std::uint64_t>() >= light_count) {
      throw Error(fmt::format("{}: light {} does not exist (the file has {})", where, light->get<std::uint64_t>(),
                              light_count));
    }
    light_of_node[n] = static_cast<int>(light->get<std::uint64_t>());
  }
  return light_of_node;
}

}  // namespace

FileLights read_file_lights(const nlohmann::json& root) {
  FileLights out;
  out.lights = read_lights(root);
  out.light_of_node = read_node_lights(root, out.lights.size());
  return out;
}

}  // namespace tilelight::gltf_detail
