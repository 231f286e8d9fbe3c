#pragma once
// The render pass of every pass that draws into a light target after the global pass: the local
// lights (local_light_passes.h) and the forward pass for blended materials (forward_pass.h).
// Colour attachment 0 is the light target, loaded and stored: the pass adds or blends onto what
// the global pass wrote, which left it (as this pass leaves it) in TRANSFER_SRC_OPTIMAL for the
// read-back. With a `depth_format`, attachment 1 is a single-sampled depth and stencil of the
// pass's own (the light volumes' resolved depth, the forward pass's depth copy), cleared (depth
// 1, stencil 0) and dropped at the end; VK_FORMAT_UNDEFINED: no depth attachment.
//
// Dependencies: in, after the global pass's writes (draws, or compute and its barrier to the
// transfer stage), the G-buffer's (made visible to fragment reads by its own pass), and the
// previous target's pass's depth and stencil tests (the depth image is reused); out, to the
// read-back (transfer) as the global pass's own dependency does.

#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <array>
#include <string_view>

namespace tilelight {

class Context;
class Image;
class RenderTargets;

// Throws tilelight::Error (naming `name`) if the device refuses it.
UniqueRenderPass create_light_target_pass(const Context& context, VkFormat depth_format, std::string_view name);

// The framebuffers of such a pass over each light target, in LocalLightTarget's order
// (classified, naive, dynamic), each with `depth` as attachment 1 (null: no depth attachment).
// `pass` names them ("<pass> into the light target (naive)").
std::array<UniqueFramebuffer, 3> create_light_target_framebuffers(const Context& context, VkRenderPass render_pass,
                                                                  const RenderTargets& targets, const Image* depth,
                                                                  std::string_view pass);

}  // namespace tilelight
