#pragma once
// The runtime's non-permuted shaders (classification, index build, scene, tile vertex shader)
// come from the generated registry as companions of the Split/Second domain.

#include <cstdint>
#include <span>
#include <string_view>

namespace tilelight {

// The SPIR-V of companion `name`; throws tilelight::Error if the registry has none by that name.
std::span<const std::uint32_t> companion_spirv(std::string_view name);

}  // namespace tilelight
