#include "render_targets.h"

#include "pipelines.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <array>
#include <string>
#include <tuple>
#include <vector>

namespace tilelight {
namespace {

constexpr VkPipelineStageFlags kShaderReadStages =
    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;

VkAttachmentDescription attachment(VkFormat format, VkSampleCountFlagBits samples, VkImageLayout final_layout,
                                   VkAttachmentStoreOp store = VK_ATTACHMENT_STORE_OP_STORE) {
  VkAttachmentDescription a{};
  a.format = format;
  a.samples = samples;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = store;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // every frame overwrites the whole target
  a.finalLayout = final_layout;
  return a;
}

// A single-subpass render pass whose outputs are read afterwards by `reader_stages` with
// `reader_access`; the first dependency orders this frame's writes after the previous frame's
// reads of the same images (write-after-read), the second makes the writes visible.
UniqueRenderPass create_render_pass(const Context& context, std::span<const VkAttachmentDescription> attachments,
                                    bool has_depth, VkPipelineStageFlags reader_stages, VkAccessFlags reader_access,
                                    std::string_view name) {
  std::vector<VkAttachmentReference> colour;
  const auto colour_count = static_cast<std::uint32_t>(attachments.size() - (has_depth ? 1 : 0));
  for (std::uint32_t i = 0; i < colour_count; ++i) {
    colour.push_back({i, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
  }
  const VkAttachmentReference depth{colour_count, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = colour_count;
  subpass.pColorAttachments = colour.data();
  subpass.pDepthStencilAttachment = has_depth ? &depth : nullptr;

  const VkPipelineStageFlags output_stages =
      (colour_count > 0 ? VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT : 0) |
      (has_depth ? VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT : 0);
  const VkAccessFlags output_access =
      (colour_count > 0 ? VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT : 0) |
      (has_depth ? VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT : 0);
  std::array<VkSubpassDependency, 2> dependencies{};
  dependencies[0] = {VK_SUBPASS_EXTERNAL, 0, reader_stages, output_stages, 0, output_access, 0};
  dependencies[1] = {0, VK_SUBPASS_EXTERNAL, output_stages, reader_stages, output_access, reader_access, 0};

  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
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

UniqueFramebuffer create_framebuffer(const Context& context, VkRenderPass pass, std::span<const VkImageView> views,
                                     VkExtent2D extent, std::string_view name) {
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = pass;
  info.attachmentCount = static_cast<std::uint32_t>(views.size());
  info.pAttachments = views.data();
  info.width = extent.width;
  info.height = extent.height;
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  check(vkCreateFramebuffer(context.device(), &info, nullptr, &framebuffer), "vkCreateFramebuffer", name);
  UniqueFramebuffer owned(framebuffer, {context.device()});
  context.name_object(framebuffer, name);
  return owned;
}

// The G-buffer's depth-stencil format: kGBufferDepthFormat where the device can render it
// multisampled and sample it, else the fallback (Image then says what the device lacks).
VkFormat choose_gbuffer_depth_format(const Context& context) {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), kGBufferDepthFormat, &properties);
  constexpr VkFormatFeatureFlags kNeeded =
      VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
  return (properties.optimalTilingFeatures & kNeeded) == kNeeded ? kGBufferDepthFormat : kGBufferDepthFallbackFormat;
}

// A view of the stencil aspect alone: sampled as an unsigned integer texture.
UniqueImageView create_stencil_view(const Context& context, const Image& image) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image.handle();
  info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  info.format = image.format();
  info.subresourceRange = {VK_IMAGE_ASPECT_STENCIL_BIT, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(context.device(), &info, nullptr, &view), "vkCreateImageView", "G-buffer stencil view");
  UniqueImageView owned(view, {context.device()});
  context.name_object(view, "G-buffer stencil view");
  return owned;
}

Image gbuffer_image(const Context& context, VkExtent2D extent, VkFormat format, VkSampleCountFlagBits samples,
                    std::string name) {
  return Image(context, {extent, format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, samples,
                         VK_IMAGE_ASPECT_COLOR_BIT, std::move(name)});
}

}  // namespace

RenderTargets::RenderTargets(const Context& context, VkExtent2D extent, VkSampleCountFlagBits samples,
                             std::uint32_t shadow_map_size, bool storage_light_targets)
    : extent_(extent), samples_(samples), shadow_map_size_(shadow_map_size) {
  rt0_ = gbuffer_image(context, extent, kGBufferRt0Format, samples, "G-buffer RT0 (albedo, specular)");
  rt1_ = gbuffer_image(context, extent, kGBufferRt1Format, samples, "G-buffer RT1 (normal, motion ID)");
  rt2_ = gbuffer_image(context, extent, kGBufferRt2Format, samples, "G-buffer RT2 (prelit, power)");
  rt3_ = gbuffer_image(context, extent, kGBufferRt3Format, samples, "G-buffer RT3 (surface depth)");
  if (has_coverage_flags())
    flags_ = gbuffer_image(context, extent, kGBufferTagFormat, samples, "G-buffer RT4 (coverage flags)");
  // The depth test reads the depth within the pass; the local-light passes sample the stencil.
  depth_ = Image(context, {extent, choose_gbuffer_depth_format(context),
                           VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, samples,
                           VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT, "G-buffer depth and stencil"});
  stencil_view_ = create_stencil_view(context, depth_);
  shadow_map_ = Image(context, {{shadow_map_size, shadow_map_size},
                                kDepthFormat,
                                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                VK_SAMPLE_COUNT_1_BIT,
                                VK_IMAGE_ASPECT_DEPTH_BIT,
                                "sun shadow map"});
  VkImageUsageFlags light_usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (storage_light_targets) light_usage |= VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  auto light_target = [&](const char* name) {
    return Image(context, {extent, kLightFormat, light_usage, VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_COLOR_BIT, name});
  };
  classified_ = light_target("light target (classified)");
  naive_ = light_target("light target (naive)");
  dynamic_ = light_target("light target (dynamic)");

  const VkImageLayout read_only = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  create_gbuffer_passes(context);
  const std::array<VkAttachmentDescription, 1> shadow_attachments{
      attachment(kDepthFormat, VK_SAMPLE_COUNT_1_BIT, read_only)};
  shadow_pass_ =
      create_render_pass(context, shadow_attachments, true, kShaderReadStages | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT, "shadow map pass");
  const std::array<VkAttachmentDescription, 1> light_attachments{
      attachment(kLightFormat, VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL)};
  light_pass_ = create_render_pass(context, light_attachments, false, VK_PIPELINE_STAGE_TRANSFER_BIT,
                                   VK_ACCESS_TRANSFER_READ_BIT, "light pass");

  const std::array<VkImageView, 1> shadow_views{shadow_map_.view()};
  shadow_framebuffer_ = create_framebuffer(context, shadow_pass_.get(), shadow_views, shadow_extent(), "shadow map");
  auto light_framebuffer = [&](const Image& target, const char* name) {
    const std::array<VkImageView, 1> views{target.view()};
    return create_framebuffer(context, light_pass_.get(), views, extent, name);
  };
  classified_framebuffer_ = light_framebuffer(classified_, "light target (classified)");
  naive_framebuffer_ = light_framebuffer(naive_, "light target (naive)");
  dynamic_framebuffer_ = light_framebuffer(dynamic_, "light target (dynamic)");
}

// RT0..RT3 (+ RT4 when with_flags) and the depth, whose contents end with the pass: every pass that
// reads the G-buffer reads the colour targets.
void RenderTargets::create_gbuffer_passes(const Context& context) {
  const VkImageLayout read_only = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  auto create = [&](bool with_flags, std::string_view name) {
    std::vector<VkAttachmentDescription> attachments{
        attachment(kGBufferRt0Format, samples_, read_only), attachment(kGBufferRt1Format, samples_, read_only),
        attachment(kGBufferRt2Format, samples_, read_only), attachment(kGBufferRt3Format, samples_, read_only)};
    std::vector<VkImageView> views{rt0_.view(), rt1_.view(), rt2_.view(), rt3_.view()};
    if (with_flags) {
      attachments.push_back(attachment(kGBufferTagFormat, samples_, read_only));
      views.push_back(flags_.view());
    }
    // The depth ends with the pass; the stencil (cleared to 0: needs no lighting) is kept for
    // the local lights. Both paths' G-buffers pay for it alike.
    VkAttachmentDescription depth = attachment(depth_.format(), samples_, read_only, VK_ATTACHMENT_STORE_OP_DONT_CARE);
    depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments.push_back(depth);
    views.push_back(depth_.view());
    UniqueRenderPass pass =
        create_render_pass(context, attachments, true, kShaderReadStages, VK_ACCESS_SHADER_READ_BIT, name);
    UniqueFramebuffer framebuffer = create_framebuffer(context, pass.get(), views, extent_, name);
    return std::pair{std::move(pass), std::move(framebuffer)};
  };
  std::tie(plain_gbuffer_pass_, plain_gbuffer_framebuffer_) = create(false, "G-buffer pass (plain)");
  if (has_coverage_flags()) std::tie(gbuffer_pass_, gbuffer_framebuffer_) = create(true, "G-buffer pass (classified)");
}

VkStencilOpState gbuffer_stencil_marking() {
  VkStencilOpState s{};
  s.failOp = VK_STENCIL_OP_KEEP;
  s.passOp = VK_STENCIL_OP_REPLACE;
  s.depthFailOp = VK_STENCIL_OP_KEEP;
  s.compareOp = VK_COMPARE_OP_ALWAYS;
  s.compareMask = 0xFF;
  s.writeMask = 0xFF;
  s.reference = kStencilLit;
  return s;
}

GraphicsPipelineDesc RenderTargets::gbuffer_pipeline_desc(VkPipelineLayout layout, std::string name,
                                                          bool with_flags) const {
  GraphicsPipelineDesc desc;
  desc.layout = layout;
  desc.render_pass = gbuffer_pass(with_flags);
  desc.samples = samples_;
  desc.fragment_constants.set(0, static_cast<std::uint32_t>(samples_));  // GBUFFER_SAMPLES
  desc.color_attachments = gbuffer_colour_targets(with_flags);
  desc.depth_test = true;
  desc.name = std::move(name);
  return desc;
}

void RenderTargets::begin_gbuffer_pass(VkCommandBuffer cmd, bool with_flags) const {
  // RT1 cleared to motion ID 0 and RT3 to 1.0 read as sky; the sky pass (or the upload)
  // overwrites every pixel anyway, so the colour clear values only matter for debugging.
  const bool flagged = with_flags && has_coverage_flags();
  const std::uint32_t colours = gbuffer_colour_targets(with_flags);
  std::array<VkClearValue, 6> clears{};
  clears[3].color.float32[0] = 1.0f;
  clears[colours].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = gbuffer_pass(with_flags);
  begin.framebuffer = flagged ? gbuffer_framebuffer_.get() : plain_gbuffer_framebuffer_.get();
  begin.renderArea = {{0, 0}, extent_};
  begin.clearValueCount = colours + 1;
  begin.pClearValues = clears.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  set_viewport_and_scissor(cmd, extent_);
}

}  // namespace tilelight
