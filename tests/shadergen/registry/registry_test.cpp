// The generated registry as the runtime links it (built by shadergen_add_permutations()).
#include <gtest/gtest.h>

#include "registry_digests.h"
#include "registry_lookups.h"

#include <split_second_shaders.h>

#include <set>

namespace {

TEST(GeneratedRegistry, TableAndPermutations) {
  const shadergen::Registry& r = split_second::raster::registry();
  EXPECT_EQ(r.name, "split_second");
  ASSERT_EQ(r.raw.size(), 128u);
  ASSERT_EQ(r.optimised.size(), 32u);
  static_assert(split_second::kRawToOptimised[69] == 8);
  static_assert(split_second::kRawPruned[3] && !split_second::kRawPruned[2]);
  static_assert(split_second::raw_bit::SUN_LIGHT.value() == 64u && split_second::optimised_bit::SUN_1.value() == 16u);
  std::size_t pruned = 0;
  for (std::uint32_t id = 0; id < r.raw.size(); ++id) {
    const shadergen::Permutation& p = r.raw[id];
    EXPECT_EQ(p.id, id);
    EXPECT_EQ(r.raw_to_optimised[id], split_second::kRawToOptimised[id]);
    EXPECT_EQ(p.pruned, split_second::kRawPruned[id]);
    if (p.pruned) {
      ++pruned;
      EXPECT_TRUE(p.spirv.empty());
      continue;
    }
    ASSERT_GT(p.spirv.size(), 5u);
    EXPECT_EQ(p.spirv[0], 0x07230203u);
    ASSERT_EQ(p.reflection.outputs.size(), 1u);
    EXPECT_EQ(p.reflection.outputs[0].location, 0u);
    EXPECT_EQ(p.reflection.outputs[0].components, 4u);
  }
  EXPECT_EQ(pruned, 32u);
  EXPECT_EQ(r.optimised[31].defines.size(), 6u);
  EXPECT_EQ(r.optimised_for_raw(split_second::RawId(69)), &r.optimised[8]);
}

// Every lookup by raw ID is checked: 96 valid IDs, 32 pruned, and IDs past 127 find nothing.
TEST(GeneratedRegistry, LookupsByRawIdAreChecked) {
  using split_second::RawId;
  static_assert(split_second::optimised_id(RawId(69)) == split_second::OptimisedId(8));
  static_assert(!split_second::optimised_id(RawId(3)) && !split_second::optimised_id(RawId(128)));
  static_assert(split_second::is_valid_raw_id(RawId(127 - 1)) && !split_second::is_valid_raw_id(RawId(127)));
  // docs/lut.md's example: raw and optimised SKY are different bits of different types.
  static_assert((RawId(0) | split_second::raw_bit::SKY) == RawId(32));
  static_assert((split_second::OptimisedId(0) | split_second::optimised_bit::SKY) == split_second::OptimisedId(4));
  const registry_lookups::Counts counts = registry_lookups::expect_checked_lookups(
      split_second::raster::registry(),
      {split_second::kRawCount, split_second::kRawPruned, split_second::kRawToOptimised, split_second::is_valid_raw_id,
       split_second::optimised_id});
  EXPECT_EQ(counts.valid, 96u);
  EXPECT_EQ(counts.pruned, 32u);
}

TEST(GeneratedRegistry, CompanionAndLayout) {
  const shadergen::Registry& r = split_second::raster::registry();
  const shadergen::CompanionShader* tile = r.companion("tile");
  ASSERT_NE(tile, nullptr);
  EXPECT_EQ(tile->stage, shadergen::Stage::vertex);
  ASSERT_EQ(tile->shader.reflection.inputs.size(), 1u);
  EXPECT_EQ(tile->shader.reflection.inputs[0].components, 2u);
  EXPECT_EQ(tile->shader.reflection.push_constant_size, 8u);
  EXPECT_EQ(r.companion("nope"), nullptr);
  ASSERT_EQ(r.pipeline_layout.size(), 7u);
  EXPECT_EQ(r.pipeline_layout[0].kind, shadergen::DescriptorKind::uniform_buffer);
  EXPECT_EQ(r.pipeline_layout[5].name, "shadow_map");
  EXPECT_EQ(r.pipeline_layout[6].name, "gbuffer_coverage_flags");
  ASSERT_EQ(r.push_constants.size(), 1u);
  EXPECT_EQ(r.push_constants[0].stages, static_cast<std::uint32_t>(shadergen::Stage::vertex));
}

TEST(GeneratedRegistry, SharedBlobsAreOneArray) {
  const shadergen::Registry& r = split_second::raster::registry();
  // Optimised permutations reuse their raw twin's words: same address, not a copy.
  std::set<const std::uint32_t*> raw_words;
  for (const auto& p : r.raw)
    if (!p.pruned) raw_words.insert(p.spirv.data());
  for (const auto& p : r.optimised) EXPECT_TRUE(raw_words.count(p.spirv.data())) << "optimised " << p.id;
}

// Every hash in the generated code is the SHA-256 of its words, by coreutils' implementation.
TEST(GeneratedRegistry, HashesAreTheSha256OfTheirWords) {
  EXPECT_GT(registry_digests::expect_hashes_are_sha256_of_words(split_second::raster::registry()), 0u);
}

}  // namespace
