#include "compile/layout_check.h"

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
  return std::string(descriptor_kind_name(b.kind)) +
         (b.count > 1 ? std::string("[").append(std::to_string(b.count)).append("]") : "") + " \"" + b.name + "\"";
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

// Disagreements folded as GLSL errors are: one message per distinct disagreement (the first
// blob's side against one other side), counting every blob on the other side and naming a few.
class Disagreements {
 public:
  // `head` names the first blob and what it has ("...: raw 0 has uniform_buffer \"U\""); `verb`
  // and `other` say what `label` has instead.
  void add(const std::string& head, const std::string& verb, const std::string& other, const std::string& label) {
    std::string key = head + '\n' + other;
    auto [it, fresh] = found_.try_emplace(key, Found{head, verb, other, {}});
    if (fresh) {
      if (order_.size() == kMaxMessages) return found_.erase(it), void();  // the first few say enough
      order_.push_back(key);
    }
    it->second.labels.push_back(label);
  }

  Diagnostics messages() const {
    Diagnostics out;
    for (const std::string& key : order_) {
      const Found& f = found_.at(key);
      std::string text = f.head + ", " + f.labels[0] + " " + f.verb + " " + f.other;
      if (f.labels.size() > 1) text += ", as do " + std::to_string(f.labels.size() - 1) + " more (" + examples(f) + ")";
      out.push_back(make_error(text + kPerPermutationHint));
    }
    return out;
  }

 private:
  static constexpr std::size_t kMaxMessages = 8;
  static constexpr std::size_t kMaxExamples = 3;
  struct Found {
    std::string head, verb, other;
    std::vector<std::string> labels;
  };

  static std::string examples(const Found& f) {
    std::string text;
    for (std::size_t i = 1; i < f.labels.size() && i <= kMaxExamples; ++i) text += (i > 1 ? ", " : "") + f.labels[i];
    return f.labels.size() - 1 > kMaxExamples ? text + ", ..." : text;
  }

  std::map<std::string, Found> found_;
  std::vector<std::string> order_;
};

}  // namespace

Result<MergedLayout> merge_layouts(std::span<const LabelledReflection> blobs) {
  struct Seen {
    BindingInfo binding;
    const std::string* label;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, Seen> bindings;
  Disagreements errors;
  // Per stage, the first permutation with a push-constant block, and the first fragment
  // permutation: the others must agree with them.
  std::map<Stage, const LabelledReflection*> first_push;
  const LabelledReflection* first_fragment = nullptr;
  std::uint32_t push_size = 0, push_stages = 0;
  for (const LabelledReflection& blob : blobs) {
    for (const BindingInfo& binding : blob.info->bindings) {
      auto [it, fresh] = bindings.try_emplace({binding.set, binding.binding}, Seen{binding, &blob.label});
      if (fresh) continue;
      BindingInfo& merged = it->second.binding;
      if (merged.kind != binding.kind || merged.count != binding.count) {
        errors.add("permutations disagree on set " + std::to_string(binding.set) + " binding " +
                       std::to_string(binding.binding) + ": " + *it->second.label + " has " + describe(merged),
                   "has", describe(binding), blob.label);
        continue;
      }
      merged.stages |= binding.stages;
    }
    // One rule for every permuted stage, the uber-shader and a program's vertex half alike:
    // its permutations share one block size. Different stages may differ; the range covers
    // the largest.
    std::uint32_t size = blob.info->push_constant_size;
    if (size != 0) {
      if (blob.permuted) {
        auto [first, fresh] = first_push.try_emplace(blob.stage, &blob);
        if (!fresh && first->second->info->push_constant_size != size)
          errors.add("permutations disagree on the push-constant block: " + first->second->label + " has " +
                         std::to_string(first->second->info->push_constant_size) + " bytes",
                     "has", std::to_string(size), blob.label);
      }
      push_size = std::max(push_size, size);
      push_stages |= static_cast<std::uint32_t>(blob.stage);
    }
    // Only a fragment shader's outputs are the pipeline's attachments; what other stages
    // write is the program interface's business (checked between a program's halves).
    if (blob.permuted && blob.stage == Stage::fragment) {
      if (!first_fragment) {
        first_fragment = &blob;
      } else if (first_fragment->info->outputs != blob.info->outputs) {
        errors.add("permutations disagree on their outputs: " + first_fragment->label + " writes " +
                       describe_outputs(first_fragment->info->outputs),
                   "writes", describe_outputs(blob.info->outputs), blob.label);
      }
    }
  }
  if (Diagnostics found = errors.messages(); !found.empty()) return found;
  MergedLayout layout;
  for (auto& [key, seen] : bindings) layout.bindings.push_back(seen.binding);
  if (push_size) layout.push_constants.push_back({push_size, push_stages});
  return layout;
}

}  // namespace shadergen
