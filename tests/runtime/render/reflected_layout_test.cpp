// Layouts from reflection (runtime/render/src/reflected_layout.h): merging several shaders'
// bindings, and the check of what the runtime binds against them, with their exact messages.
#include "reflected_layout.h"

#include "tilelight/vulkan/error.h"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

namespace tilelight {
namespace {

using shadergen::DescriptorBinding;
using shadergen::DescriptorKind;

constexpr std::uint32_t kVertex = VK_SHADER_STAGE_VERTEX_BIT;
constexpr std::uint32_t kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;

const std::array<DescriptorBinding, 2> kVertexShader{{
    {0, 0, DescriptorKind::uniform_buffer, 1, kVertex, "params"},
    {1, 0, DescriptorKind::combined_image_sampler, 1, kVertex, "height"},
}};
const std::array<DescriptorBinding, 3> kFragmentShader{{
    {0, 2, DescriptorKind::storage_buffer, 1, kFragment, "out"},
    {0, 0, DescriptorKind::uniform_buffer, 1, kFragment, "params"},
    {1, 0, DescriptorKind::combined_image_sampler, 1, kFragment, "albedo"},
}};

TEST(ReflectedLayout, MergesOneSetOfSeveralShadersInBindingOrderWithEveryStage) {
  const std::vector<VkDescriptorSetLayoutBinding> set0 = merged_set_bindings({kVertexShader, kFragmentShader}, 0, "t");
  ASSERT_EQ(set0.size(), 2u);
  EXPECT_EQ(set0[0].binding, 0u);
  EXPECT_EQ(set0[0].descriptorType, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  EXPECT_EQ(set0[0].stageFlags, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  EXPECT_EQ(set0[1].binding, 2u);
  EXPECT_EQ(set0[1].stageFlags, VK_SHADER_STAGE_FRAGMENT_BIT);
  const std::vector<VkDescriptorSetLayoutBinding> set1 = merged_set_bindings({kVertexShader, kFragmentShader}, 1, "t");
  ASSERT_EQ(set1.size(), 1u);
  EXPECT_EQ(set1[0].stageFlags, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
}

TEST(ReflectedLayout, ReflectionsAndBindingSpansMergeAlike) {
  shadergen::Reflection vertex{};
  vertex.bindings = kVertexShader;
  shadergen::Reflection fragment{};
  fragment.bindings = kFragmentShader;
  const std::array<const shadergen::Reflection*, 2> shaders{&vertex, &fragment};
  const std::vector<VkDescriptorSetLayoutBinding> a = merged_set_bindings(shaders, 0, "t");
  const std::vector<VkDescriptorSetLayoutBinding> b = merged_set_bindings({kVertexShader, kFragmentShader}, 0, "t");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].binding, b[i].binding);
    EXPECT_EQ(a[i].descriptorType, b[i].descriptorType);
    EXPECT_EQ(a[i].stageFlags, b[i].stageFlags);
  }
}

TEST(ReflectedLayout, ShadersThatDisagreeOnABindingAreRefusedByName) {
  const std::array<DescriptorBinding, 1> other{{{0, 0, DescriptorKind::storage_buffer, 1, kFragment, "params"}}};
  try {
    merged_set_bindings({kVertexShader, other}, 0, "scene set 0");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "scene set 0: the shaders disagree on set 0 binding 0 (uniform buffer x1 vs storage buffer x1)");
  }
}

struct CheckCase {
  std::string name;
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  std::vector<VkDescriptorType> bound;
  std::string error;  // empty: accepted
};

VkDescriptorSetLayoutBinding binding(std::uint32_t number, VkDescriptorType type, std::uint32_t count = 1) {
  return {number, type, count, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
}

TEST(ReflectedLayout, CheckBindingsAcceptsExactlyWhatTheRuntimeBinds) {
  constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  constexpr VkDescriptorType kSampler = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  const std::vector<CheckCase> cases{
      {"exact", {binding(0, kUniform), binding(1, kSampler)}, {kUniform, kSampler}, ""},
      {"other type",
       {binding(0, kStorage)},
       {kUniform},
       "set: the shaders' reflection declares bindings (0 storage buffer); the runtime binds (0 uniform buffer)"},
      {"one more",
       {binding(0, kUniform), binding(1, kSampler)},
       {kUniform},
       "set: the shaders' reflection declares bindings (0 uniform buffer, 1 combined image sampler); the runtime "
       "binds (0 uniform buffer)"},
      {"a gap",
       {binding(1, kUniform)},
       {kUniform},
       "set: the shaders' reflection declares bindings (1 uniform buffer); the runtime binds (0 uniform buffer)"},
      {"an array",
       {binding(0, kSampler, 4)},
       {kSampler},
       "set: the shaders' reflection declares bindings (0 combined image sampler[4]); the runtime binds (0 "
       "combined image sampler)"},
      {"none",
       {},
       {kUniform},
       "set: the shaders' reflection declares bindings (); the runtime binds (0 uniform buffer)"},
  };
  for (const CheckCase& c : cases) {
    SCOPED_TRACE(c.name);
    if (c.error.empty()) {
      EXPECT_NO_THROW(check_bindings(c.bindings, c.bound, "set"));
      continue;
    }
    try {
      check_bindings(c.bindings, c.bound, "set");
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), c.error);
    }
  }
}

}  // namespace
}  // namespace tilelight
