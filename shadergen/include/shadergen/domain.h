// shadergen/domain.h - the domain spec: what a permutation domain is, read from JSON.
//
// A domain is one uber-shader plus N raw features (each a bit of the raw ID and a GLSL define),
// rules that mark impossible raw IDs, and M optimised bits whose rules collapse the 2^N raw IDs
// to 2^M optimised IDs (the lookup table). Each optimised ID is compiled with the defines of a
// set of raw features chosen by "variants" rules, so every optimised permutation is also a raw
// one. Nothing about any particular renderer is built into shadergen; docs/spec-format.md
// describes the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadergen/diagnostic.h"
#include "shadergen/expression.h"
#include "shadergen/registry.h"

namespace shadergen {

// Raw bits, not features: a valued feature takes several. A raw ID is 32 bits wide.
inline constexpr std::uint32_t kMaxRawFeatures = 32;
// Up to 20 raw bits (1,048,576 raw IDs) every raw ID is enumerated. A wider domain names the
// combinations it uses in a variants file, and only those are expanded and built.
inline constexpr std::uint32_t kMaxEnumeratedRawBits = 20;
inline constexpr std::size_t kMaxFeatureValues = 256;  // a valued feature's field: at most 8 bits
inline constexpr std::uint32_t kMaxOptimisedBits = 16;
// Up to 8 optimised bits the lookup table stores optimised IDs as bytes, past that as 16-bit words.
inline constexpr std::uint32_t kMaxByteTableOptimisedBits = 8;
// A variants file lists at most this many lines (combinations, comments and blank lines).
inline constexpr std::size_t kMaxVariantsLines = std::size_t{1} << 22;
inline constexpr std::size_t kMaxCompanions = 64;
inline constexpr std::size_t kMaxUberShaders = 8;
inline constexpr std::size_t kMaxIncludeDirs = 64;
// Rule counts bound the cost of expansion: every impossible rule is evaluated for each of up to
// raw ID expanded, every variant for each optimised ID.
inline constexpr std::size_t kMaxImpossibleRules = 64;
inline constexpr std::size_t kMaxVariants = 256;
// Expansion evaluates every impossible and optimised-bit rule for each raw ID it builds, and
// every variant's rule for each optimised ID: this bounds the IDs times the rules' characters,
// so that no spec (2^20 raw IDs times 64 rules of 1,024 characters took 132 s) keeps the tool
// busy for more than a few seconds.
inline constexpr std::uint64_t kMaxExpansionWork = std::uint64_t{1} << 32;
// A spec reports at most this many problems; a hostile file cannot grow the list without bound.
inline constexpr std::size_t kMaxSpecErrors = 50;

// A rule as written in the spec, with where it was written (for messages).
struct Rule {
  Expression expression;
  std::string text;
  int line = 0;
};

// FeatureKind (registry.h): how a feature reaches the shader (docs/spec-format.md, "Kinds"). A
// variant is compiled into each permutation as a define; a specialization constant is one
// SPIR-V for every value, fixed when the pipeline is created; a branch is one SPIR-V for every
// value, read at run time from a uniform block that shadergen declares. The collapse (optimised
// IDs) is over variants only.

// "variant", "specialization" or "branch".
std::string_view feature_kind_name(FeatureKind kind);

// How a variant feature's define is written: only when on (`#define NAME 1`, today's form), or
// always (`#define NAME 0|1`, or its value), so that `if (NAME)` reads the same under every kind.
enum class DefineStyle { presence, value };

struct RawFeature {
  std::string name;    // e.g. SHADOW_SOLID; the name rules use
  std::uint32_t bit;   // bit in the raw ID (a valued feature's lowest bit)
  std::string define;  // GLSL define the uber-shader tests, e.g. SOLID_SHADOW
  std::string description;
  // Empty: a boolean feature, one bit, `#define NAME 1` when set. Otherwise the values, as
  // written (integers or identifiers): the field of `width` bits from `bit` holds the index
  // of one, compiled as `#define NAME <value>`; indices past the end are pruned.
  std::vector<std::string> values;
  std::uint32_t width = 1;
  std::size_t spec_order = 0;  // its index in the spec's "raw.features" (the generated API's order)
  FeatureKind kind = FeatureKind::variant;
  DefineStyle define_style = DefineStyle::presence;
  // kind == specialization: its `layout(constant_id = K)`, pinned by "constant_id" or the
  // smallest ID no other feature holds, in spec order.
  std::uint32_t constant_id = 0;
  // "unread": "allowed": no check that a source of the domain's permutations reads the define.
  bool unread_allowed = false;
  int define_line = 0;  // where "define" is written, for the unread-define message
  int define_column = 0;

  bool is_variant() const { return kind == FeatureKind::variant; }
  bool valued() const { return !values.empty(); }
  std::uint32_t mask() const { return ((1u << width) - 1u) << bit; }
  // The value index this raw ID holds in the feature's field (may be >= values.size()).
  std::uint32_t index_in(std::uint32_t raw_id) const { return (raw_id >> bit) & ((1u << width) - 1u); }
};

struct ImpossibleSet {
  Rule when;  // over raw feature names
  std::string why;
};

struct OptimisedBit {
  std::string name;  // e.g. SUN_0
  std::uint32_t bit;
  Rule when;  // over raw feature names: set in the optimised ID when true
  std::string description;
};

// "optimised": {"ignore": [...]}: the optimised shader drawn for a raw ID leaves `feature` out
// (off, or its first value) where `when` holds.
struct IgnoreRule {
  std::size_t feature = 0;  // index into DomainSpec::raw_features (a variant feature)
  Rule when;                // over raw features; "true" when the spec gives none
};

// One raw feature as a variant sets it: `bits` within `mask` (a boolean's bit, or a valued
// feature's field holding a value index).
struct FeatureSetting {
  std::uint32_t mask = 0;
  std::uint32_t bits = 0;
};

// "When these optimised bits hold, compile with these raw features' defines."
struct OptimisedVariant {
  Rule when;  // over optimised bit names
  std::vector<FeatureSetting> raw_features;
};

// The Vulkan version a domain's SPIR-V is compiled and validated for. Each implies a SPIR-V
// version: 1.0 for Vulkan 1.0, 1.3 for 1.1, 1.5 for 1.2, 1.6 for 1.3.
enum class TargetEnv { vulkan1_0, vulkan1_1, vulkan1_2, vulkan1_3 };

// "vulkan1.2" for TargetEnv::vulkan1_2, and so on.
std::string_view target_env_name(TargetEnv env);
// The environment called `name` ("vulkan1.0" ... "vulkan1.3"), or false.
bool parse_target_env(std::string_view name, TargetEnv& env);
// "vulkan1.0, vulkan1.1, vulkan1.2 or vulkan1.3", for messages.
std::string_view target_env_choices();

// "compile": which permutations a collapsed domain compiles: every raw one and every optimised
// one ("all", the default), or the optimised ones only ("optimised"): then the registry's raw
// permutations carry no SPIR-V and a runtime draws raw IDs through the lookup table.
enum class CompileSet { all, optimised };

// "layout": one pipeline layout for the whole domain (checked across every permutation), or
// one per permutation (no check: permutations may differ in descriptor kinds and outputs).
enum class LayoutMode { shared, per_permutation };

struct ShaderFile {
  std::filesystem::path path;  // resolved against the spec's folder
  Stage stage = Stage::fragment;
  // Where the spec names it, for messages about the file: "program.fragment",
  // "uber_shader.path" or "companion \"tile\"", and the path value's line and column.
  std::string spec_key;
  int line = 0;
  int column = 0;
};

struct CompanionSpec {
  std::string name;
  ShaderFile file;
  // "NAME" (= 1) or "NAME=VALUE"; they replace a top-level define of the same name.
  std::vector<std::string> defines;
  // True: the companion runs in the uber-shader's pipeline layout (a tile vertex shader), so
  // it takes part in the cross-permutation layout check and the merged layout. False: it
  // has a layout of its own (a compute pass), described only by its own reflection.
  bool shared_layout = true;
  // With "uber_shaders": the entry it is compiled with ("uber_shader": "compute"; default the
  // first): its registry holds the companion, and a shared-layout companion runs in its layout.
  std::string uber_shader;
};

// One entry of "uber_shaders": {"raster": {...}, "compute": {...}}: an uber-shader compiled over
// the domain's permutations. Every entry shares the features, the table and the typed API; each
// has its own blobs, pipeline layout and registry (N::raster::registry()).
struct UberShaderEntry {
  std::string name;  // a C++ identifier: the generated namespace N::<name>
  ShaderFile file;
};

// "branch_block": where the uniform block holding the branch features' values is bound. One
// std140 uint per branch feature, in spec order (offset 4 * i); the block's size rounds up to 16.
struct BranchBlockSpec {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  int line = 0;
};

struct DomainSpec {
  std::filesystem::path spec_path;  // as given by the user
  std::string name;
  std::string description;
  ShaderFile uber;
  // "uber_shaders", in spec order (then `uber` is the first entry's file); empty with
  // "uber_shader" or "program". for_uber_shader() (spec/uber_shader_entries.h) makes the spec
  // one entry compiles.
  std::vector<UberShaderEntry> uber_shaders;
  // Set in the spec for_uber_shader() makes: the entry it compiles (its companions only).
  std::string entry;
  // The "program" form: the vertex half of a permuted vertex + fragment pair (then `uber` is
  // the fragment half). Each permutation compiles both with the same defines, and the
  // fragment inputs must be vertex outputs of the same width.
  std::optional<ShaderFile> program_vertex;
  std::vector<std::filesystem::path> include_dirs;
  TargetEnv target_env = TargetEnv::vulkan1_2;  // "target_env", or build --target-env
  LayoutMode layout = LayoutMode::shared;
  // "strip_debug" (or build --strip-debug): the written blobs lose their debug instructions
  // (names, sources, lines); reflection, the manifest and the registry still have the names.
  bool strip_debug = false;
  CompileSet compile = CompileSet::all;
  // Fixed defines, "NAME=VALUE", in spec order: every shader of the domain (uber-shader and
  // companions) is compiled with them. None names a raw feature's define.
  std::vector<std::string> defines;
  std::vector<CompanionSpec> companions;
  std::vector<RawFeature> raw_features;  // sorted by bit; together they cover bits 0..raw_bits()-1
  std::vector<ImpossibleSet> impossible;
  std::vector<OptimisedBit> optimised_bits;  // indexed by bit
  std::vector<OptimisedVariant> variants;
  // The "ignore" form of the collapse (then optimised_bits and variants are empty): the
  // optimised IDs are the distinct combinations of variant features the raw IDs reach once the
  // ignored features are dropped, numbered in the order of their smallest raw ID (expand()).
  std::vector<IgnoreRule> ignored;
  // False when the spec has no "optimised" section: no collapse, every non-pruned raw ID is
  // compiled as its own permutation and there is no lookup table.
  bool collapsed = true;
  // "variants_file" (resolved against the spec's folder), or build --variants, which wins: the
  // raw combinations the domain builds, one per line (docs/spec-format.md). Empty: every raw
  // ID is enumerated, which needs raw_bits() <= kMaxEnumeratedRawBits.
  std::filesystem::path variants_path;
  int variants_line = 0;  // line of "variants_file" in the spec; 0 when given on the command line
  // The raw IDs the variants file lists, ascending, each once (read_variants_file() fills it).
  std::vector<std::uint32_t> listed_raw_ids;
  std::optional<BranchBlockSpec> branch_block;  // present when a feature is a branch
  // What the spec reader found questionable but not wrong (a "branch_block" with no branch
  // feature: then the block is not declared, so that turning the last branch into a variant
  // stays an edit of its "kind"). Severity::warning, each naming the spec's file and line;
  // `shadergen build`, `lut`, `list` and `explain` print them.
  Diagnostics warnings;

  // Every raw feature in spec order (the generated API's order; raw_features is by bit).
  std::vector<const RawFeature*> features_in_spec_order() const;
  // The branch features in spec order: the members of the branch block.
  std::vector<const RawFeature*> branch_features() const;
  // The specialization-constant features in spec order.
  std::vector<const RawFeature*> specialization_features() const;
  // The bits of every variant feature: what a raw ID's permutation text depends on.
  std::uint32_t variant_mask() const;

  bool listed() const { return !variants_path.empty(); }
  std::uint32_t raw_bits() const;
  // How many raw IDs the bits can hold: 2^raw_bits(), up to 2^32.
  std::uint64_t raw_space() const { return std::uint64_t{1} << raw_bits(); }
  // True for the "ignore" form of the collapse: optimised IDs are numbered, not made of bits.
  bool ignore_form() const { return collapsed && optimised_bits.empty(); }
  // 2^optimised bits when collapsed (at most 65,536), else 0. In the ignore form the count is
  // known only once expanded: then the bound, 65,536 (the plan holds the real count).
  std::uint32_t optimised_count() const {
    return !collapsed ? 0u : ignore_form() ? 1u << kMaxOptimisedBits : 1u << optimised_bits.size();
  }
  // True when the lookup table stores optimised IDs as 16-bit words (more than 8 optimised bits,
  // and always in the ignore form).
  bool wide_table() const { return ignore_form() || optimised_bits.size() > kMaxByteTableOptimisedBits; }
  std::vector<std::string> raw_feature_names() const;
  std::vector<ExpressionSymbol> raw_symbols() const;  // for rules over raw features
  std::vector<std::string> optimised_bit_names() const;
};

// Reads and checks a spec (implemented with the digest the build needs in spec/load_spec.cpp).
// Diagnostics name the spec path and the line of the offending value.
Result<DomainSpec> load_domain(const std::filesystem::path& spec_path);

// Same, from text already read; `spec_path` locates relative paths and names the file in errors.
Result<DomainSpec> parse_domain(std::string_view text, const std::filesystem::path& spec_path);

// "fragment" for Stage::fragment: the spec's, the manifest's and the C++ enum's name.
std::string_view stage_name(Stage stage);
// The file extension (no dot) and glslangValidator -S name of a stage: "frag" for fragment.
std::string_view stage_extension(Stage stage);

}  // namespace shadergen
