#include "tilelight/vulkan/sampler.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <utility>

namespace tilelight {

Sampler::Sampler(const Context& context, SamplerDesc desc) : name_(std::move(desc.name)) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = desc.filter;
  info.minFilter = desc.filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;  // images have one mip level
  info.addressModeU = desc.address;
  info.addressModeV = desc.address;
  info.addressModeW = desc.address;
  info.compareEnable = desc.compare ? VK_TRUE : VK_FALSE;
  info.compareOp = desc.compare_op;
  info.minLod = 0.0f;
  info.maxLod = 0.0f;
  info.borderColor = desc.border;
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(context.device(), &info, nullptr, &sampler), "vkCreateSampler", name_);
  sampler_ = UniqueSampler(sampler, {context.device()});
  context.name_object(sampler, name_);
}

}  // namespace tilelight
