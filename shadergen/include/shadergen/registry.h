// shadergen/registry.h - the types that shadergen's generated C++ registries are made of.
//
// A registry is generated per domain spec (see shadergen_add_permutations() in CMake). Its
// header declares, inside the namespace N chosen at generation time:
//
//   using RawId = shadergen::RawId;  using OptimisedId = shadergen::OptimisedId;
//   using RawBits = shadergen::RawBits;  using OptimisedBits = shadergen::OptimisedBits;
//   inline constexpr std::uint32_t kRawBits;             // raw bits (7 for Split/Second), up to 32
//   inline constexpr std::uint32_t kRawCount;            // raw IDs in the registry: 1 << kRawBits
//                                                        // (128), or those a variants file lists
//   inline constexpr std::uint32_t kOptimisedCount;      // 1 << optimised bits (32), or those the
//                                                        // listed IDs map to; 0: not collapsed
//   Small enumerated domains (at most 65,536 raw IDs, no variants file) only, in the header:
//   inline constexpr std::array<std::uint8_t, kRawCount> kRawToOptimised;  // the lookup table
//                                                        // (absent when the domain is not collapsed;
//                                                        // std::uint16_t past 8 optimised bits)
//   inline constexpr std::array<bool, kRawCount> kRawPruned;               // impossible raw IDs
//   namespace raw_bit       { inline constexpr RawBits <FEATURE>{1u << n}; ...      // boolean
//                             inline constexpr std::uint32_t <FEATURE>_shift = n;     // valued:
//                             inline constexpr RawBits <FEATURE>_mask{...}; }         // its field
//   namespace optimised_bit { inline constexpr OptimisedBits <BIT>{1u << n}; ... }
//   constexpr bool is_valid_raw_id(RawId);              // built: in range, not pruned, listed
//   constexpr std::optional<OptimisedId> optimised_id(RawId);  // checked lookup
//   (Larger or listed domains: the table is in the generated source, and is_valid_raw_id(),
//   optimised_id() and raw_id() are declared here without constexpr.)
//   enum class <FEATURE>_value : std::uint32_t { <value>, ... };  // per valued feature: its values,
//                                                        // an integer 2 spelt _2 (-1: _m1)
//   constexpr std::optional<<FEATURE>_value> to_<FEATURE>(std::int64_t or std::string_view);
//                                                        // a value checked: nullopt if none
//   struct Features { bool <FEATURE> = false; <FEATURE>_value <FEATURE> = ...; ... };
//                                                        // one member per raw feature, in spec order
//   constexpr Features features(RawId);                  // a raw ID decoded (bits past kRawBits ignored)
//   constexpr bool is_possible(const Features&);         // false: an "impossible" rule prunes it, or a
//                                                        // value is out of its enum (every domain)
//   constexpr std::optional<RawId> raw_id(const Features&);  // the raw ID those features
//                                                        // make; nullopt: a value out of its enum, or pruned,
//                                                        // or not built (not in the variants file)
//   inline constexpr std::array<shadergen::Feature, n> kFeatures;           // in spec order
//   inline constexpr std::array<shadergen::FixedDefine, n> kDefines;        // the fixed defines
//   constexpr std::optional<RawId> find_raw_id(std::string_view);  // "A|B=2" -> raw ID; nullopt:
//                                                        // refused, or pruned (not: unbuilt)
//   std::string to_string(RawId);                        // "A | B=2", "(none)": find_raw_id() reads it
//   const shadergen::Registry& registry();
//
// Raw and optimised IDs, and the bits of each, are distinct types: a raw ID where an optimised
// one is wanted, or an optimised bit in a raw ID, does not compile, so a renamed feature cannot
// be silently replaced by the optimised bit of the same name.
//
// shadergen/vulkan.h turns a registry's permutations into Vulkan create-infos; only a consumer
// that includes it needs the Vulkan headers.
//
// This header has no dependencies beyond the standard library so that runtimes can include it
// without linking shadergen itself.
#pragma once

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace shadergen {

// A raw ID: the features a classifier found, one field per raw feature. Its own type so that it
// cannot be passed where an optimised ID is wanted (nor an integer, without saying so): both are
// small integers, and a mix-up would draw a wrong shader without any error. Any value can be
// held; the lookups check it.
class RawId {
 public:
  constexpr explicit RawId(std::uint32_t value) : value_(value) {}
  constexpr std::uint32_t value() const { return value_; }
  friend constexpr bool operator==(RawId, RawId) = default;
  // clang-tidy 14 takes the comparison with 0 that a defaulted <=> implies for a null pointer
  // constant (a known false positive).
  // NOLINTNEXTLINE(modernize-use-nullptr)
  friend constexpr std::strong_ordering operator<=>(RawId, RawId) = default;

 private:
  std::uint32_t value_;
};

// An optimised ID: the permutation a raw ID is drawn with (the lookup table's entry).
class OptimisedId {
 public:
  constexpr explicit OptimisedId(std::uint32_t value) : value_(value) {}
  constexpr std::uint32_t value() const { return value_; }
  friend constexpr bool operator==(OptimisedId, OptimisedId) = default;
  // clang-tidy 14 takes the comparison with 0 that a defaulted <=> implies for a null pointer
  // constant (a known false positive).
  // NOLINTNEXTLINE(modernize-use-nullptr)
  friend constexpr std::strong_ordering operator<=>(OptimisedId, OptimisedId) = default;

 private:
  std::uint32_t value_;
};

// Bits of a raw ID (a generated raw_bit:: constant, or several or-ed together). Distinct from
// OptimisedBits so that raw_bit::X and optimised_bit::X, which often share a name, cannot stand
// in for each other: a raw ID takes raw bits only.
class RawBits {
 public:
  constexpr explicit RawBits(std::uint32_t value) : value_(value) {}
  constexpr std::uint32_t value() const { return value_; }
  constexpr explicit operator bool() const { return value_ != 0; }
  friend constexpr bool operator==(RawBits, RawBits) = default;
  friend constexpr RawBits operator|(RawBits a, RawBits b) { return RawBits(a.value_ | b.value_); }
  friend constexpr RawBits operator&(RawBits a, RawBits b) { return RawBits(a.value_ & b.value_); }
  // The raw ID with these bits set too, and the ones of these that a raw ID has.
  friend constexpr RawId operator|(RawId id, RawBits b) { return RawId(id.value() | b.value_); }
  friend constexpr RawBits operator&(RawId id, RawBits b) { return RawBits(id.value() & b.value_); }

 private:
  std::uint32_t value_;
};

// Bits of an optimised ID (a generated optimised_bit:: constant, or several or-ed together).
class OptimisedBits {
 public:
  constexpr explicit OptimisedBits(std::uint32_t value) : value_(value) {}
  constexpr std::uint32_t value() const { return value_; }
  constexpr explicit operator bool() const { return value_ != 0; }
  friend constexpr bool operator==(OptimisedBits, OptimisedBits) = default;
  friend constexpr OptimisedBits operator|(OptimisedBits a, OptimisedBits b) {
    return OptimisedBits(a.value_ | b.value_);
  }
  friend constexpr OptimisedBits operator&(OptimisedBits a, OptimisedBits b) {
    return OptimisedBits(a.value_ & b.value_);
  }
  friend constexpr OptimisedId operator|(OptimisedId id, OptimisedBits b) { return OptimisedId(id.value() | b.value_); }
  friend constexpr OptimisedBits operator&(OptimisedId id, OptimisedBits b) {
    return OptimisedBits(id.value() & b.value_);
  }

 private:
  std::uint32_t value_;
};

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

// How a raw feature reaches the shader (the spec's "kind"): compiled in as a define (a variant),
// a specialization constant fixed at pipeline creation, or a value the shader reads at run time
// from the domain's branch block. Only variants make permutations of their own.
enum class FeatureKind : std::uint8_t { variant, specialization, branch };

// A raw feature as the generated kFeatures lists it: `width` bits from `bit` of the raw ID.
// A boolean feature has no values (width 1, set: `#define <define> 1`); a valued feature's
// field holds the index of one of `values` (compiled as `#define <define> <value>`).
struct Feature {
  std::string_view name;
  std::string_view define;
  std::uint32_t bit;
  std::uint32_t width;
  std::span<const std::string_view> values;
  FeatureKind kind = FeatureKind::variant;
};

// One specialization feature's place in the specialization data, as VkSpecializationMapEntry
// has it (same members, same layout): constant `constant_id` reads `size` bytes at `offset`.
struct SpecializationMapEntry {
  std::uint32_t constant_id;
  std::uint32_t offset;
  std::size_t size;
};

// The specialization data a raw ID's pipeline is created with (generated N::specialization()):
// one 4-byte value per specialization feature of the domain, in spec order, a VkBool32 (0 or
// 1) for a boolean, an int32 for a valued feature (a numeric value as written, an identifier's
// index). Equal values make equal pipelines, so a renderer keys its pipelines by them.
struct Specialization {
  static constexpr std::size_t kMaxConstants = 32;
  std::span<const SpecializationMapEntry> map;
  std::array<std::uint32_t, kMaxConstants> data{};  // the first map.size() words are used
  std::uint32_t data_size = 0;                      // bytes: 4 * map.size()

  friend constexpr bool operator==(const Specialization& a, const Specialization& b) {
    return a.data_size == b.data_size && a.data == b.data;
  }
};

// The uniform block shadergen declares for the branch features (spec "branch_block"): one std140
// uint per branch feature, in spec order, at `offsets[i]`; `size` bytes (a multiple of 16).
// size == 0: the domain has no branch feature.
struct BranchBlock {
  std::uint32_t set;
  std::uint32_t binding;
  std::uint32_t size;
  std::span<const std::uint32_t> offsets;
};

// The bytes a raw ID's branch block holds (generated N::branch_values()): word i is the value of
// branch feature i (as Specialization::data writes it), the rest zero up to `size`.
struct BranchValues {
  static constexpr std::size_t kMaxWords = 32;
  std::array<std::uint32_t, kMaxWords> words{};
  std::uint32_t size = 0;  // bytes to upload: BranchBlock::size

  friend constexpr bool operator==(const BranchValues& a, const BranchValues& b) {
    return a.size == b.size && a.words == b.words;
  }
};

// A define every shader of a domain is compiled with (spec "defines", --define, CMake DEFINES).
struct FixedDefine {
  std::string_view name;
  std::string_view value;
};

// One compiled permutation (or one non-permuted companion shader).
struct Permutation {
  std::uint32_t id;                           // raw or optimised ID; index for companions
  std::span<const std::string_view> defines;  // GLSL defines it was compiled with
  bool pruned;                                // impossible raw ID: no SPIR-V (spirv is empty)
  // SPIR-V words, validated. Empty when pruned, and for every raw permutation of a domain that
  // compiles only its optimised ones ("compile": "optimised"): those are drawn through the table.
  std::span<const std::uint32_t> spirv;
  std::string_view hash;  // content hash of the SPIR-V (hex)
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

// Where the record of ID `id` is in `list`, or nullopt: constant time when the list is
// enumerated (list[i].id == i), else a binary search. Precondition: `list` ascends by `id`.
// Generic over the record so that shadergen's own plan (spec/permutations.h) searches the same
// way as a registry does; `List` is a span or vector of records with an `id` member.
template <class List>
constexpr std::optional<std::size_t> position_by_id(const List& list, std::uint32_t id) {
  if (id < list.size() && list[id].id == id) return id;  // enumerated: the ID is the position
  std::size_t low = 0, high = list.size();
  while (low < high) {
    const std::size_t middle = low + (high - low) / 2;
    if (list[middle].id < id)
      low = middle + 1;
    else
      high = middle;
  }
  if (low == list.size() || list[low].id != id) return std::nullopt;
  return low;
}

// Everything one domain spec produced.
struct Registry {
  std::string_view name;  // domain name from the spec
  Stage uber_stage;       // stage of the permuted uber-shader
  // One name per raw feature, in the order of their bits (a valued feature takes several bits
  // but one name): entry i is the feature whose field is i-th from bit 0, not the name of bit i.
  std::span<const std::string_view> raw_feature_names;
  std::span<const std::string_view> optimised_bit_names;  // indexed by optimised bit
  // The LUT with at most 8 optimised bits: entry i is raw[i]'s optimised ID. Empty when the
  // domain is not collapsed or has more bits (then raw_to_optimised_wide holds it).
  std::span<const std::uint8_t> raw_to_optimised;
  // Ascending by raw ID: every raw ID of an enumerated domain, so that raw[id].id == id, or the
  // IDs a variants file lists. Unchecked, like the spans above: for an ID from outside (a
  // classifier, a file, a cast), use find_raw(), optimised_id() or optimised_for_raw().
  std::span<const Permutation> raw;
  // Ascending by optimised ID: every one (optimised[id].id == id), or with a variants file the
  // ones the listed raw IDs map to. find_optimised() looks one up by ID.
  std::span<const Permutation> optimised;
  std::span<const CompanionShader> companions;
  std::span<const DescriptorBinding> pipeline_layout;  // merged over every blob
  std::span<const PushConstantRange> push_constants;   // merged over every blob
  // The spec's "layout": "per_permutation". Then pipeline_layout and push_constants are
  // empty and each permutation's reflection is its own layout.
  bool per_permutation_layout = false;
  // The LUT with more than 8 optimised bits (up to 16): entry i is raw[i]'s optimised ID.
  std::span<const std::uint16_t> raw_to_optimised_wide = {};

  // The lookups by ID. Each checks the ID, so an ID from outside can never read past a table:
  // one outside the domain, pruned (no shader) or not built (not in a variants file) is "none".

  // Where `raw_id` is in `raw`, or nullopt: constant time when enumerated, else a binary search.
  constexpr std::optional<std::size_t> raw_position(RawId raw_id) const { return position_by_id(raw, raw_id.value()); }
  // The raw permutation `raw_id` names, or nullptr when it is out of range, pruned or not built.
  constexpr const Permutation* find_raw(RawId raw_id) const {
    std::optional<std::size_t> at = raw_position(raw_id);
    if (!at || raw[*at].pruned) return nullptr;
    return &raw[*at];
  }
  // The optimised permutation `id`, or nullptr when the registry has none of that ID.
  constexpr const Permutation* find_optimised(OptimisedId id) const {
    std::optional<std::size_t> at = position_by_id(optimised, id.value());
    return at ? &optimised[*at] : nullptr;
  }
  // True when the domain is collapsed: raw IDs are drawn through the lookup table.
  constexpr bool collapsed() const { return !raw_to_optimised.empty() || !raw_to_optimised_wide.empty(); }
  // The optimised ID `raw_id` is drawn with, or nullopt when find_raw() is nullptr (or its table
  // entry names no optimised permutation, which a generated registry never holds). In a domain
  // without collapse every raw ID is its own permutation: the raw ID's value itself.
  constexpr std::optional<OptimisedId> optimised_id(RawId raw_id) const {
    std::optional<std::size_t> at = raw_position(raw_id);
    if (!at || raw[*at].pruned) return std::nullopt;
    if (!collapsed()) return OptimisedId(raw_id.value());
    std::uint32_t id = 0;
    if (!raw_to_optimised.empty()) {
      if (*at >= raw_to_optimised.size()) return std::nullopt;
      id = raw_to_optimised[*at];
    } else {
      if (*at >= raw_to_optimised_wide.size()) return std::nullopt;
      id = raw_to_optimised_wide[*at];
    }
    if (!find_optimised(OptimisedId(id))) return std::nullopt;
    return OptimisedId(id);
  }
  // The permutation `raw_id` is drawn with: its optimised permutation, or, in a domain without
  // collapse, the raw permutation itself; nullptr when optimised_id() is nullopt.
  constexpr const Permutation* optimised_for_raw(RawId raw_id) const {
    std::optional<OptimisedId> id = optimised_id(raw_id);
    if (!id) return nullptr;
    return collapsed() ? find_optimised(*id) : find_raw(raw_id);
  }
  // Returns the companion called `name`, or nullptr.
  const CompanionShader* companion(std::string_view wanted) const {
    for (const CompanionShader& c : companions)
      if (c.name == wanted) return &c;
    return nullptr;
  }
};

// ---------------------------------------------------------------------------------------------
// Raw IDs as text: the one grammar that the generated find_raw_id(), `shadergen explain` and
// variants files read, so a text means the same wherever it is written.
//
//   text     = "" | "(none)" | word *( "|" word )     blanks (spaces, tabs) around any token
//   word     = NAME                  a boolean feature: on (a feature left out is off)
//            | NAME "=" VALUE        a valued feature: VALUE exactly as the spec's "values" writes it
//
// NAME is a feature's name, never its define. "" and "(none)" are raw ID 0, every feature off
// (what describe_raw() prints for 0). A valued feature left out holds its first value (index 0).
// Everything else is refused, naming the offending word, so that a typo never becomes a
// different shader: a number, a define, a value given to a boolean (SKY=0 would otherwise
// read as "on"), a valued feature without its value, a feature named twice, an empty word.

// Why parse_combination() refused a text. Each names ParsedCombination::word.
enum class CombinationError : std::uint8_t {
  none,
  empty_word,          // "A||B", "A|", "|A", "=2": no feature name where one belongs
  unknown_name,        // no feature is called `word`
  define_name,         // `word` is the define of features[feature], not a feature name
  number,              // `word` is a raw number (12, 0x5, 0b11): texts name features
  boolean_with_value,  // `word` ("SKY=1") gives boolean features[feature] a value
  missing_value,       // `word` names valued features[feature] without "=value"
  unknown_value,       // `word` is none of features[feature]'s values
  repeated,            // `word` names features[feature] a second time
};

// The raw ID a text names, or why it names none.
struct ParsedCombination {
  std::uint32_t raw_id = 0;  // 0 on error
  CombinationError error = CombinationError::none;
  // The offending part of the text, blanks trimmed (a view into it; empty when error is none):
  // the name for unknown_name, define_name, number and missing_value, the value for
  // unknown_value, the whole word ("SKY=1") for boolean_with_value, repeated and empty_word.
  std::string_view word;
  std::size_t position = 0;  // offset of `word` in the text, for a caret or a column
  std::size_t feature = 0;   // index into the features, for the errors about one feature
  constexpr explicit operator bool() const { return error == CombinationError::none; }
};

namespace detail {

constexpr bool is_blank(char c) { return c == ' ' || c == '\t'; }

constexpr bool is_digit_in(char c, std::uint32_t base) {
  std::uint32_t digit = c >= '0' && c <= '9'   ? static_cast<std::uint32_t>(c - '0')
                        : c >= 'a' && c <= 'f' ? static_cast<std::uint32_t>(c - 'a' + 10)
                        : c >= 'A' && c <= 'F' ? static_cast<std::uint32_t>(c - 'A' + 10)
                                               : 99u;
  return digit < base;
}

// True for a whole number as `shadergen explain` takes one: 12, 0x0c, 0b1100 (any size).
constexpr bool is_number(std::string_view word) {
  std::uint32_t base = 10;
  if (word.size() > 2 && word[0] == '0' && (word[1] == 'x' || word[1] == 'X' || word[1] == 'b' || word[1] == 'B')) {
    base = word[1] == 'b' || word[1] == 'B' ? 2 : 16;
    word.remove_prefix(2);
  }
  if (word.empty()) return false;
  for (char c : word)
    if (!is_digit_in(c, base)) return false;
  return true;
}

// The bits of a feature's field. 64-bit, so that a field reaching bit 31 shifts safely.
constexpr std::uint32_t field_mask(const Feature& f) {
  return static_cast<std::uint32_t>(((std::uint64_t{1} << f.width) - 1u) << f.bit);
}

// One pass over a text: each '|'-separated word is checked alone, then against the words
// before it (a feature named twice).
class CombinationParser {
 public:
  constexpr CombinationParser(std::span<const Feature> features, std::string_view text)
      : features_(features), text_(text) {}

  constexpr ParsedCombination run() {
    const Range all = trimmed(0, text_.size());
    if (all.empty() || slice(all) == "(none)") return result_;
    for (std::size_t start = 0;;) {
      const std::size_t bar = text_.find('|', start);
      const std::size_t end = bar == std::string_view::npos ? text_.size() : bar;
      if (!add_word(trimmed(start, end))) return result_;
      if (bar == std::string_view::npos) return result_;
      start = bar + 1;
    }
  }

 private:
  struct Range {
    std::size_t begin = 0;
    std::size_t end = 0;
    constexpr bool empty() const { return begin == end; }
  };
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  constexpr Range trimmed(std::size_t begin, std::size_t end) const {
    while (begin < end && is_blank(text_[begin])) ++begin;
    while (end > begin && is_blank(text_[end - 1])) --end;
    return {begin, end};
  }
  constexpr std::string_view slice(Range r) const { return text_.substr(r.begin, r.end - r.begin); }

  // Where the word's first '=' is, or its end when it has none.
  constexpr std::size_t equals_in(Range word) const {
    const std::size_t at = slice(word).find('=');
    return at == std::string_view::npos ? word.end : word.begin + at;
  }

  // The feature whose name (or, with `by_define`, whose define) is `word`, or kNone.
  constexpr std::size_t index_of(std::string_view word, bool by_define) const {
    for (std::size_t i = 0; i < features_.size(); ++i)
      if ((by_define ? features_[i].define : features_[i].name) == word) return i;
    return kNone;
  }

  constexpr bool fail(CombinationError error, Range word, std::size_t feature = 0) {
    result_ = {0, error, slice(word), word.begin, feature};
    return false;
  }

  // Adds what one word names to the raw ID; false (with result_ saying why) when it is refused.
  constexpr bool add_word(Range word) {
    if (word.empty()) return fail(CombinationError::empty_word, word);
    const std::size_t equals = equals_in(word);
    const Range name = trimmed(word.begin, equals);
    if (name.empty()) return fail(CombinationError::empty_word, word);
    const std::size_t index = index_of(slice(name), false);
    if (index == kNone) return fail_unknown(name);
    const Feature& f = features_[index];
    std::optional<std::uint32_t> bits =
        f.values.empty() ? boolean_bits(f, word, equals, index) : valued_bits(f, word, name, equals, index);
    if (!bits) return false;
    if (seen_ & field_mask(f)) return fail(CombinationError::repeated, word, index);
    seen_ |= field_mask(f);
    result_.raw_id |= *bits;
    return true;
  }

  // Says what an unknown name is instead: some feature's define, a number, or nothing.
  constexpr bool fail_unknown(Range name) {
    if (const std::size_t of = index_of(slice(name), true); of != kNone)
      return fail(CombinationError::define_name, name, of);
    return fail(is_number(slice(name)) ? CombinationError::number : CombinationError::unknown_name, name);
  }

  constexpr std::optional<std::uint32_t> boolean_bits(const Feature& f, Range word, std::size_t equals,
                                                      std::size_t index) {
    if (equals != word.end) {
      fail(CombinationError::boolean_with_value, word, index);
      return std::nullopt;
    }
    return static_cast<std::uint32_t>(std::uint64_t{1} << f.bit);
  }

  constexpr std::optional<std::uint32_t> valued_bits(const Feature& f, Range word, Range name, std::size_t equals,
                                                     std::size_t index) {
    if (equals == word.end) {
      fail(CombinationError::missing_value, name, index);
      return std::nullopt;
    }
    const Range value = trimmed(equals + 1, word.end);
    for (std::size_t i = 0; i < f.values.size(); ++i)
      if (f.values[i] == slice(value)) return static_cast<std::uint32_t>(std::uint64_t{i} << f.bit);
    fail(CombinationError::unknown_value, value, index);
    return std::nullopt;
  }

  std::span<const Feature> features_;
  std::string_view text_;
  ParsedCombination result_;
  std::uint32_t seen_ = 0;  // the fields of the features named so far
};

}  // namespace detail

// Reads `text` in the grammar above against `features` (a domain's kFeatures). Precondition:
// each feature's field fits a 32-bit raw ID (bit + width <= 32). Linear in the text times the
// features; usable at compile time.
constexpr ParsedCombination parse_combination(std::span<const Feature> features, std::string_view text) {
  return detail::CombinationParser(features, text).run();
}

// `raw_id` in the grammar above, exactly as `shadergen explain` prints it: the features that are
// on (a valued one with its value, "?" for an index past its values) in the order of their bits,
// joined by " | "; "(none)" for no feature. parse_combination() reads it back to `raw_id`
// whenever every field holds a value and no bit outside the features is set. Precondition: each
// feature's field fits a 32-bit raw ID, and no two features share a bit.
inline std::string combination_text(std::span<const Feature> features, std::uint32_t raw_id) {
  std::string text;
  // kFeatures is in spec order; explain prints in bit order. At most 32 features: a selection
  // of the next bit each time is simpler than a sorted copy.
  std::uint64_t next_bit = 0;
  for (std::size_t n = 0; n < features.size(); ++n) {
    const Feature* f = nullptr;
    for (const Feature& candidate : features)
      if (candidate.bit >= next_bit && (!f || candidate.bit < f->bit)) f = &candidate;
    if (!f) break;
    next_bit = std::uint64_t{f->bit} + 1;
    const std::uint32_t index = (raw_id & detail::field_mask(*f)) >> f->bit;
    if (f->values.empty() && index == 0) continue;
    if (!text.empty()) text += " | ";
    text += f->name;
    if (!f->values.empty()) {
      text += '=';
      text += index < f->values.size() ? f->values[index] : std::string_view("?");
    }
  }
  return text.empty() ? std::string("(none)") : text;
}

// The raw ID `text` names, or nullopt when parse_combination() refuses it (which says why).
// A pruned combination is named like any other: the lookups by raw ID then say "none".
constexpr std::optional<std::uint32_t> find_raw_id(std::span<const Feature> features, std::string_view text) {
  ParsedCombination parsed = parse_combination(features, text);
  if (!parsed) return std::nullopt;
  return parsed.raw_id;
}

}  // namespace shadergen
