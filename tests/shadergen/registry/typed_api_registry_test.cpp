// The generated API's contract, compiled as a consumer compiles it (tests/fixtures/typed_api:
// features listed out of bit order, integer, negative and identifier values, fixed defines
// from the spec and from CMake's DEFINES, one quoted): Features with designated initializers
// in spec order, raw_id() (checked: a cast enum value gives none), the value enums, kFeatures,
// kDefines, find_raw_id() round trips for every raw ID in the one grammar, the checked lookups
// by raw ID, and shadergen/vulkan.h's create-infos checked against the manifest and handed
// to a real driver (lavapipe in CI; skipped where the machine has no Vulkan device).
#include <gtest/gtest.h>
#include <shadergen/vulkan.h>

#include "registry_lookups.h"

#include <bit>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <type_traits>

#include <typed_api_permutations.h>

namespace {

using namespace typed_api;

// Designated initializers follow the spec's order: TONEMAP, SHARPEN, QUALITY, BIAS.
constexpr Features kAcesSharpHigh{
    .TONEMAP = TONEMAP_value::ACES, .SHARPEN = true, .QUALITY = QUALITY_value::_2, .BIAS = BIAS_value::_1};
static_assert(raw_id(kAcesSharpHigh) == RawId((1u << 3) | 1u | (2u << 1) | (1u << 5)));
static_assert(raw_id({}) == RawId(0), "every feature's default is its first value");
static_assert(raw_id({.QUALITY = QUALITY_value::_1}) == RawId(2));
static_assert(static_cast<std::uint32_t>(BIAS_value::_m1) == 0u && static_cast<std::uint32_t>(BIAS_value::_1) == 1u);
static_assert(static_cast<std::uint32_t>(TONEMAP_value::FILMIC) == 2u);
static_assert(find_raw_id("TONEMAP=ACES|SHARPEN|QUALITY=2|BIAS=1") == raw_id(kAcesSharpHigh));
static_assert(std::is_aggregate_v<Features>);
// A value cast from outside its enum is no raw ID: QUALITY has 3 values in a 2-bit field (3
// fits the field but names no value), TONEMAP 7 and BIAS 2 would spill into the next field.
static_assert(raw_id({.QUALITY = static_cast<QUALITY_value>(3)}) == std::nullopt);
static_assert(raw_id({.TONEMAP = static_cast<TONEMAP_value>(7)}) == std::nullopt);
static_assert(raw_id({.BIAS = static_cast<BIAS_value>(2)}) == std::nullopt);
static_assert(raw_id({.BIAS = static_cast<BIAS_value>(0xffffffffu)}) == std::nullopt);

TEST(TypedApi, FeaturesAreListedInSpecOrder) {
  ASSERT_EQ(kFeatures.size(), 4u);
  const shadergen::Feature& tonemap = kFeatures[0];
  EXPECT_EQ(tonemap.name, "TONEMAP");
  EXPECT_EQ(tonemap.define, "TONEMAP");
  EXPECT_EQ(tonemap.bit, 3u);
  EXPECT_EQ(tonemap.width, 2u);
  ASSERT_EQ(tonemap.values.size(), 3u);
  EXPECT_EQ(tonemap.values[1], "ACES");
  EXPECT_EQ(kFeatures[1].name, "SHARPEN");
  EXPECT_EQ(kFeatures[1].define, "USE_SHARPEN");
  EXPECT_EQ(kFeatures[1].bit, 0u);
  EXPECT_EQ(kFeatures[1].width, 1u);
  EXPECT_TRUE(kFeatures[1].values.empty());
  EXPECT_EQ(kFeatures[2].name, "QUALITY");
  EXPECT_EQ(kFeatures[2].values[2], "2");
  EXPECT_EQ(kFeatures[3].name, "BIAS");
  EXPECT_EQ(kFeatures[3].values[0], "-1");
}

TEST(TypedApi, FixedDefinesFromTheSpecAndCMake) {
  ASSERT_EQ(kDefines.size(), 3u);
  EXPECT_EQ(kDefines[0].name, "MAX_TAPS");
  EXPECT_EQ(kDefines[0].value, "4");
  EXPECT_EQ(kDefines[1].name, "BANNER");
  EXPECT_EQ(kDefines[1].value, "\"graded\" \\ done") << "escaped in the generated source, read back as written";
  EXPECT_EQ(kDefines[2].name, "EXTRA");
  EXPECT_EQ(kDefines[2].value, "7");
}

// The names of raw ID `id` in explain's syntax; empty when a field holds no value (pruned).
std::optional<std::string> names_of(std::uint32_t id) {
  std::string text;
  for (const shadergen::Feature& f : kFeatures) {
    std::uint32_t index = (id >> f.bit) & ((1u << f.width) - 1u);
    std::string term;
    if (f.values.empty() && index) term = f.name;
    if (!f.values.empty()) {
      if (index >= f.values.size()) return std::nullopt;
      term = std::string(f.name) + "=" + std::string(f.values[index]);
    }
    if (!term.empty()) text += (text.empty() ? "" : "|") + term;
  }
  return text;
}

TEST(TypedApi, FindRawIdRoundTripsEveryRawId) {
  std::size_t named = 0;
  for (std::uint32_t id = 0; id < kRawCount; ++id) {
    EXPECT_EQ(find_raw_id(std::to_string(id)), std::nullopt) << "a number is no feature text: " << id;
    if (auto names = names_of(id)) {
      EXPECT_EQ(find_raw_id(*names), RawId(id)) << *names;
      ++named;
    } else {
      EXPECT_TRUE(kRawPruned[id]) << "a field past its values is pruned: raw " << id;
    }
  }
  EXPECT_EQ(named, 3u * 2u * 3u * 2u);
}

// The one grammar (shadergen::parse_combination): feature names joined by '|', valued ones as
// NAME=VALUE, blanks ignored, "" and "(none)" are 0; everything else is refused.
TEST(TypedApi, FindRawIdRefusesWhatIsNotARawId) {
  using Error = shadergen::CombinationError;
  const std::vector<std::pair<std::string, std::optional<RawId>>> accepted = {
      {"", RawId(0)},
      {"(none)", RawId(0)},
      {"SHARPEN", RawId(1)},
      {" SHARPEN | QUALITY = 2 ", RawId(5)},
      {"SHARPEN|TONEMAP=FILMIC|BIAS=-1", RawId(1u | (2u << 3))},
      {"BIAS=1\t|\tTONEMAP=LINEAR", RawId(1u << 5)},
  };
  for (const auto& [text, expected] : accepted) EXPECT_EQ(find_raw_id(text), expected) << '"' << text << '"';
  const std::vector<std::pair<std::string, Error>> refused = {
      {"USE_SHARPEN", Error::define_name},
      {"SHARPEN+TONEMAP=FILMIC", Error::unknown_name},
      {"SHARPEN,BIAS=-1", Error::unknown_name},
      {"0b101", Error::number},
      {"63", Error::number},
      {"SHARPEN=1", Error::boolean_with_value},
      {"SHARPEN=0", Error::boolean_with_value},
      {"QUALITY", Error::missing_value},
      {"QUALITY=3", Error::unknown_value},
      {"TONEMAP=aces", Error::unknown_value},
      {"NOT_A_FEATURE", Error::unknown_name},
      {"12abc", Error::unknown_name},
      {"SHARPEN|SHARPEN", Error::repeated},
      {"QUALITY=1|QUALITY=2", Error::repeated},
      {"SHARPEN|", Error::empty_word},
  };
  for (const auto& [text, error] : refused) {
    EXPECT_EQ(find_raw_id(text), std::nullopt) << '"' << text << '"';
    EXPECT_EQ(shadergen::parse_combination(kFeatures, text).error, error) << '"' << text << '"';
  }
}

// raw_id() and the lookups by raw ID, all checked: a domain without collapse, so optimised_id()
// is the raw ID itself, and the 28 IDs whose fields hold no value are pruned.
TEST(TypedApi, LookupsByRawIdAreChecked) {
  static_assert(optimised_id(*raw_id(kAcesSharpHigh)) == OptimisedId(raw_id(kAcesSharpHigh)->value()));
  static_assert(is_valid_raw_id(RawId(0)) && !is_valid_raw_id(RawId(kRawCount)) && !is_valid_raw_id(RawId(3u << 1)));
  const registry_lookups::Counts counts =
      registry_lookups::expect_checked_lookups(registry(), {kRawCount, kRawPruned, {}, is_valid_raw_id, optimised_id});
  EXPECT_EQ(counts.valid, 36u);
  EXPECT_EQ(counts.pruned, 28u);
  const std::optional<RawId> id = raw_id({.TONEMAP = TONEMAP_value::FILMIC, .SHARPEN = true});
  ASSERT_TRUE(id);
  const shadergen::Permutation* p = registry().optimised_for_raw(*id);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p, &registry().raw[id->value()]);
}

// features() decodes what raw_id() encodes; is_possible() says which decoded IDs hold values
// (this domain has no impossible rule: only the 28 IDs with a field past its values are not).
static_assert(features(*raw_id(kAcesSharpHigh)).TONEMAP == TONEMAP_value::ACES);
static_assert(features(*raw_id(kAcesSharpHigh)).SHARPEN && features(*raw_id(kAcesSharpHigh)).BIAS == BIAS_value::_1);
static_assert(raw_id(features(RawId(0x2bu))) == RawId(0x2bu));
static_assert(!is_possible(features(RawId(3u << 1))) && !is_possible({.TONEMAP = static_cast<TONEMAP_value>(3)}));

TEST(TypedApi, FeaturesDecodeEveryRawIdAndIsPossibleAgreesWithThePrunedFlags) {
  for (std::uint32_t id = 0; id < kRawCount; ++id) {
    const Features decoded = features(RawId(id));
    EXPECT_EQ(is_possible(decoded), !kRawPruned[id]) << id;
    if (is_possible(decoded)) EXPECT_EQ(raw_id(decoded), RawId(id));
  }
}

// to_string() writes what find_raw_id() reads, in explain's order (by bit) and spelling.
TEST(TypedApi, ToStringRoundTripsEveryPossibleRawId) {
  EXPECT_EQ(to_string(RawId(0)), "QUALITY=0 | TONEMAP=LINEAR | BIAS=-1") << "a valued feature always has a value";
  EXPECT_EQ(to_string(*raw_id(kAcesSharpHigh)), "SHARPEN | QUALITY=2 | TONEMAP=ACES | BIAS=1");
  EXPECT_EQ(to_string(RawId(3u << 1)), "QUALITY=? | TONEMAP=LINEAR | BIAS=-1") << "a field past its values, as explain";
  std::size_t round_trips = 0;
  for (std::uint32_t id = 0; id < kRawCount; ++id) {
    if (kRawPruned[id]) continue;
    EXPECT_EQ(find_raw_id(to_string(RawId(id))), RawId(id)) << to_string(RawId(id));
    ++round_trips;
  }
  EXPECT_EQ(round_trips, 36u);
}

// The checked conversions into the value enums: integers for integer values, text otherwise.
static_assert(to_QUALITY(2) == QUALITY_value::_2 && to_QUALITY(0) == QUALITY_value::_0);
static_assert(to_QUALITY(3) == std::nullopt && to_QUALITY(-1) == std::nullopt);
static_assert(to_BIAS(-1) == BIAS_value::_m1 && to_BIAS(1) == BIAS_value::_1 && !to_BIAS(0));
static_assert(to_TONEMAP("FILMIC") == TONEMAP_value::FILMIC && !to_TONEMAP("aces") && !to_TONEMAP(""));
static_assert(std::is_same_v<decltype(to_TONEMAP(std::string_view())), std::optional<TONEMAP_value>>);

// The ID types are their own: not integers, not each other (compile_fails.cmake shows the mixes
// do not compile); the generated names are shadergen's types.
static_assert(std::is_same_v<RawId, shadergen::RawId> && std::is_same_v<OptimisedId, shadergen::OptimisedId>);
static_assert(!std::is_convertible_v<std::uint32_t, RawId> && !std::is_convertible_v<RawId, std::uint32_t>);
static_assert(!std::is_convertible_v<OptimisedId, RawId> && !std::is_convertible_v<RawId, OptimisedId>);
static_assert(!std::is_constructible_v<RawId, OptimisedId> && !std::is_constructible_v<OptimisedId, RawId>);
static_assert(RawId(3) < RawId(5) && OptimisedId(7) > OptimisedId(2) && RawId(4).value() == 4u);

nlohmann::json manifest() {
  std::ifstream in(TYPED_API_MANIFEST);
  return nlohmann::json::parse(in);
}

// The layout bindings of each set as shadergen/vulkan.h gives them, against the manifest's
// pipeline layout: one entry per binding (the aliased storage buffers once), kinds as written.
TEST(TypedApi, VulkanSetLayoutsMatchTheManifest) {
  const shadergen::Registry& r = registry();
  nlohmann::json layout = manifest()["pipeline_layout"];
  ASSERT_EQ(shadergen::vk::descriptor_set_count(r.pipeline_layout), 2u);
  std::size_t listed = 0;
  for (std::uint32_t set = 0; set < 2; ++set) {
    for (const VkDescriptorSetLayoutBinding& b :
         shadergen::vk::descriptor_set_layout_bindings(r.pipeline_layout, set)) {
      auto found = std::find_if(layout["bindings"].begin(), layout["bindings"].end(),
                                [&](const nlohmann::json& j) { return j["set"] == set && j["binding"] == b.binding; });
      ASSERT_NE(found, layout["bindings"].end()) << "set " << set << " binding " << b.binding;
      EXPECT_EQ(b.descriptorCount, (*found)["count"].get<std::uint32_t>());
      EXPECT_EQ(b.stageFlags, VK_SHADER_STAGE_FRAGMENT_BIT);
      const std::string kind = (*found)["kind"];
      VkDescriptorType expected = kind == "uniform_texel_buffer"   ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                  : kind == "storage_texel_buffer" ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                  : kind == "storage_buffer"       ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                                                   : VK_DESCRIPTOR_TYPE_MAX_ENUM;
      EXPECT_EQ(b.descriptorType, expected) << kind;
      ++listed;
    }
  }
  EXPECT_EQ(listed, layout["bindings"].size());
  EXPECT_EQ(listed, 3u) << "texel buffer, aliased storage buffer once, storage texel buffer";
  std::vector<VkPushConstantRange> push = shadergen::vk::push_constant_ranges(r);
  ASSERT_EQ(push.size(), 1u);
  EXPECT_EQ(push[0].size, 16u);
  EXPECT_EQ(push[0].stageFlags, VK_SHADER_STAGE_FRAGMENT_BIT);
  EXPECT_EQ(manifest()["defines"], nlohmann::json::array({"MAX_TAPS=4", "BANNER=\"graded\" \\ done", "EXTRA=7"}));
}

// STRIP_DEBUG: no OpName (5) or OpMemberName (6) in any blob, and still the names in the registry.
TEST(TypedApi, StrippedBlobsKeepTheirNamesInTheRegistry) {
  const shadergen::Registry& r = registry();
  ASSERT_EQ(r.pipeline_layout.size(), 3u);
  EXPECT_EQ(r.pipeline_layout[0].name, "curve");
  EXPECT_EQ(r.pipeline_layout[1].name, "Weights");
  EXPECT_EQ(r.pipeline_layout[2].name, "lut");
  for (const shadergen::Permutation& p : r.raw) {
    for (std::size_t i = 5; i < p.spirv.size();) {
      std::uint32_t count = p.spirv[i] >> 16, opcode = p.spirv[i] & 0xffffu;
      EXPECT_TRUE(opcode != 5 && opcode != 6) << "raw " << p.id << " word " << i;
      if (count == 0) break;
      i += count;
    }
  }
}

TEST(TypedApi, VulkanModulesAndSpecializationPerPermutation) {
  const shadergen::Registry& r = registry();
  std::size_t compiled = 0;
  for (const shadergen::Permutation& p : r.raw) {
    if (p.pruned) continue;
    ++compiled;
    VkShaderModuleCreateInfo info = shadergen::vk::shader_module_create_info(p);
    EXPECT_EQ(info.sType, VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    EXPECT_EQ(info.codeSize, p.spirv.size() * 4);
    EXPECT_EQ(info.pCode, p.spirv.data());
    std::vector<VkSpecializationMapEntry> entries = shadergen::vk::specialization_map_entries(p.reflection);
    std::vector<std::uint32_t> data = shadergen::vk::specialization_defaults(p.reflection);
    ASSERT_EQ(entries.size(), data.size());
    ASSERT_GE(entries.size(), 1u) << "EXPOSURE is always alive";
    EXPECT_EQ(entries[0].constantID, 0u);
    EXPECT_EQ(entries[0].offset, 0u);
    EXPECT_EQ(entries[0].size, 4u);
    EXPECT_EQ(data[0], std::bit_cast<std::uint32_t>(1.5f));
    if (entries.size() == 2) {
      EXPECT_EQ(entries[1].constantID, 4u);
      EXPECT_EQ(entries[1].offset, 4u);
      EXPECT_EQ(data[1], 3u);
    }
  }
  EXPECT_EQ(compiled, 36u);
}

// A Vulkan device of any kind (lavapipe in CI) with no extension: enough to create layouts
// and modules. Null members when the machine has none.
struct Device {
  VkInstance instance = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  Device() {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO, nullptr, "typed_api", 1, nullptr, 0, VK_API_VERSION_1_2};
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, nullptr, 0, &app, 0, nullptr, 0, nullptr};
    if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return;
    std::uint32_t count = 1;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    if (vkEnumeratePhysicalDevices(instance, &count, &physical) < 0 || count == 0) return;
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, nullptr, 0, 0, 1, &priority};
    VkDeviceCreateInfo device_info{
        VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, nullptr, 0, 1, &queue, 0, nullptr, 0, nullptr, nullptr};
    if (vkCreateDevice(physical, &device_info, nullptr, &device) != VK_SUCCESS) device = VK_NULL_HANDLE;
  }
  ~Device() {
    if (device) vkDestroyDevice(device, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

// What shadergen/vulkan.h gives, handed to a real driver: each set layout, the pipeline layout
// with the push-constant range, and every compiled permutation's shader module.
TEST(TypedApi, AVulkanDriverAcceptsTheLayoutsAndModules) {
  Device d;
  if (!d.device) GTEST_SKIP() << "no Vulkan device (install mesa-vulkan-drivers for lavapipe)";
  const shadergen::Registry& r = registry();
  std::vector<VkDescriptorSetLayout> sets;
  for (std::uint32_t set = 0; set < shadergen::vk::descriptor_set_count(r.pipeline_layout); ++set) {
    auto bindings = shadergen::vk::descriptor_set_layout_bindings(r.pipeline_layout, set);
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO, nullptr, 0,
                                         static_cast<std::uint32_t>(bindings.size()), bindings.data()};
    ASSERT_EQ(vkCreateDescriptorSetLayout(d.device, &info, nullptr, &sets.emplace_back()), VK_SUCCESS) << set;
  }
  auto push = shadergen::vk::push_constant_ranges(r);
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                         nullptr,
                                         0,
                                         static_cast<std::uint32_t>(sets.size()),
                                         sets.data(),
                                         static_cast<std::uint32_t>(push.size()),
                                         push.data()};
  VkPipelineLayout layout = VK_NULL_HANDLE;
  EXPECT_EQ(vkCreatePipelineLayout(d.device, &layout_info, nullptr, &layout), VK_SUCCESS);
  for (const shadergen::Permutation& p : r.raw) {
    if (p.pruned) continue;
    VkShaderModuleCreateInfo info = shadergen::vk::shader_module_create_info(p);
    VkShaderModule module = VK_NULL_HANDLE;
    EXPECT_EQ(vkCreateShaderModule(d.device, &info, nullptr, &module), VK_SUCCESS) << "raw " << p.id;
    vkDestroyShaderModule(d.device, module, nullptr);
  }
  vkDestroyPipelineLayout(d.device, layout, nullptr);
  for (VkDescriptorSetLayout set : sets) vkDestroyDescriptorSetLayout(d.device, set, nullptr);
}

}  // namespace
