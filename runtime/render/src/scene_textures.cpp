#include "scene_textures.h"

#include "descriptors.h"
#include "pipelines.h"
#include "tilelight/scene/texture_mips.h"
#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/commands.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/submit.h"

#include <array>

namespace tilelight {
namespace {

VkFilter vk_filter(TextureFilter filter) {
  return filter == TextureFilter::nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
}

VkSamplerAddressMode vk_address(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case TextureWrap::mirrored_repeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case TextureWrap::clamp_to_edge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

SamplerDesc sampler_desc(const Texture& texture) {
  const TextureSampling& s = texture.sampling;
  SamplerDesc desc;
  desc.mag_filter = vk_filter(s.magnify);
  desc.min_filter = vk_filter(s.minify);
  desc.mipmap_mode =
      s.between_mips == TextureFilter::nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR;
  desc.max_lod = s.mipmapped ? VK_LOD_CLAMP_NONE : 0.0f;
  desc.address_u = vk_address(s.wrap_u);
  desc.address_v = vk_address(s.wrap_v);
  desc.name = "base colour " + texture.name;
  return desc;
}

Texture white_texture() {
  Texture white;
  white.name = "white (meshes without a base colour texture)";
  white.width = white.height = 1;
  white.rgba = {255, 255, 255, 255};
  white.sampling.magnify = white.sampling.minify = TextureFilter::nearest;
  return white;
}

// Copies every level of `chain`, staged in `staging` from `offsets`, into `image`, leaving it
// ready for fragment-shader reads.
void record_copy(VkCommandBuffer cmd, const Image& image, VkBuffer staging, const std::vector<TextureMip>& chain,
                 const std::vector<VkDeviceSize>& offsets) {
  image_barrier(cmd, image.handle(), image.subresource_range(), VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, {VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0},
                {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
  std::vector<VkBufferImageCopy> copies;
  for (std::uint32_t level = 0; level < chain.size(); ++level) {
    VkBufferImageCopy copy{};
    copy.bufferOffset = offsets[level];
    copy.imageSubresource = image.subresource_layers(level);
    copy.imageExtent = {chain[level].width, chain[level].height, 1};
    copies.push_back(copy);
  }
  vkCmdCopyBufferToImage(cmd, staging, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         static_cast<std::uint32_t>(copies.size()), copies.data());
  image_barrier(cmd, image.handle(), image.subresource_range(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT});
}

}  // namespace

SceneTextures::SceneTextures(const Context& context, const CommandPool& pool, const std::vector<Texture>& textures,
                             std::span<const VkDescriptorSetLayoutBinding> set_bindings) {
  const auto set_count = static_cast<std::uint32_t>(textures.size() + 1);
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, set_count};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = set_count;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  VkDescriptorPool descriptor_pool = VK_NULL_HANDLE;
  check(vkCreateDescriptorPool(context.device(), &pool_info, nullptr, &descriptor_pool), "vkCreateDescriptorPool",
        "base colour textures");
  descriptor_pool_ = UniqueDescriptorPool(descriptor_pool, {context.device()});
  context.name_object(descriptor_pool, "base colour textures");

  set_layout_ = create_descriptor_set_layout(context, set_bindings, "base colour texture set layout");
  textures_.reserve(set_count);
  for (const Texture& texture : textures) textures_.push_back(upload(context, pool, texture));
  textures_.push_back(upload(context, pool, white_texture()));
}

VkDescriptorSet SceneTextures::set_of(std::optional<std::uint32_t> texture) const {
  return texture ? textures_[*texture].set : textures_.back().set;
}

SceneTextures::GpuTexture SceneTextures::upload(const Context& context, const CommandPool& pool,
                                                const Texture& texture) {
  const std::vector<TextureMip> chain = srgb_mip_chain(texture);
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize bytes = 0;
  for (const TextureMip& mip : chain) {
    offsets.push_back(bytes);
    bytes += mip.rgba.size();  // a multiple of 4, as copies from buffers require
  }
  const std::string name = "base colour " + texture.name;
  Buffer staging(context, {bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostUpload, name + " (staging)"});
  for (std::size_t level = 0; level < chain.size(); ++level) {
    staging.write(std::as_bytes(std::span(chain[level].rgba)), offsets[level]);
  }
  GpuTexture gpu;
  gpu.image = Image(context, {.extent = {texture.width, texture.height},
                              .format = VK_FORMAT_R8G8B8A8_SRGB,
                              .usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                              .name = name,
                              .mip_levels = static_cast<std::uint32_t>(chain.size())});
  submit_and_wait(
      context, pool, [&](VkCommandBuffer cmd) { record_copy(cmd, gpu.image, staging.handle(), chain, offsets); },
      "upload of " + name);
  gpu.sampler = Sampler(context, sampler_desc(texture));
  gpu.set = allocate_descriptor_set(context, descriptor_pool_.get(), set_layout_.get(), name);
  write_image_descriptor(context, gpu.set, 0, gpu.sampler.handle(), gpu.image.view(),
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  return gpu;
}

}  // namespace tilelight
