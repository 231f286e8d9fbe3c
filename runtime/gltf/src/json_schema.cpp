#include "json_schema.h"

#include "ignored_features.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {
namespace {

using Json = nlohmann::json;

// int32: a non-negative integer that tinygltf reads into an int (the sparse properties).
enum class Kind { uint, int32, number, string, boolean, object, array, any };

struct ObjectSchema;

// What one property must be. For arrays: `element` and, when non-zero, `length`; for objects
// and arrays of objects: `schema` (null: any object).
struct Expect {
  Kind kind = Kind::any;
  Kind element = Kind::any;
  std::size_t length = 0;
  const ObjectSchema* schema = nullptr;
  bool required = false;
};

struct Property {
  const char* name;
  Expect expect;
};

struct ObjectSchema {
  std::vector<Property> properties;
  const Expect* values = nullptr;  // a map (mesh attributes): every value must be this
};

Expect uint_(bool required = false) { return {Kind::uint, Kind::any, 0, nullptr, required}; }
Expect int32(bool required = false) { return {Kind::int32, Kind::any, 0, nullptr, required}; }
Expect number() { return {Kind::number}; }
Expect string_(bool required = false) { return {Kind::string, Kind::any, 0, nullptr, required}; }
Expect boolean() { return {Kind::boolean}; }
Expect numbers(std::size_t length = 0) { return {Kind::array, Kind::number, length}; }
Expect uints() { return {Kind::array, Kind::uint}; }
Expect strings() { return {Kind::array, Kind::string}; }
Expect object(const ObjectSchema* schema = nullptr, bool required = false) {
  return {Kind::object, Kind::any, 0, schema, required};
}
Expect objects(const ObjectSchema* schema = nullptr, bool required = false) {
  return {Kind::array, Kind::object, 0, schema, required};
}

const Expect kAttributeValue = uint_();
const ObjectSchema kAny{};
const ObjectSchema kAttributes{{}, &kAttributeValue};
const ObjectSchema kTextureInfo{{{"index", uint_(true)}, {"texCoord", uint_()}}};
const ObjectSchema kNormalTextureInfo{{{"index", uint_(true)}, {"texCoord", uint_()}, {"scale", number()}}};
const ObjectSchema kOcclusionTextureInfo{{{"index", uint_(true)}, {"texCoord", uint_()}, {"strength", number()}}};
const ObjectSchema kPbr{{{"baseColorFactor", numbers(4)},
                         {"baseColorTexture", object(&kTextureInfo)},
                         {"metallicFactor", number()},
                         {"roughnessFactor", number()},
                         {"metallicRoughnessTexture", object(&kTextureInfo)}}};
const ObjectSchema kMaterial{{{"pbrMetallicRoughness", object(&kPbr)},
                              {"normalTexture", object(&kNormalTextureInfo)},
                              {"occlusionTexture", object(&kOcclusionTextureInfo)},
                              {"emissiveTexture", object(&kTextureInfo)},
                              {"emissiveFactor", numbers(3)},
                              {"alphaMode", string_()},
                              {"alphaCutoff", number()},
                              {"doubleSided", boolean()}}};
const ObjectSchema kPrimitive{{{"attributes", object(&kAttributes, true)},
                               {"indices", uint_()},
                               {"material", uint_()},
                               {"mode", uint_()},
                               {"targets", objects(&kAttributes)}}};
const ObjectSchema kMesh{{{"primitives", objects(&kPrimitive, true)}, {"weights", numbers()}}};
const ObjectSchema kNode{{{"camera", uint_()},
                          {"children", uints()},
                          {"skin", uint_()},
                          {"matrix", numbers(16)},
                          {"mesh", uint_()},
                          {"rotation", numbers(4)},
                          {"scale", numbers(3)},
                          {"translation", numbers(3)},
                          {"weights", numbers()}}};
const ObjectSchema kScene{{{"nodes", uints()}}};
const ObjectSchema kSparseIndices{
    {{"bufferView", int32(true)}, {"byteOffset", int32()}, {"componentType", int32(true)}}};
const ObjectSchema kSparseValues{{{"bufferView", int32(true)}, {"byteOffset", int32()}}};
const ObjectSchema kSparse{
    {{"count", int32(true)}, {"indices", object(&kSparseIndices, true)}, {"values", object(&kSparseValues, true)}}};
const ObjectSchema kAccessor{{{"bufferView", uint_()},
                              {"byteOffset", uint_()},
                              {"componentType", uint_(true)},
                              {"normalized", boolean()},
                              {"count", uint_(true)},
                              {"type", string_(true)},
                              {"max", numbers()},
                              {"min", numbers()},
                              {"sparse", object(&kSparse)}}};
const ObjectSchema kBufferView{{{"buffer", uint_(true)},
                                {"byteOffset", uint_()},
                                {"byteLength", uint_(true)},
                                {"byteStride", uint_()},
                                {"target", uint_()}}};
const ObjectSchema kBuffer{{{"uri", string_()}, {"byteLength", uint_(true)}}};
const ObjectSchema kImage{{{"uri", string_()}, {"mimeType", string_()}, {"bufferView", uint_()}}};
const ObjectSchema kTexture{{{"sampler", uint_()}, {"source", uint_()}}};
const ObjectSchema kSampler{{{"magFilter", uint_()}, {"minFilter", uint_()}, {"wrapS", uint_()}, {"wrapT", uint_()}}};
const ObjectSchema kAsset{
    {{"version", string_(true)}, {"minVersion", string_()}, {"generator", string_()}, {"copyright", string_()}}};
const ObjectSchema kRoot{{{"asset", object(&kAsset, true)},
                          {"scene", uint_()},
                          {"scenes", objects(&kScene)},
                          {"nodes", objects(&kNode)},
                          {"meshes", objects(&kMesh)},
                          {"accessors", objects(&kAccessor)},
                          {"bufferViews", objects(&kBufferView)},
                          {"buffers", objects(&kBuffer)},
                          {"materials", objects(&kMaterial)},
                          {"images", objects(&kImage)},
                          {"textures", objects(&kTexture)},
                          {"samplers", objects(&kSampler)},
                          {"cameras", objects(&kAny)},
                          {"skins", objects(&kAny)},
                          {"animations", objects(&kAny)},
                          {"extensionsUsed", strings()},
                          {"extensionsRequired", strings()}}};

const char* kind_name(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "a string";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::number_integer: return value.get<std::int64_t>() < 0 ? "a negative integer" : "an integer";
    case Json::value_t::number_unsigned: return "an integer";
    case Json::value_t::number_float: return "a fractional number";
    default: return "an unexpected value";
  }
}

const char* expected_name(Kind kind) {
  switch (kind) {
    case Kind::uint: return "a non-negative integer";
    case Kind::int32: return "a non-negative integer below 2^31";
    case Kind::number: return "a number";
    case Kind::string: return "a string";
    case Kind::boolean: return "a boolean";
    case Kind::object: return "an object";
    case Kind::array: return "an array";
    case Kind::any: return "a value";
  }
  return "a value";
}

bool matches(const Json& value, Kind kind) {
  switch (kind) {
    case Kind::uint: return value.is_number_unsigned() || (value.is_number_integer() && value.get<std::int64_t>() >= 0);
    case Kind::int32:
      return matches(value, Kind::uint) &&
             value.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max());
    case Kind::number: return value.is_number();
    case Kind::string: return value.is_string();
    case Kind::boolean: return value.is_boolean();
    case Kind::object: return value.is_object();
    case Kind::array: return value.is_array();
    case Kind::any: return true;
  }
  return false;
}

void require_kind(const Json& value, Kind kind, const std::string& path) {
  if (!matches(value, kind))
    throw Error(fmt::format("{}: expected {}, got {}", path, expected_name(kind), kind_name(value)));
}

void check_object(const Json& value, const ObjectSchema& schema, const std::string& path);

void check_value(const Json& value, const Expect& expect, const std::string& path) {
  require_kind(value, expect.kind, path);
  if (expect.kind == Kind::object) {
    check_object(value, expect.schema != nullptr ? *expect.schema : kAny, path);
  } else if (expect.kind == Kind::array) {
    if (expect.length != 0 && value.size() != expect.length) {
      throw Error(fmt::format("{}: expected {} elements, got {}", path, expect.length, value.size()));
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
      const std::string element_path = fmt::format("{}[{}]", path, i);
      require_kind(value[i], expect.element, element_path);
      if (expect.element == Kind::object)
        check_object(value[i], expect.schema != nullptr ? *expect.schema : kAny, element_path);
    }
  }
}

// Every glTF object may have a "name" (a string) and "extensions" (an object of objects).
void check_object(const Json& value, const ObjectSchema& schema, const std::string& path) {
  if (schema.values != nullptr) {
    for (const auto& [key, item] : value.items()) check_value(item, *schema.values, path + "." + key);
    return;
  }
  if (const auto name = value.find("name"); name != value.end()) require_kind(*name, Kind::string, path + ".name");
  if (const auto extensions = value.find("extensions"); extensions != value.end()) {
    require_kind(*extensions, Kind::object, path + ".extensions");
    for (const auto& [key, item] : extensions->items()) require_kind(item, Kind::object, path + ".extensions." + key);
  }
  for (const Property& p : schema.properties) {
    const std::string property_path = path.empty() ? p.name : path + "." + p.name;
    const auto found = value.find(p.name);
    if (found == value.end()) {
      if (p.expect.required) throw Error(fmt::format("{}: missing (required)", property_path));
      continue;
    }
    check_value(*found, p.expect, property_path);
  }
}

// Extensions that only change shading this renderer does not do: a file that requires them
// still renders meaningfully without them (each is reported as ignored: ignored_features.h).
// Any other required extension that is not implemented (mesh compression) changes what the
// buffers mean, so the file is refused.
bool ignorable_extension(std::string_view name) {
  return name.rfind("KHR_materials_", 0) == 0 || name == "KHR_texture_transform" || name == "KHR_lights_punctual";
}

// glTF 1.0 (and its drafts) says so in asset.version, as a string or a number, or, without
// one, shows it by keeping its objects in dictionaries where 2.0 has arrays.
bool is_gltf1(const Json& root) {
  const auto asset = root.find("asset");
  if (asset != root.end() && asset->is_object()) {
    const auto version = asset->find("version");
    if (version != asset->end() && version->is_number()) return version->get<double>() < 2.0;
    if (version != asset->end() && version->is_string()) {
      const std::string text = version->get<std::string>();
      return text.rfind("1.", 0) == 0 || text.rfind("0.", 0) == 0 || text == "1";
    }
  }
  for (const char* collection : {"meshes", "accessors", "bufferViews", "buffers", "nodes", "scenes", "materials"}) {
    const auto found = root.find(collection);
    if (found != root.end() && found->is_object()) return true;
  }
  return false;
}

// A base64 data URI's payload length, from its text alone; nullopt when it is not one.
std::optional<std::uint64_t> data_uri_bytes(const std::string& uri) {
  if (uri.rfind("data:", 0) != 0) return std::nullopt;
  const std::size_t comma = uri.find(";base64,");
  if (comma == std::string::npos) return std::nullopt;
  std::uint64_t characters = uri.size() - (comma + 8);
  std::uint64_t padding = 0;
  while (padding < 2 && characters > padding && uri[uri.size() - 1 - padding] == '=') ++padding;
  return characters / 4 * 3 + (characters % 4 == 0 ? 0 : characters % 4 - 1) - padding;
}

// Embedded buffers hold what "byteLength" says (tinygltf would only say it failed to decode).
void check_data_uris(const Json& root) {
  const auto buffers = root.find("buffers");
  if (buffers == root.end()) return;
  for (std::size_t i = 0; i < buffers->size(); ++i) {
    const Json& buffer = (*buffers)[i];
    const auto uri = buffer.find("uri");
    if (uri == buffer.end()) continue;
    const std::optional<std::uint64_t> bytes = data_uri_bytes(uri->get<std::string>());
    const auto length = buffer["byteLength"].get<std::uint64_t>();
    if (bytes && *bytes != length) {
      throw Error(fmt::format("buffers[{}]: its data URI holds {} bytes, byteLength says {}", i, *bytes, length));
    }
  }
}

// The deepest nesting of arrays and objects, counted on the text without parsing it: tinygltf
// turns "extras" and extension values into its own Value type recursively, so a deeply nested
// one would overflow the stack before any check could see it.
std::size_t nesting_depth(std::string_view text) {
  std::size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

}  // namespace

Json check_json_schema(std::string_view json_text) {
  // nlohmann::json (and so tinygltf) stops reading at a NUL byte and would ignore the rest.
  if (const std::size_t nul = json_text.find('\0'); nul != std::string_view::npos) {
    throw Error(fmt::format("not valid JSON: a NUL byte at offset {} (everything after it would be ignored)", nul));
  }
  if (const std::size_t depth = nesting_depth(json_text); depth > kMaxJsonDepth) {
    throw Error(fmt::format("JSON nested {} levels deep, more than this loader reads ({})", depth, kMaxJsonDepth));
  }
  Json root;
  try {
    root = Json::parse(json_text.begin(), json_text.end());
  } catch (const Json::exception& e) {
    // A syntax error (parse_error) or a number too large for a double (out_of_range 406); e.what()
    // is "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
    std::string what = e.what();
    if (const std::size_t bracket = what.find("] "); bracket != std::string::npos) what.erase(0, bracket + 2);
    throw Error("not valid JSON: " + what);
  }
  if (!root.is_object()) throw Error(fmt::format("the top level is {}, not a glTF object", kind_name(root)));
  if (is_gltf1(root)) throw Error(kGltf1Refused);
  check_object(root, kRoot, "");
  check_data_uris(root);
  const std::string version = root["asset"]["version"].get<std::string>();
  if (version.rfind("2.", 0) != 0) throw Error("asset.version is \"" + version + "\"; only glTF 2.x is supported");
  if (const auto required = root.find("extensionsRequired"); required != root.end()) {
    for (const Json& name : *required) {
      if (!ignorable_extension(name.get<std::string>()) && !implemented_extension(name.get<std::string>())) {
        throw Error("requires the extension " + name.get<std::string>() + ", which this loader does not support");
      }
    }
  }
  return root;
}

}  // namespace tilelight::gltf_detail
