// spec_keys.h - every key the spec reader accepts, by the object that holds it.
//
// The reader refuses any other key (a misspelt key would otherwise be ignored), naming these in
// its message; the docs test checks that docs/spec-format.md documents each one, so a key added
// here without docs fails a test rather than going unmentioned.
#pragma once

#include <array>
#include <span>
#include <string_view>

namespace shadergen::spec_keys {

inline constexpr std::array<std::string_view, 18> kTop{
    "format",       "name",       "description", "uber_shader",   "uber_shaders", "program",
    "include_dirs", "target_env", "layout",      "strip_debug",   "defines",      "companions",
    "raw",          "optimised",  "compile",     "variants_file", "define_style", "branch_block"};
inline constexpr std::array<std::string_view, 2> kShaderFile{"path", "stage"};  // uber_shader, uber_shaders.<name>
inline constexpr std::array<std::string_view, 2> kProgram{"vertex", "fragment"};
inline constexpr std::array<std::string_view, 6> kCompanion{"name",    "path",          "stage",
                                                            "defines", "shared_layout", "uber_shader"};
inline constexpr std::array<std::string_view, 2> kRaw{"features", "impossible"};
inline constexpr std::array<std::string_view, 9> kFeature{
    "name", "bit", "define", "values", "description", "kind", "constant_id", "define_style", "unread"};
inline constexpr std::array<std::string_view, 2> kImpossible{"when", "why"};
inline constexpr std::array<std::string_view, 3> kOptimised{"bits", "variants", "ignore"};
inline constexpr std::array<std::string_view, 4> kOptimisedBit{"name", "bit", "when", "description"};
inline constexpr std::array<std::string_view, 3> kIgnore{"feature", "when", "description"};
inline constexpr std::array<std::string_view, 3> kVariant{"when", "raw_features", "description"};
inline constexpr std::array<std::string_view, 2> kBranchBlock{"set", "binding"};

// One object of the format and the keys it takes; `object` as the reader's messages name it.
struct ObjectKeys {
  std::string_view object;
  std::span<const std::string_view> keys;
};

inline constexpr std::array<ObjectKeys, 13> kAll{{
    {"spec", kTop},
    {"uber_shader", kShaderFile},
    {"uber_shaders.<name>", kShaderFile},
    {"program", kProgram},
    {"companions[]", kCompanion},
    {"raw", kRaw},
    {"raw.features[]", kFeature},
    {"raw.impossible[]", kImpossible},
    {"optimised", kOptimised},
    {"optimised.bits[]", kOptimisedBit},
    {"optimised.ignore[]", kIgnore},
    {"optimised.variants[]", kVariant},
    {"branch_block", kBranchBlock},
}};

}  // namespace shadergen::spec_keys
