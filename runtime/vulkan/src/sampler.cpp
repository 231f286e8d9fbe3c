#include "tilelight/vulkan/sampler.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <utility>

namespace tilelight {

Sampler::Sampler(const Context& context, SamplerDesc desc) : name_(std::move(desc.name)) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = desc.mag_filter;
  info.minFilter = desc.min_filter;
  info.mipmapMode = desc.mipmap_mode;
  info.addressModeU = desc.address_u;
  info.addressModeV = desc.address_v;
  info.addressModeW = desc.address_u;
  info.compareEnable = desc.compare ? VK_TRUE : VK_FALSE;
  info.compareOp = desc.compare_op;
  info.minLod = 0.0f;
  info.maxLod = desc.max_lod;
  info.borderColor = desc.border;
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(context.device(), &info, nullptr, &sampler), "vkCreateSampler", name_);
  sampler_ = UniqueSampler(sampler, {context.device()});
  context.name_object(sampler, name_);
}

}  // namespace tilelight
