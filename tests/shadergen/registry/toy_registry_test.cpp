// The generated C++ of the toy fixture domain, compiled and linked the way a consumer uses it:
// shadergen_add_permutations(toy_permutations DOMAIN tests/fixtures/toy/toy.json NAMESPACE toy)
// in tests/shadergen/CMakeLists.txt runs the shadergen executable at build time; this test
// links the resulting library. It does not link shadergen itself: the header needs nothing but
// <shadergen/registry.h> and the standard library.
#include <gtest/gtest.h>

#include "registry_digests.h"
#include "registry_lookups.h"

#include <toy_permutations.h>

#include <array>
#include <set>
#include <string_view>
#include <type_traits>

namespace {

// The table and the bit constants are usable at compile time.
static_assert(toy::kRawCount == 16u);
static_assert(toy::kOptimisedCount == 4u);
static_assert(std::is_same_v<decltype(toy::kRawToOptimised), const std::array<std::uint8_t, 16>>);
static_assert(toy::kRawToOptimised[(toy::raw_bit::LIT | toy::raw_bit::TEXTURED).value()] ==
              (toy::optimised_bit::SHADED | toy::optimised_bit::SAMPLED).value());
static_assert(toy::kRawToOptimised[toy::raw_bit::SOFT.value()] == toy::optimised_bit::SAMPLED.value());
static_assert(toy::kRawToOptimised[toy::raw_bit::DISTORT.value()] == toy::optimised_bit::SHADED.value());
static_assert(toy::kRawPruned[(toy::raw_bit::DISTORT | toy::raw_bit::LIT).value()]);
static_assert(!toy::kRawPruned[(toy::raw_bit::DISTORT | toy::raw_bit::TEXTURED).value()]);
static_assert(toy::raw_bit::LIT.value() == 1u && toy::raw_bit::TEXTURED.value() == 2u &&
              toy::raw_bit::SOFT.value() == 4u && toy::raw_bit::DISTORT.value() == 8u);
// The bits compose with IDs of their own kind only: a raw ID with raw bits, an optimised ID with
// optimised bits (tests/shadergen/registry/compile_fails checks that the mixes do not compile).
static_assert((toy::RawId(0) | toy::raw_bit::LIT | toy::raw_bit::SOFT) == toy::RawId(5));
static_assert((toy::RawId(5) & toy::raw_bit::SOFT) && !(toy::RawId(5) & toy::raw_bit::TEXTURED));
static_assert((toy::OptimisedId(0) | toy::optimised_bit::SAMPLED) ==
              toy::OptimisedId(toy::optimised_bit::SAMPLED.value()));

// The checked lookups too: a pruned ID or one past the table is none.
static_assert(toy::optimised_id(toy::RawId(0) | toy::raw_bit::LIT | toy::raw_bit::TEXTURED) == toy::OptimisedId(3));
static_assert(toy::optimised_id(toy::RawId(0) | toy::raw_bit::DISTORT | toy::raw_bit::LIT) == std::nullopt);
static_assert(toy::optimised_id(toy::RawId(toy::kRawCount)) == std::nullopt &&
              toy::optimised_id(toy::RawId(0xffffffffu)) == std::nullopt);
static_assert(toy::is_valid_raw_id(toy::RawId(0)) && !toy::is_valid_raw_id(toy::RawId(9)) &&
              !toy::is_valid_raw_id(toy::RawId(16)));
static_assert(toy::raw_id({.LIT = true, .DISTORT = true}) == std::nullopt, "pruned");
static_assert(toy::raw_id({.SOFT = true, .DISTORT = true}) ==
              (toy::RawId(0) | toy::raw_bit::SOFT | toy::raw_bit::DISTORT));
// is_possible() is the impossible rule "LIT && DISTORT" itself; find_raw_id() of the pruned
// combination is none.
static_assert(!toy::is_possible({.LIT = true, .DISTORT = true}) && toy::is_possible({.SOFT = true, .LIT = true}));
static_assert(toy::find_raw_id("LIT|DISTORT") == std::nullopt);
static_assert(toy::find_raw_id("SOFT|DISTORT") == toy::RawId(12));

TEST(ToyRegistry, ToStringIsExplainsText) {
  EXPECT_EQ(toy::to_string(toy::RawId(0)), "(none)");
  EXPECT_EQ(toy::to_string(toy::RawId(12)), "SOFT | DISTORT");
  for (std::uint32_t id = 0; id < toy::kRawCount; ++id)
    EXPECT_EQ(toy::find_raw_id(toy::to_string(toy::RawId(id))),
              toy::kRawPruned[id] ? std::nullopt : std::optional<toy::RawId>(toy::RawId(id)));
}

constexpr std::array<int, 16> kExpected = {0, 1, 2, 3, 2, 3, 2, 3, 1, -1, 3, -1, 3, -1, 3, -1};
constexpr std::uint32_t kSpirvMagic = 0x07230203u;

TEST(ToyRegistry, NamesAndCounts) {
  const shadergen::Registry& r = toy::registry();
  EXPECT_EQ(r.name, "toy_particles");
  EXPECT_EQ(r.uber_stage, shadergen::Stage::fragment);
  ASSERT_EQ(r.raw.size(), 16u);
  ASSERT_EQ(r.optimised.size(), 4u);
  ASSERT_EQ(r.raw_to_optimised.size(), 16u);
  const std::array<std::string_view, 4> features = {"LIT", "TEXTURED", "SOFT", "DISTORT"};
  ASSERT_EQ(r.raw_feature_names.size(), 4u);
  for (std::size_t bit = 0; bit < 4; ++bit) EXPECT_EQ(r.raw_feature_names[bit], features[bit]);
  ASSERT_EQ(r.optimised_bit_names.size(), 2u);
  EXPECT_EQ(r.optimised_bit_names[0], "SHADED");
  EXPECT_EQ(r.optimised_bit_names[1], "SAMPLED");
}

TEST(ToyRegistry, TableMatchesTheConstexprTableAndTheSpec) {
  const shadergen::Registry& r = toy::registry();
  for (std::uint32_t id = 0; id < 16; ++id) {
    SCOPED_TRACE("raw " + std::to_string(id));
    EXPECT_EQ(r.raw_to_optimised[id], toy::kRawToOptimised[id]);
    EXPECT_EQ(r.raw[id].pruned, toy::kRawPruned[id]);
    EXPECT_EQ(r.raw[id].pruned, kExpected[id] < 0);
    if (kExpected[id] >= 0) {
      EXPECT_EQ(static_cast<int>(r.raw_to_optimised[id]), kExpected[id]);
      EXPECT_EQ(r.optimised_for_raw(toy::RawId(id)), &r.optimised[static_cast<std::size_t>(kExpected[id])]);
    } else {
      EXPECT_EQ(r.optimised_for_raw(toy::RawId(id)), nullptr) << "pruned: no shader, though the table holds an entry";
    }
  }
}

TEST(ToyRegistry, LookupsByRawIdAreChecked) {
  const registry_lookups::Counts counts = registry_lookups::expect_checked_lookups(
      toy::registry(),
      {toy::kRawCount, toy::kRawPruned, toy::kRawToOptimised, toy::is_valid_raw_id, toy::optimised_id});
  EXPECT_EQ(counts.valid, 12u);
  EXPECT_EQ(counts.pruned, 4u);
  EXPECT_EQ(counts.out_of_range, 4u);
}

TEST(ToyRegistry, PermutationsCarrySpirvUnlessPruned) {
  const shadergen::Registry& r = toy::registry();
  std::size_t pruned = 0;
  for (std::uint32_t id = 0; id < r.raw.size(); ++id) {
    const shadergen::Permutation& p = r.raw[id];
    SCOPED_TRACE("raw " + std::to_string(id));
    EXPECT_EQ(p.id, id);
    if (p.pruned) {
      ++pruned;
      EXPECT_TRUE(p.spirv.empty());
      EXPECT_TRUE(p.hash.empty());
      continue;
    }
    ASSERT_GT(p.spirv.size(), 5u);
    EXPECT_EQ(p.spirv[0], kSpirvMagic);
    ASSERT_EQ(p.reflection.outputs.size(), 1u);
    EXPECT_EQ(p.reflection.outputs[0].location, 0u);
    EXPECT_EQ(p.reflection.outputs[0].components, 4u);
    EXPECT_EQ(p.reflection.local_size[0], 0u);
  }
  EXPECT_EQ(pruned, 4u);
  for (const shadergen::Permutation& o : r.optimised) {
    SCOPED_TRACE("optimised " + std::to_string(o.id));
    EXPECT_FALSE(o.pruned);
    ASSERT_FALSE(o.spirv.empty());
    EXPECT_EQ(o.spirv[0], kSpirvMagic);
  }
}

TEST(ToyRegistry, DefinesFollowTheRawBits) {
  const shadergen::Registry& r = toy::registry();
  auto defines = [](const shadergen::Permutation& p) {
    std::vector<std::string_view> list(p.defines.begin(), p.defines.end());
    return list;
  };
  EXPECT_TRUE(defines(r.raw[0]).empty());
  EXPECT_EQ(defines(r.raw[7]), (std::vector<std::string_view>{"LIT", "USE_TEXTURE", "SOFT_PARTICLES"}));
  EXPECT_EQ(defines(r.raw[9]), (std::vector<std::string_view>{"LIT", "DISTORTION"})) << "pruned, but named";
  EXPECT_EQ(defines(r.optimised[2]), (std::vector<std::string_view>{"USE_TEXTURE", "SOFT_PARTICLES"}));
  EXPECT_EQ(defines(r.optimised[3]), (std::vector<std::string_view>{"LIT", "USE_TEXTURE", "SOFT_PARTICLES"}));
}

TEST(ToyRegistry, OptimisedBlobsAreSharedWithTheirRawTwins) {
  const shadergen::Registry& r = toy::registry();
  // Optimised 0..3 are compiled with the defines of raw 0, 1, 6, 7: the same words, stored once.
  const std::array<std::uint32_t, 4> twin = {0, 1, 6, 7};
  for (std::uint32_t id = 0; id < 4; ++id) {
    EXPECT_EQ(r.optimised[id].spirv.data(), r.raw[twin[id]].spirv.data()) << "optimised " << id;
    EXPECT_EQ(r.optimised[id].hash, r.raw[twin[id]].hash) << "optimised " << id;
  }
  std::set<std::string_view> hashes;
  for (const shadergen::Permutation& p : r.raw)
    if (!p.pruned) hashes.insert(p.hash);
  EXPECT_EQ(hashes.size(), 12u) << "every compilable raw permutation of the toy has its own code";
}

TEST(ToyRegistry, ComputeCompanionReflectsItsWorkGroupAndBuffer) {
  const shadergen::Registry& r = toy::registry();
  ASSERT_EQ(r.companions.size(), 1u);
  const shadergen::CompanionShader* sort = r.companion("sort");
  ASSERT_NE(sort, nullptr);
  EXPECT_EQ(r.companion("particle"), nullptr);
  EXPECT_EQ(sort->name, "sort");
  EXPECT_EQ(sort->stage, shadergen::Stage::compute);
  const shadergen::Permutation& shader = sort->shader;
  ASSERT_GT(shader.spirv.size(), 5u);
  EXPECT_EQ(shader.spirv[0], kSpirvMagic);
  ASSERT_EQ(shader.defines.size(), 1u);
  EXPECT_EQ(shader.defines[0], "WIDE_GROUPS");
  // WIDE_GROUPS selects local_size_x = 128.
  EXPECT_EQ(shader.reflection.local_size[0], 128u);
  EXPECT_EQ(shader.reflection.local_size[1], 1u);
  EXPECT_EQ(shader.reflection.local_size[2], 1u);
  EXPECT_EQ(shader.reflection.push_constant_size, 4u);
  ASSERT_EQ(shader.reflection.bindings.size(), 1u);
  EXPECT_EQ(shader.reflection.bindings[0].set, 1u);
  EXPECT_EQ(shader.reflection.bindings[0].binding, 0u);
  EXPECT_EQ(shader.reflection.bindings[0].kind, shadergen::DescriptorKind::storage_buffer);
}

TEST(ToyRegistry, MergedPipelineLayout) {
  const shadergen::Registry& r = toy::registry();
  struct Expected {
    std::uint32_t set, binding;
    shadergen::DescriptorKind kind;
    shadergen::Stage stage;
    std::string_view name;
  };
  const std::array<Expected, 4> expected = {{
      {0, 0, shadergen::DescriptorKind::uniform_buffer, shadergen::Stage::fragment, "ParticleParams"},
      {0, 1, shadergen::DescriptorKind::combined_image_sampler, shadergen::Stage::fragment, "particle_texture"},
      {0, 2, shadergen::DescriptorKind::combined_image_sampler, shadergen::Stage::fragment, "scene_depth"},
      {1, 0, shadergen::DescriptorKind::storage_buffer, shadergen::Stage::compute, "Keys"},
  }};
  ASSERT_EQ(r.pipeline_layout.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE("binding " + std::to_string(i));
    EXPECT_EQ(r.pipeline_layout[i].set, expected[i].set);
    EXPECT_EQ(r.pipeline_layout[i].binding, expected[i].binding);
    EXPECT_EQ(r.pipeline_layout[i].kind, expected[i].kind);
    EXPECT_EQ(r.pipeline_layout[i].count, 1u);
    EXPECT_EQ(r.pipeline_layout[i].stages, static_cast<std::uint32_t>(expected[i].stage));
    EXPECT_EQ(r.pipeline_layout[i].name, expected[i].name);
  }
  ASSERT_EQ(r.push_constants.size(), 1u);
  EXPECT_EQ(r.push_constants[0].size, 4u);
  EXPECT_EQ(r.push_constants[0].stages, static_cast<std::uint32_t>(shadergen::Stage::compute));
}

// Every hash in the generated code is the SHA-256 of its words, by coreutils' implementation.
TEST(ToyRegistry, HashesAreTheSha256OfTheirWords) {
  EXPECT_GT(registry_digests::expect_hashes_are_sha256_of_words(toy::registry()), 0u);
}

}  // namespace
