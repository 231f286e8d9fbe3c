#pragma once
// The floor pass's output (Baselines::floor): a single-sampled light target like the naive and
// dynamic ones of RenderTargets (same format, usage, light render pass and layouts), owned
// apart from them because only a renderer that runs the floor pass needs it.

#include "render_targets.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/vk_handles.h"

namespace tilelight {

class Context;

class FloorTarget {
 public:
  // `targets`' extent and light render pass; with `targets`' storage light targets, this one is
  // a storage image as well (the compute light pass).
  FloorTarget(const Context& context, const RenderTargets& targets);

  const Image& image() const { return image_; }
  VkFramebuffer framebuffer() const { return framebuffer_.get(); }  // of RenderTargets::light_pass()

 private:
  Image image_;
  UniqueFramebuffer framebuffer_;
};

}  // namespace tilelight
