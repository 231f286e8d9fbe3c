#include "tilelight/vulkan/image.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/formats.h"

#include <fmt/format.h>

#include <utility>

namespace tilelight {
namespace {

// Gives a precise reason instead of letting vkCreateImage fail (or, worse, succeed while
// validation complains) for an unsupported combination.
void check_support(const Context& context, const ImageDesc& desc) {
  if (desc.extent.width == 0 || desc.extent.height == 0) {
    throw Error(fmt::format("image {} has an empty extent {}x{}", desc.name, desc.extent.width, desc.extent.height));
  }
  VkImageFormatProperties props{};
  const VkResult result = vkGetPhysicalDeviceImageFormatProperties(
      context.physical_device(), desc.format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL, desc.usage, 0, &props);
  if (result == VK_ERROR_FORMAT_NOT_SUPPORTED) {
    throw Error(fmt::format("image {}: {} is not supported for usage {:#x} on {}", desc.name, format_name(desc.format),
                            desc.usage, context.device_name()));
  }
  check(result, "vkGetPhysicalDeviceImageFormatProperties", desc.name);
  if ((props.sampleCounts & desc.samples) == 0) {
    throw Error(
        fmt::format("image {}: {} with usage {:#x} does not support {}x samples "
                    "(supported: {})",
                    desc.name, format_name(desc.format), desc.usage, static_cast<unsigned>(desc.samples),
                    sample_counts_text(props.sampleCounts)));
  }
  if (desc.mip_levels == 0 || desc.mip_levels > props.maxMipLevels) {
    throw Error(fmt::format("image {}: {} mip levels; {} supports 1 to {}", desc.name, desc.mip_levels,
                            format_name(desc.format), props.maxMipLevels));
  }
  if (desc.extent.width > props.maxExtent.width || desc.extent.height > props.maxExtent.height) {
    throw Error(fmt::format("image {}: {}x{} exceeds the maximum {}x{} for {}", desc.name, desc.extent.width,
                            desc.extent.height, props.maxExtent.width, props.maxExtent.height,
                            format_name(desc.format)));
  }
}

}  // namespace

Image::Image(const Context& context, ImageDesc desc) : desc_(std::move(desc)) {
  check_support(context, desc_);
  const VkDevice device = context.device();

  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc_.format;
  info.extent = {desc_.extent.width, desc_.extent.height, 1};
  info.mipLevels = desc_.mip_levels;
  info.arrayLayers = 1;
  info.samples = desc_.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc_.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  check(vkCreateImage(device, &info, nullptr, &image), "vkCreateImage", desc_.name);
  image_ = UniqueImage(image, {device});
  context.name_object(image, desc_.name);

  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(device, image, &requirements);
  memory_ = allocate_memory(context, requirements, MemoryUse::DeviceLocal, desc_.name);
  check(vkBindImageMemory(device, image, memory_.get(), 0), "vkBindImageMemory", desc_.name);

  constexpr VkImageUsageFlags kViewUsages =
      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT |
      VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT;
  if ((desc_.usage & kViewUsages) == 0) {
    return;  // a view of a transfer-only image is invalid (VUID-VkImageViewCreateInfo-image-04441)
  }

  VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view_info.image = image;
  view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view_info.format = desc_.format;
  view_info.subresourceRange = subresource_range();
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(device, &view_info, nullptr, &view), "vkCreateImageView", desc_.name);
  view_ = UniqueImageView(view, {device});
  context.name_object(view, desc_.name);
}

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    // Children first, as in the destructor; the defaulted version would free the memory while
    // the old image and view still exist.
    view_.reset();
    image_.reset();
    memory_ = std::move(other.memory_);
    image_ = std::move(other.image_);
    view_ = std::move(other.view_);
    desc_ = std::move(other.desc_);
  }
  return *this;
}

VkImageSubresourceRange Image::subresource_range() const {
  VkImageSubresourceRange range{};
  range.aspectMask = desc_.aspect;
  range.baseMipLevel = 0;
  range.levelCount = desc_.mip_levels;
  range.baseArrayLayer = 0;
  range.layerCount = 1;
  return range;
}

VkImageSubresourceLayers Image::subresource_layers(std::uint32_t mip_level) const {
  VkImageSubresourceLayers layers{};
  layers.aspectMask = desc_.aspect;
  layers.mipLevel = mip_level;
  layers.baseArrayLayer = 0;
  layers.layerCount = 1;
  return layers;
}

}  // namespace tilelight
