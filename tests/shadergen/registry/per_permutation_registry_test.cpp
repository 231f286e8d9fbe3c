// The per-permutation-layout fixture's generated C++, linked as a consumer links it: no merged
// layout, and each permutation's reflection is its own layout (kinds, input attachment index,
// outputs and runtime-sized arrays as the manifest has them).
#include <gtest/gtest.h>

#include "registry_digests.h"
#include "registry_lookups.h"

#include <per_permutation_permutations.h>

#include <algorithm>

namespace {

const shadergen::DescriptorBinding* binding_at(const shadergen::Permutation& p, std::uint32_t set,
                                               std::uint32_t binding) {
  auto& list = p.reflection.bindings;
  auto found = std::find_if(list.begin(), list.end(), [&](const shadergen::DescriptorBinding& b) {
    return b.set == set && b.binding == binding;
  });
  return found == list.end() ? nullptr : &*found;
}

TEST(PerPermutationRegistry, LookupsByRawIdAreChecked) {
  const registry_lookups::Counts counts = registry_lookups::expect_checked_lookups(
      per_permutation::registry(),
      {per_permutation::kRawCount, per_permutation::kRawPruned, per_permutation::kRawToOptimised,
       per_permutation::is_valid_raw_id, per_permutation::optimised_id});
  EXPECT_EQ(counts.valid, 8u);
}

TEST(PerPermutationRegistry, EachPermutationHasItsOwnLayout) {
  const shadergen::Registry& r = per_permutation::registry();
  EXPECT_TRUE(r.per_permutation_layout);
  EXPECT_TRUE(r.pipeline_layout.empty());
  ASSERT_EQ(r.raw.size(), 8u);
  const auto* sampled = binding_at(r.raw[0], 0, 1);
  const auto* subpass = binding_at(r.raw[1], 0, 1);
  ASSERT_TRUE(sampled && subpass);
  EXPECT_EQ(sampled->kind, shadergen::DescriptorKind::combined_image_sampler);
  EXPECT_EQ(subpass->kind, shadergen::DescriptorKind::input_attachment);
  EXPECT_EQ(subpass->input_attachment_index, 0u);
  EXPECT_EQ(r.raw[0].reflection.outputs.size(), 1u);
  EXPECT_EQ(r.raw[2].reflection.outputs.size(), 2u);
  const auto* cookies = binding_at(r.raw[4], 1, 0);
  ASSERT_NE(cookies, nullptr);
  EXPECT_TRUE(cookies->runtime_sized);
  EXPECT_EQ(cookies->count, 0u);
  ASSERT_EQ(r.raw[0].reflection.specialization_constants.size(), 1u);
  EXPECT_EQ(r.raw[0].reflection.specialization_constants[0].name, "LIGHT_SCALE");
  const shadergen::CompanionShader* fft = r.companion("fft");
  ASSERT_NE(fft, nullptr);
  EXPECT_EQ(fft->stage, shadergen::Stage::compute);
  EXPECT_EQ(fft->shader.reflection.local_size_ids[0], 3u);
  EXPECT_EQ(fft->shader.reflection.local_size_ids[1], shadergen::Reflection::kNoConstant);
  ASSERT_EQ(fft->shader.reflection.specialization_constants.size(), 2u);
  EXPECT_EQ(fft->shader.reflection.specialization_constants[1].name, "RADIX");
  EXPECT_EQ(fft->shader.reflection.specialization_constants[1].default_bits, 4u);
}

// Every hash in the generated code is the SHA-256 of its words, by coreutils' implementation.
TEST(PerPermutationRegistry, HashesAreTheSha256OfTheirWords) {
  EXPECT_GT(registry_digests::expect_hashes_are_sha256_of_words(per_permutation::registry()), 0u);
}

}  // namespace
