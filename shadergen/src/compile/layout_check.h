// layout_check.h - the cross-permutation check: every blob of a domain must fit one pipeline
// layout, because the runtime builds one layout and swaps pipelines per tile class.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "compile/reflection.h"

namespace shadergen {

struct LabelledReflection {
  std::string label;  // "raw 37 (SKY SUN_LIGHT)", "companion tile"
  Stage stage = Stage::fragment;
  // A permutation (of the uber-shader or of a program's vertex half): per stage, permutations
  // agree on their push-constant size, and fragment permutations on their outputs.
  bool permuted = false;
  const ReflectionInfo* info = nullptr;
};

struct PushConstantInfo {
  std::uint32_t size = 0;
  std::uint32_t stages = 0;
};

struct MergedLayout {
  std::vector<BindingInfo> bindings;             // union, sorted by (set, binding); stages OR-ed
  std::vector<PushConstantInfo> push_constants;  // one range covering every stage's block, or none
};

// Fails, naming both blobs, when two blobs give one (set, binding) a different kind or count,
// when permutations of one stage disagree on their push-constant size, or when fragment
// permutations disagree on their outputs (the attachments; other stages' outputs are no part
// of the layout).
Result<MergedLayout> merge_layouts(std::span<const LabelledReflection> blobs);

std::string_view descriptor_kind_name(DescriptorKind kind);

}  // namespace shadergen
