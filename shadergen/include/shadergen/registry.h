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
//   const shadergen::Registry& registry();
//
// This header has no dependencies beyond the standard library so that runtimes can include it
// without linking shadergen itself.
#pragma once

#include <cstdint>
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
  std::string_view name;                                  // domain name from the spec
  Stage uber_stage;                                       // stage of the permuted uber-shader
  std::span<const std::string_view> raw_feature_names;    // indexed by raw bit
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

}  // namespace shadergen
