#include "spec/cpp_names.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <map>

#include "shadergen/domain.h"

namespace shadergen {
namespace {

// The C++20 keywords ([lex.key]) and alternative tokens ([lex.digraph]): none can be declared.
constexpr std::string_view kKeywords[] = {
    "alignas", "alignof", "asm", "auto", "bool", "break", "case", "catch", "char", "char8_t", "char16_t", "char32_t",
    "class", "concept", "const", "consteval", "constexpr", "constinit", "const_cast", "continue", "co_await",
    "co_return", "co_yield", "decltype", "default", "delete", "do", "double", "dynamic_cast", "else", "enum",
    "explicit", "export", "extern", "false", "float", "for", "friend", "goto", "if", "inline", "int", "long", "mutable",
    "namespace", "new", "noexcept", "nullptr", "operator", "private", "protected", "public", "register",
    "reinterpret_cast", "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast",
    "struct", "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename",
    "union", "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while",
    // alternative tokens
    "and", "and_eq", "bitand", "bitor", "compl", "not", "not_eq", "or", "or_eq", "xor", "xor_eq"};

// The names the generated namespace declares (shadergen/registry.h lists them) and the
// namespaces its code names. A member of Features so called would hide the name inside the
// struct, and a registry whose feature reads as its API invites misreading.
constexpr std::string_view kGeneratedNames[] = {
    "Features",        "RawId",           "OptimisedId", "RawBits",   "OptimisedBits", "kRawBits",    "kRawCount",
    "kOptimisedCount", "kRawToOptimised", "kRawPruned",  "kFeatures", "kDefines",      "raw_bit",     "optimised_bit",
    "is_valid_raw_id", "optimised_id",    "raw_id",      "features",  "is_possible",   "find_raw_id", "to_string",
    "registry",        "detail",          "std",         "shadergen", "companions"};

bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }

// A name the generated code derives from a valued feature's name.
struct Derived {
  std::string name;
  std::string what;  // "the enum", ...
};

// The names derived from valued feature `f` that feature `other` must not take: its enum and
// value conversion anywhere (Features' members name the enums' types), its raw_bit:: shift and
// mask where `other` is boolean (a raw_bit:: constant of its own name).
std::vector<Derived> derived_names(const RawFeature& f, const RawFeature& other) {
  if (!f.valued()) return {};
  std::vector<Derived> names = {{f.name + "_value", "the enum"}, {"to_" + f.name, "the value conversion"}};
  if (!other.valued()) {
    names.push_back({f.name + "_shift", "raw_bit::" + f.name + "_shift"});
    names.push_back({f.name + "_mask", "raw_bit::" + f.name + "_mask"});
  }
  return names;
}

}  // namespace

std::string enumerator_name(std::string_view value) {
  if (value.empty()) return "_";
  if (value[0] == '-') return "_m" + std::string(value.substr(1));
  if (value[0] >= '0' && value[0] <= '9') return std::string("_").append(value);
  return std::string(value);
}

std::string cpp_identifier_problem(std::string_view name) {
  const std::string quoted = "\"" + std::string(name) + "\"";
  if (std::ranges::find(kKeywords, name) != std::end(kKeywords))
    return quoted + " is a C++ keyword or reserved name; the generated registry cannot declare it";
  if (name.size() >= 2 && name[0] == '_' && is_upper(name[1]))
    return quoted +
           " is reserved in C++ (an underscore and a capital letter begin it); the generated registry "
           "cannot declare it";
  if (name.find("__") != std::string_view::npos)
    return quoted + " is reserved in C++ (it holds a double underscore); the generated registry cannot declare it";
  return {};
}

std::string feature_name_problem(std::string_view name) {
  if (std::string problem = cpp_identifier_problem(name); !problem.empty()) return problem;
  if (std::ranges::find(kGeneratedNames, name) != std::end(kGeneratedNames))
    return "\"" + std::string(name) + "\" is a name the generated registry declares itself";
  return {};
}

std::vector<NameClash> generated_name_clashes(const std::vector<RawFeature>& features) {
  std::vector<NameClash> clashes;
  for (std::size_t i = 0; i < features.size(); ++i) {
    std::map<std::string, std::size_t> enumerators;
    for (std::size_t j = 0; j < features[i].values.size(); ++j) {
      const std::string& value = features[i].values[j];
      const std::string name = enumerator_name(value);
      auto [it, fresh] = enumerators.emplace(name, j);
      if (!fresh)
        clashes.push_back({i, j, NameClash::Kind::value,
                           "values " + features[i].values[it->second] + " and " + value +
                               " both become the enumerator " + features[i].name + "_value::" + name +
                               " in the generated C++"});
    }
  }
  // A derived name clashes with a feature whichever comes first in the spec: reported on the later.
  for (std::size_t i = 0; i < features.size(); ++i)
    for (std::size_t k = 0; k < features.size(); ++k) {
      if (i == k) continue;
      for (const Derived& derived : derived_names(features[k], features[i])) {
        if (features[i].name != derived.name) continue;
        const std::string of = derived.what + " of valued feature " + features[k].name;
        clashes.push_back({std::max(i, k), 0, NameClash::Kind::name,
                           i > k ? "\"" + derived.name + "\" clashes with " + of + " in the generated C++"
                                 : of + ", " + derived.name + ", clashes with feature \"" + features[i].name +
                                       "\" in the generated C++"});
      }
    }
  return clashes;
}

}  // namespace shadergen
