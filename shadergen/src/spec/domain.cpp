#include "shadergen/domain.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "spec/cpp_names.h"
#include "spec/defines.h"
#include "spec/json.h"
#include "spec/spec_keys.h"
#include "spec/stages.h"

namespace shadergen {

std::vector<std::string> DomainSpec::raw_feature_names() const {
  std::vector<std::string> names;
  for (const RawFeature& feature : raw_features) names.push_back(feature.name);
  return names;
}

std::uint32_t DomainSpec::raw_bits() const {
  std::uint32_t bits = 0;
  for (const RawFeature& feature : raw_features) bits += feature.width;
  return bits;
}

std::vector<ExpressionSymbol> DomainSpec::raw_symbols() const {
  std::vector<ExpressionSymbol> symbols;
  for (const RawFeature& f : raw_features) symbols.push_back({f.name, f.bit, f.width, f.values});
  return symbols;
}

std::string_view feature_kind_name(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::variant: return "variant";
    case FeatureKind::specialization: return "specialization";
    case FeatureKind::branch: return "branch";
  }
  return "variant";
}

std::vector<const RawFeature*> DomainSpec::features_in_spec_order() const {
  std::vector<const RawFeature*> out;
  for (const RawFeature& f : raw_features) out.push_back(&f);
  std::sort(out.begin(), out.end(),
            [](const RawFeature* a, const RawFeature* b) { return a->spec_order < b->spec_order; });
  return out;
}

namespace {
std::vector<const RawFeature*> features_of_kind(const DomainSpec& spec, FeatureKind kind) {
  std::vector<const RawFeature*> out = spec.features_in_spec_order();
  std::erase_if(out, [&](const RawFeature* f) { return f->kind != kind; });
  return out;
}
}  // namespace

std::vector<const RawFeature*> DomainSpec::branch_features() const {
  return features_of_kind(*this, FeatureKind::branch);
}

std::vector<const RawFeature*> DomainSpec::specialization_features() const {
  return features_of_kind(*this, FeatureKind::specialization);
}

std::uint32_t DomainSpec::variant_mask() const {
  std::uint32_t mask = 0;
  for (const RawFeature& f : raw_features)
    if (f.is_variant()) mask |= f.mask();
  return mask;
}

std::vector<std::string> DomainSpec::optimised_bit_names() const {
  std::vector<std::string> names;
  for (const OptimisedBit& bit : optimised_bits) names.push_back(bit.name);
  return names;
}

namespace {

using json::Type;
using json::Value;

// Walks the JSON tree, checking shapes and collecting every problem with its line.
class SpecReader {
 public:
  explicit SpecReader(std::string file) : file_(std::move(file)) {}

  Diagnostics& errors() { return errors_; }

  void error(const Value& at, std::string_view where, std::string message) {
    if (errors_.size() > kMaxSpecErrors) return;
    if (errors_.size() == kMaxSpecErrors) {
      errors_.push_back(
          make_error(file_, 0, "more than " + std::to_string(kMaxSpecErrors) + " problems; the rest are not reported"));
      return;
    }
    errors_.push_back(
        Diagnostic{Severity::error, file_, at.line, at.column, std::string(where) + ": " + std::move(message)});
  }

  // The member `key` of `object` with type `type`; records an error and returns nullptr if
  // a required member is missing or any member has the wrong type.
  const Value* member(const Value& object, std::string_view where, std::string_view key, Type type,
                      bool required = true) {
    const Value* found = object.find(key);
    if (!found) {
      if (required) error(object, where, "missing \"" + std::string(key) + "\"");
      return nullptr;
    }
    if (found->type != type) {
      error(*found, join(where, key),
            std::string("expected ") + json::type_name(type) + ", found " + json::type_name(found->type));
      return nullptr;
    }
    return found;
  }

  std::string string_member(const Value& object, std::string_view where, std::string_view key, bool required = true) {
    const Value* found = member(object, where, key, Type::string, required);
    return found ? found->string : std::string();
  }

  // Rejects keys the format does not know: a misspelt key would otherwise be ignored silently.
  void only_keys(const Value& object, std::string_view where, std::span<const std::string_view> known) {
    for (const json::Member& m : object.object) {
      if (std::find(known.begin(), known.end(), m.first) != known.end()) continue;
      std::string list;
      for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      error(m.second, where, "unknown key \"" + m.first + "\" (expected one of: " + list + ")");
    }
  }

  std::optional<std::uint32_t> bit_member(const Value& object, std::string_view where, std::uint32_t limit) {
    const Value* found = member(object, where, "bit", Type::number);
    if (!found) return std::nullopt;
    double v = found->number;
    // The range test comes first: converting a double outside an integer type's range (a
    // "bit" of 1e300; Clang's UBSan flagged it in the fuzz corpus) is undefined behaviour.
    if (!(v >= 0 && v < limit) || v != std::trunc(v)) {
      error(*found, join(where, "bit"),
            "bit must be an integer from 0 to " + std::to_string(limit - 1) + ", found " + json_number(v));
      return std::nullopt;
    }
    return static_cast<std::uint32_t>(v);
  }

  std::optional<Rule> rule_member(const Value& object, std::string_view where, std::string_view key,
                                  std::span<const ExpressionSymbol> symbols, std::string_view symbol_kind) {
    const Value* found = member(object, where, key, Type::string);
    if (!found) return std::nullopt;
    auto parsed = parse_expression(found->string, symbols);
    if (!parsed) {
      Diagnostic d = parsed.errors().front();
      // The value's column points at its opening quote; expression columns are 1-based.
      error(*found, join(where, key),
            d.message + " in \"" + quoted_rule(found->string) + "\" at column " + std::to_string(d.column) +
                " (rules here name " + std::string(symbol_kind) + ")");
      return std::nullopt;
    }
    return Rule{std::move(parsed).value(), found->string, found->line};
  }

  // A rule as quoted in a message; one over the length limit is shortened, not repeated whole.
  static std::string quoted_rule(const std::string& text) {
    constexpr std::size_t kShown = 40;
    return text.size() <= kMaxExpressionLength ? text : text.substr(0, kShown) + "...";
  }

  // Records an error and returns false when `list` has more than `limit` entries.
  bool within_limit(const Value& list, std::string_view where, std::size_t limit, std::string_view what) {
    if (list.array.size() <= limit) return true;
    error(list, where,
          "more than " + std::to_string(limit) + " " + std::string(what) + " (found " +
              std::to_string(list.array.size()) + ")");
    return false;
  }

  static std::string join(std::string_view where, std::string_view key) {
    return std::string(where) + "." + std::string(key);
  }
  static std::string index(std::string_view where, std::size_t i) {
    return std::string(where) + "[" + std::to_string(i) + "]";
  }
  static std::string json_number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }

 private:
  std::string file_;
  Diagnostics errors_;
};

class DomainBuilder {
 public:
  DomainBuilder(const std::filesystem::path& spec_path, SpecReader& reader)
      : reader_(reader), base_(spec_path.parent_path()) {
    spec_.spec_path = spec_path;
  }

  DomainSpec build(const Value& root) {
    if (root.type != Type::object) {
      reader_.error(root, "spec", "the spec must be a JSON object");
      return std::move(spec_);
    }
    reader_.only_keys(root, "spec", spec_keys::kTop);
    read_header(root);
    read_permuted_shaders(root);
    read_include_dirs(root);
    read_target_env(root);
    read_layout(root);
    if (const Value* strip = reader_.member(root, "spec", "strip_debug", Type::boolean, false))
      spec_.strip_debug = strip->boolean;
    if (const Value* defines = reader_.member(root, "spec", "defines", Type::object, false))
      spec_.defines = read_define_map(*defines, "defines");
    read_companions(root);
    if (const Value* style = root.find("define_style")) read_define_style(*style, "define_style", default_style_);
    if (const Value* raw = reader_.member(root, "spec", "raw", Type::object)) read_raw(*raw);
    read_kinds(root);
    check_fixed_defines(root);
    spec_.collapsed = root.find("optimised") != nullptr;
    if (const Value* optimised = reader_.member(root, "spec", "optimised", Type::object, false))
      read_optimised(*optimised);
    read_compile_set(root);
    read_variants_file_key(root);
    return std::move(spec_);
  }

 private:
  void read_header(const Value& root) {
    if (const Value* format = reader_.member(root, "spec", "format", Type::number, false)) {
      if (format->number != 1)
        reader_.error(*format, "spec.format", "unsupported format version (this shadergen reads 1)");
    }
    spec_.name = reader_.string_member(root, "spec", "name");
    if (root.find("name") && !spec_.name.empty() && !is_identifier(spec_.name))
      reader_.error(*root.find("name"), "spec.name",
                    "\"" + spec_.name + "\" is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)");
    spec_.description = reader_.string_member(root, "spec", "description", false);
  }

  // `key` names the file in later messages (a companion by its name); default: where.path.
  ShaderFile read_shader_file(const Value& object, const std::string& where, const std::string& key = {}) {
    ShaderFile file;
    std::string path = reader_.string_member(object, where, "path");
    if (const Value* value = object.find("path")) located(file, key.empty() ? where + ".path" : key, *value);
    if (!path.empty())
      file.path = (base_ / path).lexically_normal();
    else if (object.find("path") && object.find("path")->type == Type::string)
      reader_.error(*object.find("path"), where + ".path", "the path is empty");
    read_stage(object, where, path, file);
    return file;
  }

  // "uber_shader", "uber_shaders" or "program": { "vertex": path, "fragment": path } (one of the three).
  void read_permuted_shaders(const Value& root) {
    const Value* program = root.find("program");
    if (const Value* several = root.find("uber_shaders")) {
      if (program || root.find("uber_shader"))
        reader_.error(
            *several, "uber_shaders",
            std::string("a spec has \"uber_shaders\" or \"") + (program ? "program" : "uber_shader") + "\", not both");
      else
        read_uber_shaders(root);
      return;
    }
    if (!program) {
      if (const Value* uber = reader_.member(root, "spec", "uber_shader", Type::object)) {
        reader_.only_keys(*uber, "uber_shader", spec_keys::kShaderFile);
        spec_.uber = read_shader_file(*uber, "uber_shader");
      }
      return;
    }
    if (root.find("uber_shader")) {
      reader_.error(*program, "program", "a spec has \"uber_shader\" or \"program\", not both");
      return;
    }
    if (!(program = reader_.member(root, "spec", "program", Type::object))) return;
    reader_.only_keys(*program, "program", spec_keys::kProgram);
    std::string vertex = reader_.string_member(*program, "program", "vertex");
    std::string fragment = reader_.string_member(*program, "program", "fragment");
    if (vertex.empty() || fragment.empty()) return;
    spec_.program_vertex = ShaderFile{(base_ / vertex).lexically_normal(), Stage::vertex, {}, 0, 0};
    spec_.uber = ShaderFile{(base_ / fragment).lexically_normal(), Stage::fragment, {}, 0, 0};
    located(*spec_.program_vertex, "program.vertex", *program->find("vertex"));
    located(spec_.uber, "program.fragment", *program->find("fragment"));
  }

  // "uber_shaders": {"raster": {"path", "stage"}, ...}: one domain, several uber-shaders.
  void read_uber_shaders(const Value& root) {
    const Value* entries = reader_.member(root, "spec", "uber_shaders", Type::object);
    if (!entries) return;
    if (entries->object.empty() || entries->object.size() > kMaxUberShaders) {
      reader_.error(*entries, "uber_shaders",
                    "expected 1 to " + std::to_string(kMaxUberShaders) + " uber-shaders, each {\"path\", \"stage\"}");
      return;
    }
    for (const auto& [name, value] : entries->object) {
      const std::string where = "uber_shaders." + name;
      std::string problem = is_identifier(name) ? feature_name_problem(name) : "\"" + name + "\" is not an identifier";
      if (!problem.empty()) {
        reader_.error(value, where, problem + " (an entry's name is the namespace of its registry)");
        continue;
      }
      if (value.type != Type::object) {
        reader_.error(value, where, "expected an object {\"path\", \"stage\"}");
        continue;
      }
      reader_.only_keys(value, where, spec_keys::kShaderFile);
      spec_.uber_shaders.push_back({name, read_shader_file(value, where)});
    }
    if (!spec_.uber_shaders.empty()) spec_.uber = spec_.uber_shaders.front().file;
  }

  static void located(ShaderFile& file, std::string key, const Value& value) {
    file.spec_key = std::move(key);
    file.line = value.line;
    file.column = value.column;
  }

  // "stage", or when it is absent the stage the path's extension names.
  void read_stage(const Value& object, const std::string& where, const std::string& path, ShaderFile& file) {
    if (!object.find("stage")) {
      if (auto inferred = stage_for_extension(path))
        file.stage = *inferred;
      else if (!path.empty())
        reader_.error(object, where,
                      "missing \"stage\", and the extension of \"" + path + "\" names none (one of " +
                          stage_extensions() + " does)");
      return;
    }
    std::string stage = reader_.string_member(object, where, "stage");
    if (auto parsed = parse_stage(stage)) {
      file.stage = *parsed;
    } else if (object.find("stage")->type == Type::string) {
      reader_.error(*object.find("stage"), where + ".stage",
                    "unknown stage \"" + stage + "\" (expected one of " + stage_names() + ", or " + stage_extensions() +
                        " without the dot)");
    }
  }

  void read_target_env(const Value& root) {
    const Value* env = reader_.member(root, "spec", "target_env", Type::string, false);
    if (env && !parse_target_env(env->string, spec_.target_env))
      reader_.error(
          *env, "target_env",
          "unknown target environment \"" + env->string + "\" (expected " + std::string(target_env_choices()) + ")");
  }

  void read_compile_set(const Value& root) {
    const Value* compile = reader_.member(root, "spec", "compile", Type::string, false);
    if (!compile) return;
    if (compile->string == "optimised") {
      spec_.compile = CompileSet::optimised;
      if (!spec_.collapsed)
        reader_.error(*compile, "compile",
                      "\"optimised\" needs an \"optimised\" section: without a collapse the raw permutations are "
                      "the only ones");
    } else if (compile->string != "all") {
      reader_.error(*compile, "compile", "unknown value \"" + compile->string + "\" (expected all or optimised)");
    }
  }

  // Only the path: the file is read once the command line had its say (build --variants).
  void read_variants_file_key(const Value& root) {
    const Value* file = reader_.member(root, "spec", "variants_file", Type::string, false);
    if (!file) return;
    if (file->string.empty()) {
      reader_.error(*file, "variants_file", "the path is empty");
      return;
    }
    spec_.variants_path = (base_ / file->string).lexically_normal();
    spec_.variants_line = file->line;
  }

  void read_layout(const Value& root) {
    const Value* layout = reader_.member(root, "spec", "layout", Type::string, false);
    if (!layout) return;
    if (layout->string == "per_permutation")
      spec_.layout = LayoutMode::per_permutation;
    else if (layout->string != "shared")
      reader_.error(*layout, "layout",
                    "unknown layout \"" + layout->string + "\" (expected shared or per_permutation)");
  }

  void read_include_dirs(const Value& root) {
    const Value* dirs = reader_.member(root, "spec", "include_dirs", Type::array, false);
    if (!dirs || !reader_.within_limit(*dirs, "include_dirs", kMaxIncludeDirs, "include folders")) return;
    for (std::size_t i = 0; i < dirs->array.size(); ++i) {
      const Value& dir = dirs->array[i];
      if (dir.type != Type::string) {
        reader_.error(dir, SpecReader::index("include_dirs", i), "expected a string");
        continue;
      }
      spec_.include_dirs.push_back((base_ / dir.string).lexically_normal());
    }
  }

  void read_companions(const Value& root) {
    const Value* list = reader_.member(root, "spec", "companions", Type::array, false);
    if (!list) return;
    if (list->array.size() > kMaxCompanions)
      reader_.error(*list, "companions", "more than " + std::to_string(kMaxCompanions) + " companions");
    std::set<std::string> names;
    for (std::size_t i = 0; i < list->array.size() && i < kMaxCompanions; ++i) {
      const Value& item = list->array[i];
      std::string where = SpecReader::index("companions", i);
      if (item.type != Type::object) {
        reader_.error(item, where, "expected an object");
        continue;
      }
      reader_.only_keys(item, where, spec_keys::kCompanion);
      CompanionSpec companion;
      companion.name = reader_.string_member(item, where, "name");
      if (item.find("name") && !is_identifier(companion.name))
        reader_.error(*item.find("name"), where + ".name", "\"" + companion.name + "\" is not an identifier");
      else if (std::string problem = cpp_identifier_problem(companion.name); item.find("name") && !problem.empty())
        reader_.error(*item.find("name"), where + ".name", problem + " (a companion's name is its accessor's)");
      else if (!companion.name.empty() && !names.insert(companion.name).second)
        reader_.error(*item.find("name"), where + ".name", "companion \"" + companion.name + "\" is declared twice");
      companion.file = read_shader_file(
          item, where, companion.name.empty() ? std::string() : "companion \"" + companion.name + "\"");
      if (const Value* defines = item.find("defines")) companion.defines = read_companion_defines(*defines, where);
      if (const Value* shared = reader_.member(item, where, "shared_layout", Type::boolean, false))
        companion.shared_layout = shared->boolean;
      if (const Value* entry = reader_.member(item, where, "uber_shader", Type::string, false))
        companion.uber_shader = companion_entry(*entry, where);
      spec_.companions.push_back(std::move(companion));
    }
  }

  // A companion's "uber_shader": the name of an entry of "uber_shaders" (read before it).
  std::string companion_entry(const Value& entry, const std::string& where) {
    std::string names;
    for (const UberShaderEntry& e : spec_.uber_shaders) {
      if (e.name == entry.string) return entry.string;
      names += (names.empty() ? "" : ", ") + e.name;
    }
    if (spec_.uber_shaders.empty())
      reader_.error(entry, where + ".uber_shader", "names an entry of \"uber_shaders\", and the spec has none");
    else
      reader_.error(entry, where + ".uber_shader",
                    "no uber-shader \"" + entry.string + "\" (the spec has " + names + ")");
    return {};
  }

  // {"NAME": "VALUE", ...} as "NAME=VALUE" strings, in the file's order.
  std::vector<std::string> read_define_map(const Value& map, const std::string& where) {
    std::vector<std::string> out;
    for (const json::Member& m : map.object) {
      std::string at = SpecReader::join(where, m.first);
      std::string problem = define_name_problem(m.first);
      if (!problem.empty()) {
        reader_.error(m.second, at, problem);
        continue;
      }
      if (m.second.type != Type::string) {
        reader_.error(m.second, at,
                      std::string("expected a string value, found ") + json::type_name(m.second.type) + " (write \"" +
                          m.first + "\": \"1\")");
        continue;
      }
      if (problem = define_value_problem(m.second.string); !problem.empty()) {
        reader_.error(m.second, at, problem);
        continue;
      }
      out.push_back(m.first + "=" + m.second.string);
    }
    return out;
  }

  // A companion's "defines": identifiers (each = 1) or an object of values.
  std::vector<std::string> read_companion_defines(const Value& defines, const std::string& where) {
    if (defines.type == Type::object) return read_define_map(defines, where + ".defines");
    if (defines.type == Type::array) return read_identifier_list(defines, where + ".defines");
    reader_.error(
        defines, where + ".defines",
        std::string("expected an array of identifiers or an object of values, found ") + json::type_name(defines.type));
    return {};
  }

  // A fixed define on a feature's macro would fight the feature: the feature's permutations
  // would redefine it, and the others would have it on.
  void check_fixed_defines(const Value& root) {
    const Value* map = root.find("defines");
    if (!map || map->type != Type::object) return;
    for (const json::Member& m : map->object)
      for (const RawFeature& feature : spec_.raw_features)
        if (feature.define == m.first)
          reader_.error(
              m.second, SpecReader::join("defines", m.first),
              m.first + " is the define of raw feature " + feature.name + "; a fixed define cannot also be a feature");
  }

  std::vector<std::string> read_identifier_list(const Value& list, const std::string& where) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < list.array.size(); ++i) {
      const Value& item = list.array[i];
      if (item.type != Type::string || !is_identifier(item.string)) {
        reader_.error(item, SpecReader::index(where, i), "expected an identifier string");
        continue;
      }
      out.push_back(item.string);
    }
    return out;
  }

  // A value of a valued feature: an integer (kept as its decimal text) or an identifier.
  std::optional<std::string> read_value(const Value& value, const std::string& where) {
    if (value.type == Type::number && std::abs(value.number) < 1e9 && value.number == std::trunc(value.number))
      return std::to_string(static_cast<long long>(value.number));
    if (value.type == Type::string && is_identifier(value.string)) return value.string;
    std::string shown = value.type == Type::string   ? "\"" + value.string + "\""
                        : value.type == Type::number ? SpecReader::json_number(value.number)
                                                     : std::string(json::type_name(value.type));
    reader_.error(value, where, "expected an integer or an identifier, found " + shown);
    return std::nullopt;
  }

  // "values" of feature `where`: none (boolean), the list, or nullopt after an error.
  std::optional<std::vector<std::string>> read_values(const Value& item, const std::string& where) {
    const Value* list = item.find("values");
    if (!list) return std::vector<std::string>{};
    if (list->type != Type::array) {
      reader_.error(*list, where + ".values", std::string("expected an array, found ") + json::type_name(list->type));
      return std::nullopt;
    }
    if (list->array.size() < 2 || list->array.size() > kMaxFeatureValues) {
      reader_.error(*list, where + ".values",
                    "a valued feature has 2 to " + std::to_string(kMaxFeatureValues) + " values, found " +
                        std::to_string(list->array.size()));
      return std::nullopt;
    }
    std::vector<std::string> values;
    bool ok = true;
    for (std::size_t j = 0; j < list->array.size(); ++j) {
      std::string at = SpecReader::index(where + ".values", j);
      auto value = read_value(list->array[j], at);
      if (!value) {
        ok = false;
      } else if (std::find(values.begin(), values.end(), *value) != values.end()) {
        reader_.error(list->array[j], at, "value " + *value + " is listed twice");
        ok = false;
      } else {
        values.push_back(std::move(*value));
      }
    }
    if (!ok) return std::nullopt;
    return values;
  }

  static std::uint32_t width_for(std::size_t value_count) {
    std::uint32_t width = 1;
    while ((std::size_t{1} << width) < value_count) ++width;
    return width;
  }

  void read_raw(const Value& raw) {
    reader_.only_keys(raw, "raw", spec_keys::kRaw);
    const Value* features = reader_.member(raw, "raw", "features", Type::array);
    if (!features) return;
    if (features->array.empty() || features->array.size() > kMaxRawFeatures) {
      reader_.error(*features, "raw.features",
                    "expected 1 to " + std::to_string(kMaxRawFeatures) + " features, found " +
                        std::to_string(features->array.size()));
      return;
    }
    // The values decide the widths, and the widths how many raw bits there are to place.
    std::vector<std::vector<std::string>> values(features->array.size());
    std::uint32_t total = 0;
    bool values_read = true;
    for (std::size_t i = 0; i < features->array.size(); ++i) {
      const Value& item = features->array[i];
      if (item.type != Type::object) continue;
      auto read = read_values(item, SpecReader::index("raw.features", i));
      if (read) values[i] = std::move(*read);
      values_read = values_read && read.has_value();
      total += values[i].empty() ? 1 : width_for(values[i].size());
    }
    // Without every feature's values the widths, and so every bit check, would be wrong.
    if (!values_read) return;
    if (total > kMaxRawFeatures) {
      reader_.error(
          *features, "raw.features",
          "the features take " + std::to_string(total) + " raw bits; the limit is " + std::to_string(kMaxRawFeatures));
      return;
    }
    std::vector<std::optional<RawFeature>> by_bit(total);
    std::vector<std::string> owner(total);
    std::map<std::string, std::string> defines_seen;
    std::set<std::string> names_seen;
    for (std::size_t i = 0; i < features->array.size(); ++i) {
      const Value& item = features->array[i];
      std::string where = SpecReader::index("raw.features", i);
      if (item.type != Type::object) {
        reader_.error(item, where, "expected an object");
        continue;
      }
      reader_.only_keys(item, where, spec_keys::kFeature);
      RawFeature feature;
      feature.name = reader_.string_member(item, where, "name");
      feature.define = reader_.string_member(item, where, "define");
      if (const Value* define = item.find("define")) {
        feature.define_line = define->line;
        feature.define_column = define->column;
      }
      feature.description = reader_.string_member(item, where, "description", false);
      feature.values = std::move(values[i]);
      feature.width = feature.valued() ? width_for(feature.values.size()) : 1;
      feature.spec_order = i;
      read_feature_kind(item, where, feature);
      auto bit = reader_.bit_member(item, where, total);
      if (item.find("name") && !is_identifier(feature.name)) {
        reader_.error(*item.find("name"), where + ".name", "\"" + feature.name + "\" is not an identifier");
        continue;
      }
      if (item.find("define") && !is_identifier(feature.define)) {
        reader_.error(*item.find("define"), where + ".define", "\"" + feature.define + "\" is not a GLSL identifier");
        continue;
      }
      if (!feature.name.empty() && !names_seen.insert(feature.name).second)
        reader_.error(*item.find("name"), where + ".name", "feature \"" + feature.name + "\" is declared twice");
      if (!feature.define.empty()) {
        auto [it, fresh] = defines_seen.emplace(feature.define, feature.name);
        if (!fresh)
          reader_.error(*item.find("define"), where + ".define",
                        "define " + feature.define + " is already used by feature " + it->second);
      }
      if (bit) place_feature(std::move(feature), *bit, *item.find("bit"), where, by_bit, owner);
    }
    if (!reader_.errors().empty()) return;
    for (auto& feature : by_bit)
      if (feature) spec_.raw_features.push_back(std::move(*feature));
    check_cpp_names(*features);
    read_impossible(raw);
  }

  // The features' names and values become C++ names in the generated registry
  // (spec/cpp_names.h): refused here, at the key that wrote them, rather than as a compile
  // error in generated code. `features` is "raw.features", whose entries all became features.
  void check_cpp_names(const Value& features) {
    std::vector<RawFeature> in_order(spec_.raw_features.size());
    for (const RawFeature& f : spec_.raw_features) in_order[f.spec_order] = f;
    for (std::size_t i = 0; i < in_order.size(); ++i) {
      const std::string where = SpecReader::index("raw.features", i);
      if (std::string problem = feature_name_problem(in_order[i].name); !problem.empty())
        reader_.error(*features.array[i].find("name"), where + ".name", problem);
      for (std::size_t j = 0; j < in_order[i].values.size(); ++j) {
        const std::string& value = in_order[i].values[j];
        if (!is_identifier(value)) continue;  // an integer: its enumerator is _<digits>
        if (std::string problem = cpp_identifier_problem(value); !problem.empty())
          reader_.error(features.array[i].find("values")->array[j], SpecReader::index(where + ".values", j), problem);
      }
    }
    for (const NameClash& clash : generated_name_clashes(in_order)) {
      const Value& item = features.array[clash.feature];
      const std::string where = SpecReader::index("raw.features", clash.feature);
      if (clash.kind == NameClash::Kind::value)
        reader_.error(item.find("values")->array[clash.value], SpecReader::index(where + ".values", clash.value),
                      clash.message);
      else
        reader_.error(*item.find("name"), where + ".name", clash.message);
    }
  }

  // Puts `feature` on bits [bit, bit + width), unless they run past the last raw bit or
  // another feature holds one of them.
  void place_feature(RawFeature feature, std::uint32_t bit, const Value& at, const std::string& where,
                     std::vector<std::optional<RawFeature>>& by_bit, std::vector<std::string>& owner) {
    std::uint32_t total = static_cast<std::uint32_t>(owner.size());
    if (bit + feature.width > total) {
      reader_.error(at, where + ".bit",
                    feature.name + " has " + std::to_string(feature.values.size()) + " values, so it takes bits " +
                        std::to_string(bit) + " to " + std::to_string(bit + feature.width - 1) +
                        ", past the last raw bit " + std::to_string(total - 1));
      return;
    }
    for (std::uint32_t b = bit; b < bit + feature.width; ++b) {
      if (owner[b].empty()) continue;
      reader_.error(at, where + ".bit",
                    "bit " + std::to_string(b) + " of " + feature.name + " collides with feature " + owner[b]);
      return;
    }
    for (std::uint32_t b = bit; b < bit + feature.width; ++b) owner[b] = feature.name;
    feature.bit = bit;
    by_bit[bit] = std::move(feature);
  }

  void read_impossible(const Value& raw) {
    const Value* list = reader_.member(raw, "raw", "impossible", Type::array, false);
    if (!list || !reader_.within_limit(*list, "raw.impossible", kMaxImpossibleRules, "rules")) return;
    auto symbols = spec_.raw_symbols();
    for (std::size_t i = 0; i < list->array.size(); ++i) {
      const Value& item = list->array[i];
      std::string where = SpecReader::index("raw.impossible", i);
      if (item.type != Type::object) {
        reader_.error(item, where, "expected an object with \"when\" and \"why\"");
        continue;
      }
      reader_.only_keys(item, where, spec_keys::kImpossible);
      auto rule = reader_.rule_member(item, where, "when", symbols, "raw features");
      std::string why = reader_.string_member(item, where, "why", false);
      if (rule) spec_.impossible.push_back(ImpossibleSet{std::move(*rule), std::move(why)});
    }
  }

  void read_optimised(const Value& optimised) {
    reader_.only_keys(optimised, "optimised", spec_keys::kOptimised);
    if (spec_.raw_features.empty()) return;  // raw section already reported
    if (const Value* ignore = optimised.find("ignore")) {
      if (optimised.find("bits") || optimised.find("variants"))
        reader_.error(*ignore, "optimised.ignore",
                      "\"ignore\" replaces \"bits\" and \"variants\": a collapse takes one form or the other");
      else
        read_ignore(*ignore);
      return;
    }
    const Value* bits = reader_.member(optimised, "optimised", "bits", Type::array);
    if (!bits) return;
    if (bits->array.empty() || bits->array.size() > kMaxOptimisedBits) {
      reader_.error(
          *bits, "optimised.bits",
          "expected 1 to " + std::to_string(kMaxOptimisedBits) + " bits, found " + std::to_string(bits->array.size()));
      return;
    }
    std::uint32_t count = static_cast<std::uint32_t>(bits->array.size());
    std::vector<std::optional<OptimisedBit>> by_bit(count);
    std::set<std::string> names_seen;
    auto raw_symbols = spec_.raw_symbols();
    for (std::size_t i = 0; i < bits->array.size(); ++i) {
      const Value& item = bits->array[i];
      std::string where = SpecReader::index("optimised.bits", i);
      if (item.type != Type::object) {
        reader_.error(item, where, "expected an object");
        continue;
      }
      reader_.only_keys(item, where, spec_keys::kOptimisedBit);
      OptimisedBit bit;
      bit.name = reader_.string_member(item, where, "name");
      bit.description = reader_.string_member(item, where, "description", false);
      auto index = reader_.bit_member(item, where, count);
      auto rule = reader_.rule_member(item, where, "when", raw_symbols, "raw features");
      if (item.find("name") && !is_identifier(bit.name)) {
        reader_.error(*item.find("name"), where + ".name", "\"" + bit.name + "\" is not an identifier");
        continue;
      }
      if (std::string problem = cpp_identifier_problem(bit.name); !problem.empty()) {
        reader_.error(*item.find("name"), where + ".name", problem);
        continue;
      }
      if (!bit.name.empty() && !names_seen.insert(bit.name).second)
        reader_.error(*item.find("name"), where + ".name", "optimised bit \"" + bit.name + "\" is declared twice");
      if (!index || !rule) continue;
      if (by_bit[*index]) {
        reader_.error(*item.find("bit"), where + ".bit",
                      "bit " + std::to_string(*index) + " of " + bit.name + " collides with optimised bit " +
                          by_bit[*index]->name);
        continue;
      }
      if (const RawFeature* other = first_non_variant(rule->expression.symbol_mask()))
        reader_.error(*item.find("when"), where + ".when",
                      "optimised bit " + bit.name + " names feature " + other->name + ", a " +
                          kind_phrase(other->kind) + ": the collapse is over variant features only");
      bit.bit = *index;
      bit.when = std::move(*rule);
      by_bit[*index] = std::move(bit);
    }
    if (!reader_.errors().empty()) return;
    for (auto& bit : by_bit) spec_.optimised_bits.push_back(std::move(*bit));
    read_variants(optimised);
  }

  // "ignore": [{"feature": NAME, "when": RULE}, ...]: what the optimised shaders leave out.
  void read_ignore(const Value& ignore) {
    if (ignore.type != Type::array) {
      reader_.error(ignore, "optimised.ignore",
                    std::string("expected an array, found ") + json::type_name(ignore.type));
      return;
    }
    if (!reader_.within_limit(ignore, "optimised.ignore", kMaxVariants, "rules")) return;
    auto symbols = spec_.raw_symbols();
    for (std::size_t i = 0; i < ignore.array.size(); ++i) {
      const Value& item = ignore.array[i];
      std::string where = SpecReader::index("optimised.ignore", i);
      if (item.type != Type::object) {
        reader_.error(item, where, "expected an object with \"feature\" and \"when\"");
        continue;
      }
      reader_.only_keys(item, where, spec_keys::kIgnore);
      std::string name = reader_.string_member(item, where, "feature");
      auto found = std::find_if(spec_.raw_features.begin(), spec_.raw_features.end(),
                                [&](const RawFeature& f) { return f.name == name; });
      IgnoreRule rule;
      if (item.find("when")) {
        auto when = reader_.rule_member(item, where, "when", symbols, "raw features");
        if (!when) continue;
        rule.when = std::move(*when);
      } else {
        rule.when = Rule{*parse_expression("true", symbols), "true", item.line};
      }
      if (!item.find("feature") || item.find("feature")->type != Type::string) continue;
      if (found == spec_.raw_features.end()) {
        reader_.error(*item.find("feature"), where + ".feature", "unknown raw feature \"" + name + "\"");
        continue;
      }
      if (!found->is_variant()) {
        reader_.error(*item.find("feature"), where + ".feature",
                      name + " is a " + kind_phrase(found->kind) +
                          ": it is never compiled in, so an optimised shader has nothing to leave out");
        continue;
      }
      // The optimised ID is fixed by the lookup table: a rule reading a value set only when the
      // pipeline is created, or at draw time, would choose the program from a run-time value.
      if (const RawFeature* other = first_non_variant(rule.when.expression.symbol_mask())) {
        reader_.error(*item.find("when"), where + ".when",
                      "the rule names feature " + other->name + ", a " + kind_phrase(other->kind) +
                          ": which optimised shader a raw ID draws cannot depend on a value set at run time "
                          "(the collapse is over variant features only)");
        continue;
      }
      rule.feature = static_cast<std::size_t>(found - spec_.raw_features.begin());
      spec_.ignored.push_back(std::move(rule));
    }
  }

  void read_variants(const Value& optimised) {
    const Value* list = reader_.member(optimised, "optimised", "variants", Type::array);
    if (!list || !reader_.within_limit(*list, "optimised.variants", kMaxVariants, "variants")) return;
    std::vector<ExpressionSymbol> symbols;
    for (const OptimisedBit& bit : spec_.optimised_bits) symbols.push_back({bit.name, bit.bit, 1, {}});
    for (std::size_t i = 0; i < list->array.size(); ++i) {
      const Value& item = list->array[i];
      std::string where = SpecReader::index("optimised.variants", i);
      if (item.type != Type::object) {
        reader_.error(item, where, "expected an object with \"when\" and \"raw_features\"");
        continue;
      }
      reader_.only_keys(item, where, spec_keys::kVariant);
      auto rule = reader_.rule_member(item, where, "when", symbols, "optimised bits");
      const Value* features = reader_.member(item, where, "raw_features", Type::array);
      if (!rule || !features) continue;
      OptimisedVariant variant{std::move(*rule), {}};
      for (std::size_t j = 0; j < features->array.size(); ++j)
        if (auto setting = read_setting(features->array[j], SpecReader::index(where + ".raw_features", j)))
          variant.raw_features.push_back(*setting);
      spec_.variants.push_back(std::move(variant));
    }
  }

  // A variant's raw feature: "NAME" for a boolean one, "NAME=VALUE" for a valued one.
  std::optional<FeatureSetting> read_setting(const Value& entry, const std::string& where) {
    std::string text = entry.type == Type::string ? entry.string : std::string();
    std::string name = text.substr(0, text.find('='));
    auto found = std::find_if(spec_.raw_features.begin(), spec_.raw_features.end(),
                              [&](const RawFeature& f) { return f.name == name; });
    if (entry.type != Type::string || found == spec_.raw_features.end()) {
      std::string known;
      for (const RawFeature& f : spec_.raw_features) known += (known.empty() ? "" : ", ") + f.name;
      reader_.error(entry, where,
                    (entry.type == Type::string ? "unknown raw feature \"" + name + "\""
                                                : std::string("expected a raw feature name")) +
                        " (known: " + known + ")");
      return std::nullopt;
    }
    if (!found->is_variant()) {
      reader_.error(entry, where,
                    found->name + " is a " + kind_phrase(found->kind) +
                        ": a variant compiles variant features only (its value travels beside the optimised ID)");
      return std::nullopt;
    }
    bool has_value = name.size() < text.size();
    if (!found->valued()) {
      if (has_value) reader_.error(entry, where, found->name + " is a boolean feature; name it without a value");
      if (has_value) return std::nullopt;
      return FeatureSetting{found->mask(), found->mask()};
    }
    std::string value = has_value ? text.substr(name.size() + 1) : std::string();
    auto index = std::find(found->values.begin(), found->values.end(), value);
    if (index == found->values.end()) {
      std::string listed;
      for (const std::string& v : found->values) listed += (listed.empty() ? "" : ", ") + v;
      reader_.error(entry, where,
                    has_value ? found->name + " has no value " + value + " (values: " + listed + ")"
                              : found->name + " has values (" + listed + "); name one, e.g. \"" + found->name + "=" +
                                    found->values.front() + "\"");
      return std::nullopt;
    }
    auto position = static_cast<std::uint32_t>(index - found->values.begin());
    return FeatureSetting{found->mask(), position << found->bit};
  }

  // "a specialization constant", "run-time branch" or "variant", for messages.
  static std::string kind_phrase(FeatureKind kind) {
    switch (kind) {
      case FeatureKind::variant: return "variant";
      case FeatureKind::specialization: return "specialization constant";
      case FeatureKind::branch: return "run-time branch";
    }
    return "variant";
  }

  // The first feature with a bit in `mask` that is not a variant, or nullptr.
  const RawFeature* first_non_variant(std::uint32_t mask) const {
    for (const RawFeature& f : spec_.raw_features)
      if (!f.is_variant() && (f.mask() & mask)) return &f;
    return nullptr;
  }

  void read_define_style(const Value& value, const std::string& where, DefineStyle& style) {
    if (value.type == Type::string && value.string == "presence")
      style = DefineStyle::presence;
    else if (value.type == Type::string && value.string == "value")
      style = DefineStyle::value;
    else
      reader_.error(value, where, "unknown define style " + shown(value) + " (expected presence or value)");
  }

  static std::string shown(const Value& value) {
    return value.type == Type::string ? "\"" + value.string + "\"" : std::string(json::type_name(value.type));
  }

  // "kind", "constant_id", "define_style" and "unread" of one raw feature.
  void read_feature_kind(const Value& item, const std::string& where, RawFeature& feature) {
    feature.define_style = default_style_;
    if (const Value* style = item.find("define_style"))
      read_define_style(*style, where + ".define_style", feature.define_style);
    if (const Value* kind = item.find("kind")) {
      if (kind->type == Type::string && kind->string == "specialization")
        feature.kind = FeatureKind::specialization;
      else if (kind->type == Type::string && kind->string == "branch")
        feature.kind = FeatureKind::branch;
      else if (!(kind->type == Type::string && kind->string == "variant"))
        reader_.error(*kind, where + ".kind",
                      "unknown kind " + shown(*kind) + " (expected variant, specialization or branch)");
    }
    if (const Value* id = item.find("constant_id")) {
      double v = id->number;
      if (feature.kind != FeatureKind::specialization)
        reader_.error(*id, where + ".constant_id",
                      "only a specialization feature has a constant_id (this one is a " +
                          std::string(feature_kind_name(feature.kind)) + ")");
      else if (id->type != Type::number || !(v >= 0 && v <= 2147483647.0) || v != std::trunc(v))
        reader_.error(*id, where + ".constant_id", "expected an integer from 0 to 2147483647");
      else {
        pinned_ids_.push_back({static_cast<std::uint32_t>(v), item.find("constant_id")});
        pinned_features_.insert(feature.spec_order);
      }
    }
    if (const Value* unread = item.find("unread")) {
      if (unread->type == Type::string && unread->string == "allowed")
        feature.unread_allowed = true;
      else
        reader_.error(*unread, where + ".unread", "expected \"allowed\", found " + shown(*unread));
    }
  }

  // After the features: constant IDs, the branch block, and the names the kinds declare.
  void read_kinds(const Value& root) {
    assign_constant_ids();
    read_branch_block(root);
    check_declared_values();
  }

  // Pinned IDs as written; the others take the smallest free ID, in spec order.
  void assign_constant_ids() {
    std::map<std::uint32_t, std::string> taken;
    std::vector<RawFeature*> order;
    for (RawFeature& f : spec_.raw_features) order.push_back(&f);
    std::sort(order.begin(), order.end(),
              [](const RawFeature* a, const RawFeature* b) { return a->spec_order < b->spec_order; });
    std::size_t pinned_next = 0;
    std::vector<RawFeature*> unpinned;
    for (RawFeature* f : order) {
      if (f->kind != FeatureKind::specialization) continue;
      if (!has_pinned_id(*f)) {
        unpinned.push_back(f);
        continue;
      }
      const PinnedId& pin = pinned_ids_[pinned_next++];
      f->constant_id = pin.id;
      auto [it, fresh] = taken.emplace(pin.id, f->name);
      if (!fresh)
        reader_.error(*pin.at, "raw.features[" + std::to_string(f->spec_order) + "].constant_id",
                      "constant_id " + std::to_string(pin.id) + " is already taken by feature " + it->second);
    }
    std::uint32_t next = 0;
    for (RawFeature* f : unpinned) {
      while (taken.count(next)) ++next;
      f->constant_id = next;
      taken.emplace(next, f->name);
    }
  }

  bool has_pinned_id(const RawFeature& f) const { return pinned_features_.count(f.spec_order) > 0; }

  void read_branch_block(const Value& root) {
    std::vector<const RawFeature*> branches = spec_.branch_features();
    const Value* block = root.find("branch_block");
    if (!block) {
      if (!branches.empty())
        reader_.error(root, "spec",
                      "feature " + branches.front()->name +
                          " is a run-time branch: its value is read from a uniform block, so the spec needs "
                          "\"branch_block\": {\"set\": S, \"binding\": B}");
      return;
    }
    if (!(block = reader_.member(root, "spec", "branch_block", Type::object))) return;
    reader_.only_keys(*block, "branch_block", spec_keys::kBranchBlock);
    BranchBlockSpec spec{0, 0, block->line};
    bool ok = small_index(*block, "set", spec.set) && small_index(*block, "binding", spec.binding);
    if (!ok) return;
    if (branches.empty()) {
      // A warning, not an error: switching the last branch to a variant stays an edit of its
      // "kind". Said only when the features were read: after an error in them (a misspelt
      // "kind" or key) whether a feature is a branch is not known.
      if (reader_.errors().empty())
        spec_.warnings.push_back(Diagnostic{
            Severity::warning, spec_.spec_path.string(), block->line, block->column,
            "branch_block: no feature is of kind branch, so no block is declared; remove it, or make a feature a "
            "branch"});
      return;
    }
    spec_.branch_block = spec;
  }

  bool small_index(const Value& block, std::string_view key, std::uint32_t& out) {
    const Value* value = reader_.member(block, "branch_block", key, Type::number);
    if (!value) return false;
    if (!(value->number >= 0 && value->number < 65536) || value->number != std::trunc(value->number)) {
      reader_.error(*value, "branch_block." + std::string(key), "expected an integer from 0 to 65535");
      return false;
    }
    out = static_cast<std::uint32_t>(value->number);
    return true;
  }

  // Identifier values of a specialization, branch or value-style feature are declared to the
  // shader as constants of their index: one name cannot stand for two indices.
  void check_declared_values() {
    std::map<std::string, std::pair<std::size_t, const RawFeature*>> declared;
    for (const RawFeature& f : spec_.raw_features) {
      if (f.is_variant() && f.define_style == DefineStyle::presence) continue;
      for (std::size_t i = 0; i < f.values.size(); ++i) {
        if (!is_identifier(f.values[i])) continue;
        auto [it, fresh] = declared.emplace(f.values[i], std::pair{i, &f});
        if (fresh || it->second.first == i) continue;
        reader_.error(spec_location(f), "raw.features[" + std::to_string(f.spec_order) + "].values",
                      "value " + f.values[i] + " is declared to the shader as " + std::to_string(i) + " for " + f.name +
                          " and as " + std::to_string(it->second.first) + " for " + it->second.second->name);
      }
    }
  }

  // A feature's "define" location stands for the feature in messages about it as a whole.
  static Value spec_location(const RawFeature& f) {
    Value at;
    at.line = f.define_line;
    at.column = f.define_column;
    return at;
  }

  struct PinnedId {
    std::uint32_t id;
    const Value* at;
  };

  SpecReader& reader_;
  std::filesystem::path base_;
  DomainSpec spec_;
  DefineStyle default_style_ = DefineStyle::presence;
  std::vector<PinnedId> pinned_ids_;       // "constant_id"s as read, in spec order
  std::set<std::size_t> pinned_features_;  // spec_order of the features that pin one
};

}  // namespace

Result<DomainSpec> parse_domain(std::string_view text, const std::filesystem::path& spec_path) {
  std::string file = spec_path.string();
  auto root = json::parse(text, file);
  if (!root) return std::move(root).take_errors();
  SpecReader reader(file);
  DomainSpec spec = DomainBuilder(spec_path, reader).build(*root);
  if (!reader.errors().empty()) return std::move(reader.errors());
  return spec;
}

}  // namespace shadergen
