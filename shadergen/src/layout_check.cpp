#include "layout_check.h"

#include <algorithm>
#include <map>

namespace shadergen {

std::string_view descriptor_kind_name(DescriptorKind kind) {
  switch (kind) {
    case DescriptorKind::sampler: return "sampler";
    case DescriptorKind::combined_image_sampler: return "combined_image_sampler";
    case DescriptorKind::sampled_image: return "sampled_image";
    case DescriptorKind::storage_image: return "storage_image";
    case DescriptorKind::uniform_texel_buffer: return "uniform_texel_buffer";
    case DescriptorKind::storage_texel_buffer: return "storage_texel_buffer";
    case DescriptorKind::uniform_buffer: return "uniform_buffer";
    case DescriptorKind::storage_buffer: return "storage_buffer";
    case DescriptorKind::input_attachment: return "input_attachment";
    case DescriptorKind::acceleration_structure: return "acceleration_structure";
  }
  return "?";
}

namespace {

std::string describe(const BindingInfo& b) {
  return std::string(descriptor_kind_name(b.kind)) + (b.count > 1 ? "[" + std::to_string(b.count) + "]" : "") + " \"" +
         b.name + "\"";
}

std::string describe_outputs(const std::vector<VariableInfo>& outputs) {
  std::string text;
  for (const VariableInfo& v : outputs)
    text += (text.empty() ? "" : ", ") + std::string("location ") + std::to_string(v.location) + " vec" +
            std::to_string(v.components);
  return text.empty() ? "none" : text;
}

// A shared layout is a choice, not a rule of the tool: say how to make the other one.
constexpr const char* kPerPermutationHint =
    " (the spec's \"layout\" is \"shared\"; \"layout\": \"per_permutation\" gives each permutation a layout "
    "of its own)";

}  // namespace

Result<MergedLayout> merge_layouts(std::span<const LabelledReflection> blobs) {
  struct Seen {
    BindingInfo binding;
    const std::string* label;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, Seen> bindings;
  Diagnostics errors;
  const LabelledReflection* first_push = nullptr;
  const LabelledReflection* first_permuted = nullptr;
  std::uint32_t push_size = 0, push_stages = 0;
  for (const LabelledReflection& blob : blobs) {
    for (const BindingInfo& binding : blob.info->bindings) {
      auto [it, fresh] = bindings.try_emplace({binding.set, binding.binding}, Seen{binding, &blob.label});
      if (fresh) continue;
      BindingInfo& merged = it->second.binding;
      if (merged.kind != binding.kind || merged.count != binding.count) {
        errors.push_back(make_error("permutations disagree on set " + std::to_string(binding.set) + " binding " +
                                    std::to_string(binding.binding) + ": " + *it->second.label + " has " +
                                    describe(merged) + ", " + blob.label + " has " + describe(binding) +
                                    kPerPermutationHint));
        continue;
      }
      merged.stages |= binding.stages;
    }
    std::uint32_t size = blob.info->push_constant_size;
    if (size != 0) {
      if (blob.permuted && first_push && first_push->permuted && first_push->info->push_constant_size != size)
        errors.push_back(make_error("permutations disagree on the push-constant block: " + first_push->label + " has " +
                                    std::to_string(first_push->info->push_constant_size) + " bytes, " + blob.label +
                                    " has " + std::to_string(size) + kPerPermutationHint));
      if (!first_push || (blob.permuted && !first_push->permuted)) first_push = &blob;
      push_size = std::max(push_size, size);
      push_stages |= static_cast<std::uint32_t>(blob.stage);
    }
    if (blob.permuted) {
      if (!first_permuted) {
        first_permuted = &blob;
      } else if (first_permuted->info->outputs != blob.info->outputs) {
        errors.push_back(make_error("permutations disagree on their outputs: " + first_permuted->label + " writes " +
                                    describe_outputs(first_permuted->info->outputs) + ", " + blob.label + " writes " +
                                    describe_outputs(blob.info->outputs) + kPerPermutationHint));
      }
    }
    if (errors.size() >= 8) break;  // the first few conflicts say enough
  }
  if (!errors.empty()) return errors;
  MergedLayout layout;
  for (auto& [key, seen] : bindings) layout.bindings.push_back(seen.binding);
  if (push_size) layout.push_constants.push_back({push_size, push_stages});
  return layout;
}

}  // namespace shadergen
