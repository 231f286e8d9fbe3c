#include "light_target_pass.h"

#include "render_targets.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <array>
#include <string>
#include <utility>

namespace tilelight {

UniqueRenderPass create_light_target_pass(const Context& context, VkFormat depth_format, std::string_view name) {
  VkAttachmentDescription target{};
  target.format = kLightFormat;
  target.samples = VK_SAMPLE_COUNT_1_BIT;
  target.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  target.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  target.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  target.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  target.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  target.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  VkAttachmentDescription depth{};
  depth.format = depth_format;
  depth.samples = VK_SAMPLE_COUNT_1_BIT;
  depth.loadOp = depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  const bool with_depth = depth_format != VK_FORMAT_UNDEFINED;
  const std::array<VkAttachmentDescription, 2> attachments{target, depth};
  const VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depth_stencil{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
  subpass.pDepthStencilAttachment = with_depth ? &depth_stencil : nullptr;
  // light_target_pass.h says what each dependency waits for.
  constexpr VkPipelineStageFlags kTests =
      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  constexpr VkPipelineStageFlags kBefore = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                           VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                                           kTests;
  constexpr VkPipelineStageFlags kOutput = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  constexpr VkAccessFlags kBlend = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  constexpr VkAccessFlags kDepthStencil =
      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  const std::array<VkSubpassDependency, 2> dependencies{{
      {VK_SUBPASS_EXTERNAL, 0, kBefore, kOutput | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | kTests,
       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
       kBlend | kDepthStencil, 0},
      {0, VK_SUBPASS_EXTERNAL, kOutput, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
       VK_ACCESS_TRANSFER_READ_BIT, 0},
  }};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = with_depth ? 2 : 1;
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<std::uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  VkRenderPass pass = VK_NULL_HANDLE;
  check(vkCreateRenderPass(context.device(), &info, nullptr, &pass), "vkCreateRenderPass", name);
  UniqueRenderPass owned(pass, {context.device()});
  context.name_object(pass, name);
  return owned;
}

std::array<UniqueFramebuffer, 3> create_light_target_framebuffers(const Context& context, VkRenderPass render_pass,
                                                                  const RenderTargets& targets, const Image* depth,
                                                                  std::string_view pass) {
  const std::array<std::pair<const Image*, const char*>, 3> images{
      {{&targets.classified(), "classified"}, {&targets.naive(), "naive"}, {&targets.dynamic(), "dynamic"}}};
  std::array<UniqueFramebuffer, 3> framebuffers;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const std::array<VkImageView, 2> views{images[i].first->view(), depth != nullptr ? depth->view() : VK_NULL_HANDLE};
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = render_pass;
    info.attachmentCount = depth != nullptr ? 2 : 1;
    info.pAttachments = views.data();
    info.width = targets.extent().width;
    info.height = targets.extent().height;
    info.layers = 1;
    const std::string name = std::string(pass) + " into the light target (" + images[i].second + ")";
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    check(vkCreateFramebuffer(context.device(), &info, nullptr, &framebuffer), "vkCreateFramebuffer", name);
    framebuffers[i] = UniqueFramebuffer(framebuffer, {context.device()});
    context.name_object(framebuffer, name);
  }
  return framebuffers;
}

}  // namespace tilelight
