#include "floor_target.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

namespace tilelight {
namespace {

// The usage the other light targets have, so that every pass writes it as it writes theirs.
ImageDesc like_the_naive_target(const RenderTargets& targets) {
  return {targets.extent(),      targets.naive().format(),  targets.naive().usage(),
          VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_COLOR_BIT, "light target (floor)"};
}

}  // namespace

FloorTarget::FloorTarget(const Context& context, const RenderTargets& targets)
    : image_(context, like_the_naive_target(targets)) {
  const VkImageView view = image_.view();
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = targets.light_pass();
  info.attachmentCount = 1;
  info.pAttachments = &view;
  info.width = targets.extent().width;
  info.height = targets.extent().height;
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  check(vkCreateFramebuffer(context.device(), &info, nullptr, &framebuffer), "vkCreateFramebuffer",
        "light target (floor)");
  framebuffer_ = UniqueFramebuffer(framebuffer, {context.device()});
  context.name_object(framebuffer, "light target (floor)");
}

}  // namespace tilelight
