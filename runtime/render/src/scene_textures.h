#pragma once
// The scene's base colour textures on the GPU: each an sRGB image with its full mip chain
// (made on the CPU, tilelight/scene/texture_mips.h) and its sampler, in a descriptor set of
// its own (set 1 of the G-buffer pipeline, binding 0); plus a 1x1 white texture for meshes
// without one, so every draw binds a set and untextured albedo is multiplied by exactly 1.

#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/sampler.h"
#include "tilelight/vulkan/vk_handles.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace tilelight {

class CommandPool;
class Context;

class SceneTextures {
 public:
  // Uploads every texture (a submit each, waited for) and writes the sets. Throws tilelight::Error
  // naming the texture if the device cannot hold it. `set_bindings`: the texture set's layout as
  // the material shaders' reflection declares it; precondition: one combined image sampler at
  // binding 0 (what this class writes).
  SceneTextures(const Context& context, const CommandPool& pool, const std::vector<Texture>& textures,
                std::span<const VkDescriptorSetLayoutBinding> set_bindings);

  // The layout of each texture's set.
  VkDescriptorSetLayout set_layout() const { return set_layout_.get(); }

  // The set of texture `texture` (an index into the scene's textures), or the white one.
  // Precondition: texture < the number of textures given.
  VkDescriptorSet set_of(std::optional<std::uint32_t> texture) const;

 private:
  struct GpuTexture {
    Image image;
    Sampler sampler;
    VkDescriptorSet set = VK_NULL_HANDLE;
  };
  GpuTexture upload(const Context& context, const CommandPool& pool, const Texture& texture);

  UniqueDescriptorPool descriptor_pool_;
  UniqueDescriptorSetLayout set_layout_;
  std::vector<GpuTexture> textures_;  // the scene's, then the white one
};

}  // namespace tilelight
