// shadergen/registry.h - the types that shadergen's generated C++ registries are made of.
//
// A registry is generated per domain spec (see shadergen_add_permutations() in CMake). Its
// header declares, inside the namespace chosen at generation time:
//
//   inline constexpr std::uint32_t kRawCount;            // 1 << raw bits (128 for Split/Second)
//   inline constexpr std::uint32_t kOptimisedCount;      // 1 << optimised bits (32); 0: not collapsed
//   inline constexpr std::array<std::uint8_t, kRawCount> kRawToOptimised;  // the lookup table
//                                                        // (absent when the domain is not collapsed)
//   inline constexpr std::array<bool, kRawCount> kRawPruned;               // impossible raw IDs
//   namespace raw_bit       { inline constexpr std::uint32_t <FEATURE> = 1u << n; ... }
//   namespace optimised_bit { inline constexpr std::uint32_t <BIT> = 1u << n; ... }
//   enum class <FEATURE>_value : std::uint32_t { <value>, ... };  // per valued feature: its values,
//                                                        // an integer 2 spelt _2 (-1: _m1)
//   struct Features { bool <FEATURE> = false; <FEATURE>_value <FEATURE> = ...; ... };
//                                                        // one member per raw feature, in spec order
//   constexpr std::uint32_t raw_id(const Features&);     // the raw ID those features make
//   inline constexpr std::array<shadergen::Feature, n> kFeatures;           // in spec order
//   inline constexpr std::array<shadergen::FixedDefine, n> kDefines;        // the fixed defines
//   constexpr std::optional<std::uint32_t> find_raw_id(std::string_view);   // "A|B=2" -> raw ID
//   const shadergen::Registry& registry();
//
// shadergen/vulkan.h turns a registry's permutations into Vulkan create-infos; only a consumer
// that includes it needs the Vulkan headers.
//
// This header has no dependencies beyond the standard library so that runtimes can include it
// without linking shadergen itself.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace shadergen {

// Pipeline stage of a compiled blob. Values match VkShaderStageFlagBits so a runtime can cast.
enum class Stage : std::uint32_t {
  vertex = 0x01,
  tess_control = 0x02,
  tess_evaluation = 0x04,
  geometry = 0x08,
  fragment = 0x10,
  compute = 0x20,
  task = 0x40,             // VK_SHADER_STAGE_TASK_BIT_EXT
  mesh = 0x80,             // VK_SHADER_STAGE_MESH_BIT_EXT
  ray_generation = 0x100,  // VK_SHADER_STAGE_RAYGEN_BIT_KHR
  any_hit = 0x200,
  closest_hit = 0x400,
  miss = 0x800,
  intersection = 0x1000,
  callable = 0x2000,
};

// Descriptor kinds found by reflection. Values match VkDescriptorType so a runtime can cast.
enum class DescriptorKind : std::uint32_t {
  sampler = 0,
  combined_image_sampler = 1,
  sampled_image = 2,
  storage_image = 3,
  uniform_texel_buffer = 4,
  storage_texel_buffer = 5,
  uniform_buffer = 6,
  storage_buffer = 7,
  input_attachment = 10,                // a subpass input
  acceleration_structure = 1000150000,  // VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR
};

// One descriptor binding of the merged pipeline layout: the union over every blob of the
// registry. `stages` is a VkShaderStageFlags-compatible mask of the stages that use it.
struct DescriptorBinding {
  std::uint32_t set;
  std::uint32_t binding;
  DescriptorKind kind;
  std::uint32_t count;  // array size; 1 for a scalar binding; 0 when runtime-sized
  std::uint32_t stages;
  std::string_view name;
  bool runtime_sized = false;                // `texture2D t[]`: the count is chosen at run time
  std::uint32_t input_attachment_index = 0;  // kind == input_attachment: the subpass input's index
};

// A specialization constant (`layout(constant_id = N) const T name = default;`).
enum class ScalarType : std::uint32_t { boolean, int32, uint32, float32 };
struct SpecializationConstant {
  std::uint32_t id;  // constant_id, as VkSpecializationMapEntry::constantID
  std::string_view name;
  ScalarType type;
  std::uint32_t default_bits;  // the default's 32-bit pattern (a float's bits for float32)
};

// A push-constant block: byte size and the VkShaderStageFlags-compatible stages using it.
struct PushConstantRange {
  std::uint32_t size;
  std::uint32_t stages;
};

// A stage input or output variable (vertex inputs, fragment outputs, varyings).
struct InterfaceVariable {
  std::uint32_t location;
  std::uint32_t components;  // vector width: 1..4
  std::string_view name;
};

// Reflection of one blob.
struct Reflection {
  std::span<const DescriptorBinding> bindings;
  std::uint32_t push_constant_size;  // 0 when the blob has no push constants
  std::span<const InterfaceVariable> inputs;
  std::span<const InterfaceVariable> outputs;
  std::uint32_t local_size[3];  // work-group size (compute, task, mesh; the default where
                                // a specialization constant sets it); {0,0,0} otherwise
  std::span<const SpecializationConstant> specialization_constants = {};
  // Per axis, the constant_id that sets the work-group size (local_size_x_id), or kNoConstant.
  static constexpr std::uint32_t kNoConstant = 0xffffffffu;
  std::uint32_t local_size_ids[3] = {kNoConstant, kNoConstant, kNoConstant};
};

// A raw feature as the generated kFeatures lists it: `width` bits from `bit` of the raw ID.
// A boolean feature has no values (width 1, set: `#define <define> 1`); a valued feature's
// field holds the index of one of `values` (compiled as `#define <define> <value>`).
struct Feature {
  std::string_view name;
  std::string_view define;
  std::uint32_t bit;
  std::uint32_t width;
  std::span<const std::string_view> values;
};

// A define every shader of a domain is compiled with (spec "defines", --define, CMake DEFINES).
struct FixedDefine {
  std::string_view name;
  std::string_view value;
};

// The raw ID that `text` names, in the syntax of `shadergen explain`: a number (12, 0x0c,
// 0b1100) below 1 << `raw_bits`, or features by name or define joined by '|', '+' or ','
// (spaces ignored), a valued one as NAME=VALUE; "" is 0. Returns nullopt for an unknown name
// or value, a value given to a boolean feature, or a number out of range. Linear in the text
// and the features; usable at compile time.
constexpr std::optional<std::uint32_t> find_raw_id(std::span<const Feature> features, std::uint32_t raw_bits,
                                                   std::string_view text);

// One compiled permutation (or one non-permuted companion shader).
struct Permutation {
  std::uint32_t id;                           // raw or optimised ID; index for companions
  std::span<const std::string_view> defines;  // GLSL defines it was compiled with
  bool pruned;                                // impossible raw ID: no SPIR-V (spirv is empty)
  std::span<const std::uint32_t> spirv;       // SPIR-V words, validated
  std::string_view hash;                      // content hash of the SPIR-V (hex)
  Reflection reflection;
  // The spec's "program" form: the vertex shader compiled with the same defines (empty
  // otherwise, and for pruned IDs); `spirv` is then the fragment shader.
  std::span<const std::uint32_t> vertex_spirv = {};
  std::string_view vertex_hash = {};
  const Reflection* vertex_reflection = nullptr;
};

// A non-permuted shader compiled alongside the uber-shader (tile vertex shader, compute passes).
struct CompanionShader {
  std::string_view name;
  Stage stage;
  Permutation shader;
};

// Everything one domain spec produced.
struct Registry {
  std::string_view name;  // domain name from the spec
  Stage uber_stage;       // stage of the permuted uber-shader
  // One name per raw feature, in the order of their bits (a valued feature takes several bits
  // but one name): entry i is the feature whose field is i-th from bit 0, not the name of bit i.
  std::span<const std::string_view> raw_feature_names;
  std::span<const std::string_view> optimised_bit_names;  // indexed by optimised bit
  std::span<const std::uint8_t> raw_to_optimised;         // the LUT, one entry per raw ID;
                                                          // empty when the domain is not collapsed
  std::span<const Permutation> raw;                       // indexed by raw ID
  std::span<const Permutation> optimised;                 // indexed by optimised ID
  std::span<const CompanionShader> companions;
  std::span<const DescriptorBinding> pipeline_layout;  // merged over every blob
  std::span<const PushConstantRange> push_constants;   // merged over every blob
  // The spec's "layout": "per_permutation". Then pipeline_layout and push_constants are
  // empty and each permutation's reflection is its own layout.
  bool per_permutation_layout = false;

  // Precondition: raw_id < raw.size(). Returns the permutation a raw ID is drawn with: its
  // optimised permutation, or, in a domain without collapse, the raw permutation itself.
  const Permutation& optimised_for_raw(std::uint32_t raw_id) const {
    return raw_to_optimised.empty() ? raw[raw_id] : optimised[raw_to_optimised[raw_id]];
  }
  // Returns the companion called `name`, or nullptr.
  const CompanionShader* companion(std::string_view wanted) const {
    for (const CompanionShader& c : companions)
      if (c.name == wanted) return &c;
    return nullptr;
  }
};

namespace detail {

constexpr bool is_digit_in(char c, std::uint32_t base) {
  std::uint32_t digit = c >= '0' && c <= '9'   ? static_cast<std::uint32_t>(c - '0')
                        : c >= 'a' && c <= 'f' ? static_cast<std::uint32_t>(c - 'a' + 10)
                        : c >= 'A' && c <= 'F' ? static_cast<std::uint32_t>(c - 'A' + 10)
                                               : 99u;
  return digit < base;
}

// A number in `shadergen explain`'s forms, or nullopt when `text` is not all digits of its base.
constexpr std::optional<std::uint64_t> parse_number(std::string_view text) {
  std::uint32_t base = 10;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X' || text[1] == 'b')) {
    base = text[1] == 'b' ? 2 : 16;
    text.remove_prefix(2);
  }
  std::uint64_t value = 0;
  for (char c : text) {
    if (!is_digit_in(c, base)) return std::nullopt;
    std::uint32_t digit =
        c <= '9' ? static_cast<std::uint32_t>(c - '0') : static_cast<std::uint32_t>((c | 0x20) - 'a' + 10);
    value = value * base + digit;
    if (value > 0xffffffffu) return std::nullopt;
  }
  return value;
}

constexpr std::string_view trim(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

// The bits one term ("NAME" or "NAME=VALUE") sets, or nullopt.
constexpr std::optional<std::uint32_t> term_bits(std::span<const Feature> features, std::string_view term) {
  std::size_t equals = term.find('=');
  std::string_view name = trim(term.substr(0, equals));
  for (const Feature& f : features) {
    if (f.name != name && f.define != name) continue;
    if (equals == std::string_view::npos)
      return f.values.empty() ? std::optional<std::uint32_t>(1u << f.bit) : std::nullopt;
    std::string_view value = trim(term.substr(equals + 1));
    for (std::uint32_t i = 0; i < f.values.size(); ++i)
      if (f.values[i] == value) return i << f.bit;
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace detail

constexpr std::optional<std::uint32_t> find_raw_id(std::span<const Feature> features, std::uint32_t raw_bits,
                                                   std::string_view text) {
  if (std::string_view number_text = detail::trim(text);
      !number_text.empty() && number_text.front() >= '0' && number_text.front() <= '9') {
    auto number = detail::parse_number(number_text);
    if (!number || *number >= (std::uint64_t{1} << raw_bits)) return std::nullopt;
    return static_cast<std::uint32_t>(*number);
  }
  std::uint32_t id = 0;
  while (!text.empty()) {
    std::size_t end = text.find_first_of("|+,");
    std::string_view term = detail::trim(text.substr(0, end));
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    if (term.empty()) continue;
    auto bits = detail::term_bits(features, term);
    if (!bits) return std::nullopt;
    id |= *bits;
  }
  return id;
}

}  // namespace shadergen
