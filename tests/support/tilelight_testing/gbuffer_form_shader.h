#pragma once
// The test domains gbuffer_dump.json and gbuffer_upload.json have one dimension, the G-buffer's
// form (SINGLE_SAMPLED): each pass takes the shader of its renderer's form from its registry.

#include "tilelight/vulkan/error.h"

#include <shadergen/registry.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tilelight {

// The permutation `raw_id` (the domain's raw_id() of the wanted form) of `registry`; throws
// tilelight::Error naming `domain` when it has none.
inline const shadergen::Permutation& gbuffer_form_shader(const shadergen::Registry& registry,
                                                         std::optional<shadergen::RawId> raw_id,
                                                         std::string_view domain) {
  const shadergen::Permutation* shader = raw_id ? registry.find_raw(*raw_id) : nullptr;
  if (shader == nullptr) throw Error("the test domain " + std::string(domain) + " has no shader for this G-buffer");
  return *shader;
}

}  // namespace tilelight
