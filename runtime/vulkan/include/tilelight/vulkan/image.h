#pragma once
// A 2D image with its own memory and one view covering it. The G-buffer targets, the shadow
// map, the lit result and the tile-ID image are all of this kind.

#include "tilelight/vulkan/memory.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace tilelight {

class Context;

struct ImageDesc {
  VkExtent2D extent{};  // both > 0
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageUsageFlags usage = 0;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  // Aspect of the view (and of barriers and copies): COLOR, or DEPTH for depth formats
  // (a depth view that will be sampled must not include STENCIL).
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  std::string name;
  std::uint32_t mip_levels = 1;  // >= 1; more only for single-sampled images (a sampled texture)
};

class Image {
 public:
  Image() = default;  // empty
  // Checks that the device supports format + usage + samples + extent + mip levels (and says
  // which part it lacks), then creates the image (optimal tiling, desc.mip_levels, one layer, initial layout
  // UNDEFINED), its device-local memory and, when `usage` allows views at all (sampled,
  // storage, or any attachment use), its view. Throws tilelight::Error.
  Image(const Context& context, ImageDesc desc);

  Image(Image&&) noexcept = default;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;
  ~Image() = default;

  VkImage handle() const { return image_.get(); }
  // VK_NULL_HANDLE for transfer-only images, which may not have views.
  VkImageView view() const { return view_.get(); }
  VkFormat format() const { return desc_.format; }
  VkExtent2D extent() const { return desc_.extent; }
  VkSampleCountFlagBits samples() const { return desc_.samples; }
  std::uint32_t mip_levels() const { return desc_.mip_levels; }
  VkImageUsageFlags usage() const { return desc_.usage; }
  VkImageAspectFlags aspect() const { return desc_.aspect; }
  const std::string& name() const { return desc_.name; }

  // The whole image (every mip level, its one layer) in this image's aspect.
  VkImageSubresourceRange subresource_range() const;
  // One mip level (the first by default) of its one layer, for copies.
  VkImageSubresourceLayers subresource_layers(std::uint32_t mip_level = 0) const;

 private:
  ImageDesc desc_;
  // Declaration order = reverse destruction order: view, then image, then memory.
  UniqueDeviceMemory memory_;
  UniqueImage image_;
  UniqueImageView view_;
};

}  // namespace tilelight
