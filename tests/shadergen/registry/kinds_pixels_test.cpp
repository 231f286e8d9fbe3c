// The three feature kinds draw the same picture, pixel for pixel: tests/fixtures/kinds/ holds one
// uber-shader with the same features in three specs, SOFT and TAPS compiled in as variants
// (kinds_variant), fixed as specialization constants (kinds_specialization) or read from the
// branch block (kinds_branch). Every raw ID that is not pruned is drawn on lavapipe through each
// registry as a renderer would use it: the variant's own blob; the shared blob with
// specialization_info(specialization(raw_id)); the shared blob with branch_values(raw_id) in the
// branch block (and the latter two again through the optimised blob the raw ID collapses to).
// The images must be byte-identical, and each must hold the colour the features ask for (so a
// constant or branch value the driver ignored fails), under the Khronos validation layer, which
// must stay silent (test::VulkanTest). The vertex shader is the fixture's full_screen companion.
#include "tilelight_testing/test_support.h"

#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/readback.h"
#include "tilelight/vulkan/submit.h"

#include <gtest/gtest.h>
#include <shadergen/vulkan.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <kinds_branch_permutations.h>
#include <kinds_specialization_permutations.h>
#include <kinds_variant_permutations.h>

namespace {

using tilelight::Buffer;
using tilelight::Context;
using tilelight::Image;
using tilelight::test::VulkanTest;

constexpr std::uint32_t kSize = 4;  // 4x4 pixels
constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
// Params.tint: not all 1 (a tint the shader dropped would show), and each channel a power of two
// or a sum of two, so every colour stays exact.
constexpr std::array<float, 4> kTint = {0.5f, 0.75f, 2.0f, 1.0f};

// The colour kinds.frag computes for `raw_id` (the same raw bits in all three domains).
std::array<float, 4> expected_colour(std::uint32_t raw_id) {
  using namespace kinds_variant;
  const bool fog = (raw_id & raw_bit::FOG.value()) != 0;
  const bool soft = (raw_id & raw_bit::SOFT.value()) != 0;
  const std::uint32_t taps_index = (raw_id & raw_bit::TAPS_mask.value()) >> raw_bit::TAPS_shift;
  const bool pbr = ((raw_id & raw_bit::SHADING_mask.value()) >> raw_bit::SHADING_shift) ==
                   static_cast<std::uint32_t>(SHADING_value::PBR);
  const std::array<float, 3> taps = {1.0f, 4.0f, 8.0f};
  float r = 0.125f + (fog ? 0.25f : 0.0f) + (pbr ? 0.5f : 0.0f);
  float g = 0.125f + (soft ? 0.25f : 0.0f);
  float b = 0.125f + taps.at(taps_index) / 16.0f;
  return {r * kTint[0], g * kTint[1], b * kTint[2], kTint[3]};
}

// The shader module of `words`, checked.
tilelight::UniqueShaderModule make_module(const Context& context, std::span<const std::uint32_t> words,
                                          std::string_view name) {
  const VkShaderModuleCreateInfo info = shadergen::vk::shader_module_create_info(words);
  VkShaderModule module = VK_NULL_HANDLE;
  tilelight::check(vkCreateShaderModule(context.device(), &info, nullptr, &module), "vkCreateShaderModule", name);
  return {module, {context.device()}};
}

// A colour render pass that clears to (0, 0, 0, 0), which no draw writes (alpha is kTint[3]),
// and leaves the image ready for the readback's copy.
tilelight::UniqueRenderPass make_render_pass(const Context& context) {
  VkAttachmentDescription attachment{};
  attachment.format = kFormat;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  attachment.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  const VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
  // In: the previous draw's readback copy reads the image this pass clears (write after read).
  // Out: the readback's copy reads what the pass stored.
  const std::array<VkSubpassDependency, 2> dependencies{{
      {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
       VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, 0},
      {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, 0},
  }};
  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = 1;
  info.pAttachments = &attachment;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<std::uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  VkRenderPass pass = VK_NULL_HANDLE;
  tilelight::check(vkCreateRenderPass(context.device(), &info, nullptr, &pass), "vkCreateRenderPass",
                   "the kinds render pass");
  return {pass, {context.device()}};
}

// The 4x4 target every draw renders into, and its framebuffer.
struct Target {
  Image image;
  tilelight::UniqueFramebuffer framebuffer;

  Target(const Context& context, VkRenderPass pass)
      : image(context, {{kSize, kSize},
                        kFormat,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                        VK_SAMPLE_COUNT_1_BIT,
                        VK_IMAGE_ASPECT_COLOR_BIT,
                        "kinds target",
                        1}) {
    const VkImageView view = image.view();
    VkFramebufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    info.renderPass = pass;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = kSize;
    info.height = kSize;
    info.layers = 1;
    VkFramebuffer handle = VK_NULL_HANDLE;
    tilelight::check(vkCreateFramebuffer(context.device(), &info, nullptr, &handle), "vkCreateFramebuffer",
                     "the kinds target");
    framebuffer = {handle, {context.device()}};
  }
};

// Draws one registry's raw IDs: the descriptor sets and pipeline layout from its
// pipeline_layout, Params at set 0 binding 0, the branch block (when the domain has one) at its
// set and binding, and the full_screen companion as the vertex shader.
class KindRenderer {
 public:
  KindRenderer(const Context& context, const tilelight::CommandPool& pool, VkRenderPass pass, const Target& target,
               const shadergen::Registry& registry, const shadergen::BranchBlock& branch_block)
      : context_(context), pool_(pool), pass_(pass), target_(target), registry_(registry) {
    const VkDevice device = context.device();
    const shadergen::CompanionShader* vertex = registry.companion("full_screen");
    if (vertex == nullptr || vertex->stage != shadergen::Stage::vertex || vertex->shader.spirv.empty())
      throw tilelight::Error(std::string(registry.name) + " has no full_screen vertex companion");
    vertex_ = make_module(context, vertex->shader.spirv, "full_screen.vert");

    params_ = Buffer(context, {sizeof(kTint), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, tilelight::MemoryUse::HostUpload,
                               std::string(registry.name) + " Params"});
    params_.write_values(std::span<const float>(kTint));
    if (branch_block.size != 0) {
      branch_ = Buffer(context, {branch_block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                 tilelight::MemoryUse::HostUpload, std::string(registry.name) + " branch block"});
    }

    // Every binding is a uniform buffer: Params, or the branch block.
    const std::span<const shadergen::DescriptorBinding> bindings = registry.pipeline_layout;
    const std::uint32_t set_count = shadergen::vk::descriptor_set_count(bindings);
    std::vector<VkDescriptorSetLayout> raw_layouts;
    for (std::uint32_t set = 0; set < set_count; ++set) {
      const std::vector<VkDescriptorSetLayoutBinding> set_bindings =
          shadergen::vk::descriptor_set_layout_bindings(bindings, set);
      VkDescriptorSetLayoutCreateInfo info{};
      info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
      info.bindingCount = static_cast<std::uint32_t>(set_bindings.size());
      info.pBindings = set_bindings.data();
      VkDescriptorSetLayout layout = VK_NULL_HANDLE;
      tilelight::check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout), "vkCreateDescriptorSetLayout",
                       std::string(registry.name) + " set " + std::to_string(set));
      set_layouts_.push_back(tilelight::UniqueDescriptorSetLayout(layout, {device}));
      raw_layouts.push_back(layout);
    }

    const std::vector<VkPushConstantRange> push = shadergen::vk::push_constant_ranges(registry);
    VkPipelineLayoutCreateInfo layout_info{};
    layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layout_info.setLayoutCount = set_count;
    layout_info.pSetLayouts = raw_layouts.data();
    layout_info.pushConstantRangeCount = static_cast<std::uint32_t>(push.size());
    layout_info.pPushConstantRanges = push.data();
    VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
    tilelight::check(vkCreatePipelineLayout(device, &layout_info, nullptr, &pipeline_layout), "vkCreatePipelineLayout",
                     registry.name);
    pipeline_layout_ = {pipeline_layout, {device}};

    if (set_count == 0) return;
    const VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                         static_cast<std::uint32_t>(bindings.size())};
    VkDescriptorPoolCreateInfo pool_info{};
    pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    pool_info.maxSets = set_count;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &pool_size;
    VkDescriptorPool descriptor_pool = VK_NULL_HANDLE;
    tilelight::check(vkCreateDescriptorPool(device, &pool_info, nullptr, &descriptor_pool), "vkCreateDescriptorPool",
                     registry.name);
    descriptor_pool_ = {descriptor_pool, {device}};
    VkDescriptorSetAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    allocate.descriptorPool = descriptor_pool;
    allocate.descriptorSetCount = set_count;
    allocate.pSetLayouts = raw_layouts.data();
    sets_.resize(set_count);
    tilelight::check(vkAllocateDescriptorSets(device, &allocate, sets_.data()), "vkAllocateDescriptorSets",
                     registry.name);

    std::vector<VkDescriptorBufferInfo> buffer_infos;
    buffer_infos.reserve(bindings.size());  // the writes point into it
    std::vector<VkWriteDescriptorSet> writes;
    for (const shadergen::DescriptorBinding& b : bindings) {
      if (b.kind != shadergen::DescriptorKind::uniform_buffer || b.count != 1)
        throw tilelight::Error(std::string(registry.name) + ": binding " + std::string(b.name) +
                               " is not one uniform buffer");
      const Buffer* buffer = nullptr;
      if (b.set == 0 && b.binding == 0) {
        buffer = &params_;
      } else if (branch_block.size != 0 && b.set == branch_block.set && b.binding == branch_block.binding) {
        buffer = &branch_;
      } else {
        throw tilelight::Error(std::string(registry.name) + ": unexpected binding " + std::string(b.name));
      }
      buffer_infos.push_back({buffer->handle(), 0, VK_WHOLE_SIZE});
      VkWriteDescriptorSet write{};
      write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      write.dstSet = sets_[b.set];
      write.dstBinding = b.binding;
      write.descriptorCount = 1;
      write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      write.pBufferInfo = &buffer_infos.back();
      writes.push_back(write);
    }
    vkUpdateDescriptorSets(device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }

  // Writes `values` into the branch block (the previous draw has finished: submit_and_wait).
  void set_branch_values(const shadergen::BranchValues& values) const {
    ASSERT_EQ(values.size, branch_.size());
    branch_.write(std::as_bytes(std::span(values.words)).first(values.size));
  }

  // Draws `raw_id`'s permutation with `specialization` on the fragment stage (nullptr: none) and
  // returns the image's bytes.
  std::vector<std::byte> draw(std::uint32_t raw_id, const VkSpecializationInfo* specialization) const {
    return draw(registry_.find_raw(shadergen::RawId(raw_id)), "raw " + std::to_string(raw_id), specialization);
  }
  // The same through the optimised permutation a renderer draws `raw_id` with.
  std::vector<std::byte> draw_optimised(std::uint32_t raw_id, const VkSpecializationInfo* specialization) const {
    return draw(registry_.optimised_for_raw(shadergen::RawId(raw_id)), "optimised for raw " + std::to_string(raw_id),
                specialization);
  }

 private:
  std::vector<std::byte> draw(const shadergen::Permutation* permutation, const std::string& what,
                              const VkSpecializationInfo* specialization) const {
    const std::string name = std::string(registry_.name) + " " + what;
    if (permutation == nullptr || permutation->spirv.empty()) throw tilelight::Error(name + ": no SPIR-V");
    const tilelight::UniqueShaderModule fragment = make_module(context_, permutation->spirv, name);
    const tilelight::UniquePipeline pipeline = make_pipeline(fragment.get(), specialization, name);

    tilelight::submit_and_wait(
        context_, pool_,
        [&](VkCommandBuffer cmd) {
          const VkClearValue clear{};
          VkRenderPassBeginInfo begin{};
          begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
          begin.renderPass = pass_;
          begin.framebuffer = target_.framebuffer.get();
          begin.renderArea = {{0, 0}, {kSize, kSize}};
          begin.clearValueCount = 1;
          begin.pClearValues = &clear;
          vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
          vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get());
          if (!sets_.empty())
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_.get(), 0,
                                    static_cast<std::uint32_t>(sets_.size()), sets_.data(), 0, nullptr);
          vkCmdDraw(cmd, 3, 1, 0, 0);
          vkCmdEndRenderPass(cmd);
        },
        "drawing " + name);
    return tilelight::read_image_bytes(context_, pool_, target_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  }

  tilelight::UniquePipeline make_pipeline(VkShaderModule fragment, const VkSpecializationInfo* specialization,
                                          const std::string& name) const {
    std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
    stages[0].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex_.get();
    stages[0].pName = "main";
    stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fragment;
    stages[1].pName = "main";
    stages[1].pSpecializationInfo = specialization;

    VkPipelineVertexInputStateCreateInfo vertex_input{};
    vertex_input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    VkPipelineInputAssemblyStateCreateInfo assembly{};
    assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    const VkViewport viewport{0.0f, 0.0f, static_cast<float>(kSize), static_cast<float>(kSize), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {kSize, kSize}};
    VkPipelineViewportStateCreateInfo viewport_state{};
    viewport_state.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    viewport_state.viewportCount = 1;
    viewport_state.pViewports = &viewport;
    viewport_state.scissorCount = 1;
    viewport_state.pScissors = &scissor;
    VkPipelineRasterizationStateCreateInfo raster{};
    raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{};
    multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineColorBlendAttachmentState blend_attachment{};
    blend_attachment.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{};
    blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    blend.attachmentCount = 1;
    blend.pAttachments = &blend_attachment;

    VkGraphicsPipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    info.stageCount = static_cast<std::uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertex_input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport_state;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pColorBlendState = &blend;
    info.layout = pipeline_layout_.get();
    info.renderPass = pass_;
    info.subpass = 0;
    VkPipeline pipeline = VK_NULL_HANDLE;
    tilelight::check(
        vkCreateGraphicsPipelines(context_.device(), context_.pipeline_cache(), 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines", name);
    return {pipeline, {context_.device()}};
  }

  const Context& context_;
  const tilelight::CommandPool& pool_;
  VkRenderPass pass_;
  const Target& target_;
  const shadergen::Registry& registry_;
  tilelight::UniqueShaderModule vertex_;
  Buffer params_;
  Buffer branch_;
  std::vector<tilelight::UniqueDescriptorSetLayout> set_layouts_;
  tilelight::UniquePipelineLayout pipeline_layout_;
  tilelight::UniqueDescriptorPool descriptor_pool_;
  std::vector<VkDescriptorSet> sets_;  // freed with the pool
};

// The colour of every pixel of `bytes` (R32G32B32A32_SFLOAT), or nullopt when any pixel's bytes
// differ from the first one's.
std::optional<std::array<float, 4>> uniform_colour(const std::vector<std::byte>& bytes) {
  constexpr std::size_t kTexel = sizeof(std::array<float, 4>);
  if (bytes.size() != std::size_t{kSize} * kSize * kTexel) return std::nullopt;
  const std::span<const std::byte> first(bytes.data(), kTexel);
  for (std::size_t at = kTexel; at < bytes.size(); at += kTexel)
    if (!std::equal(first.begin(), first.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at))) return std::nullopt;
  std::array<float, 4> colour{};
  std::memcpy(colour.data(), first.data(), kTexel);
  return colour;
}

// How many distinct SPIR-V blobs the valid raw permutations of `registry` use, by address and by
// content hash (the generated source shares one array per distinct blob).
std::pair<std::size_t, std::size_t> distinct_raw_blobs(const shadergen::Registry& registry) {
  std::set<const std::uint32_t*> addresses;
  std::set<std::string_view> hashes;
  for (const shadergen::Permutation& p : registry.raw) {
    if (p.pruned) continue;
    addresses.insert(p.spirv.data());
    hashes.insert(p.hash);
  }
  return {addresses.size(), hashes.size()};
}

TEST(KindsRegistries, TheThreeDomainsShareRawIdsAndTheKindsShareBlobs) {
  static_assert(kinds_variant::kRawCount == kinds_specialization::kRawCount &&
                kinds_variant::kRawCount == kinds_branch::kRawCount);
  std::size_t valid = 0;
  for (std::uint32_t id = 0; id < kinds_variant::kRawCount; ++id) {
    EXPECT_EQ(kinds_variant::is_valid_raw_id(shadergen::RawId(id)),
              kinds_specialization::is_valid_raw_id(shadergen::RawId(id)))
        << id;
    EXPECT_EQ(kinds_variant::is_valid_raw_id(shadergen::RawId(id)), kinds_branch::is_valid_raw_id(shadergen::RawId(id)))
        << id;
    if (kinds_variant::is_valid_raw_id(shadergen::RawId(id))) ++valid;
  }
  EXPECT_EQ(valid, 18u);  // 32 IDs less 8 without a TAPS value and 6 unlit-with-shadow

  // The variant domain compiles every valid raw ID on its own; the other two only per FOG x
  // SHADING, the features that stay variants.
  const auto variant = distinct_raw_blobs(kinds_variant::registry());
  const auto specialization = distinct_raw_blobs(kinds_specialization::registry());
  const auto branch = distinct_raw_blobs(kinds_branch::registry());
  EXPECT_EQ(variant, std::make_pair(valid, valid));
  EXPECT_EQ(specialization, std::make_pair(std::size_t{4}, std::size_t{4}));
  EXPECT_EQ(branch, std::make_pair(std::size_t{4}, std::size_t{4}));
  EXPECT_LT(specialization.first, variant.first);
  EXPECT_LT(branch.first, variant.first);

  // What each kind hands the renderer besides its blob.
  EXPECT_EQ(kinds_variant::kBranchBlock.size, 0u);
  EXPECT_EQ(kinds_specialization::kBranchBlock.size, 0u);
  EXPECT_EQ(kinds_branch::kBranchBlock.size, 16u);
  EXPECT_EQ(kinds_branch::kBranchBlock.set, 1u);
  EXPECT_EQ(kinds_variant::specialization(shadergen::RawId(0)).value().data_size, 0u);
  EXPECT_EQ(kinds_specialization::specialization(shadergen::RawId(0)).value().data_size, 8u);
  EXPECT_EQ(kinds_branch::specialization(shadergen::RawId(0)).value().data_size, 0u);
}

using KindsPixels = VulkanTest;

TEST_F(KindsPixels, EveryRawIdDrawsTheSameImageInAllThreeKinds) {
  ASSERT_TRUE(context().validation_enabled());
  const tilelight::UniqueRenderPass pass = make_render_pass(context());
  const Target target(context(), pass.get());
  const KindRenderer variant(context(), pool(), pass.get(), target, kinds_variant::registry(),
                             kinds_variant::kBranchBlock);
  const KindRenderer specialized(context(), pool(), pass.get(), target, kinds_specialization::registry(),
                                 kinds_specialization::kBranchBlock);
  const KindRenderer branched(context(), pool(), pass.get(), target, kinds_branch::registry(),
                              kinds_branch::kBranchBlock);

  std::map<std::uint32_t, std::array<float, 4>> colours;  // by raw ID
  for (std::uint32_t id = 0; id < kinds_variant::kRawCount; ++id) {
    if (!kinds_variant::is_valid_raw_id(shadergen::RawId(id))) continue;
    SCOPED_TRACE("raw ID " + std::to_string(id));

    const std::vector<std::byte> from_variant = variant.draw(id, nullptr);

    const shadergen::Specialization constants = kinds_specialization::specialization(shadergen::RawId(id)).value();
    const VkSpecializationInfo info = shadergen::vulkan::specialization_info(constants);
    ASSERT_EQ(info.mapEntryCount, 2u);
    const std::vector<std::byte> from_specialization = specialized.draw(id, &info);

    branched.set_branch_values(kinds_branch::branch_values(shadergen::RawId(id)).value());
    const std::vector<std::byte> from_branch = branched.draw(id, nullptr);

    EXPECT_EQ(from_specialization, from_variant) << "specialization and variant images differ";
    EXPECT_EQ(from_branch, from_variant) << "branch and variant images differ";
    // Collapse keeps FOG and SHADING, the features that stay variants, so the optimised blob a
    // renderer draws the raw ID with, given the same constants or branch values, is exact too.
    EXPECT_EQ(specialized.draw_optimised(id, &info), from_variant) << "optimised specialization image differs";
    EXPECT_EQ(branched.draw_optimised(id, nullptr), from_variant) << "optimised branch image differs";

    const std::optional<std::array<float, 4>> colour = uniform_colour(from_variant);
    ASSERT_TRUE(colour) << "the full-screen triangle left pixels of another colour";
    EXPECT_EQ(*colour, expected_colour(id));
    colours[id] = *colour;
  }

  // Not vacuous: each feature, whatever its kind, moves the colour. Every valid raw ID has its
  // own colour (the fixture's features touch separate channels), and flipping FOG (a variant),
  // SOFT or TAPS (specialization or branch) changes the pixel.
  ASSERT_EQ(colours.size(), 18u);
  std::set<std::array<float, 4>> distinct;
  for (const auto& [id, colour] : colours) distinct.insert(colour);
  EXPECT_EQ(distinct.size(), colours.size());
  using namespace kinds_variant;
  const auto colour_of = [&](const Features& features) { return colours.at(raw_id(features).value().value()); };
  EXPECT_NE(colour_of({.FOG = false, .SHADING = SHADING_value::PBR}),
            colour_of({.FOG = true, .SHADING = SHADING_value::PBR}));
  EXPECT_NE(colour_of({.SOFT = false, .SHADING = SHADING_value::PBR}),
            colour_of({.SOFT = true, .SHADING = SHADING_value::PBR}));
  EXPECT_NE(colour_of({.TAPS = TAPS_value::_1}), colour_of({.TAPS = TAPS_value::_4}));
  EXPECT_NE(colour_of({.TAPS = TAPS_value::_4}), colour_of({.TAPS = TAPS_value::_8}));
}

}  // namespace
