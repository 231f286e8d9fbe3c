// The identity fixture's generated C++ (tests/fixtures/identity, no "optimised" section),
// linked as a consumer links it: no lookup table, and optimised_for_raw() is the raw
// permutation itself, so code written for collapsed domains works unchanged.
#include <gtest/gtest.h>

#include "registry_digests.h"
#include "registry_lookups.h"

#include <identity_permutations.h>

namespace {

static_assert(identity::kRawCount == 2048u);
static_assert(identity::kOptimisedCount == 0u);

TEST(IdentityRegistry, LookupByRawIdGivesTheRawPermutation) {
  const shadergen::Registry& r = identity::registry();
  EXPECT_TRUE(r.raw_to_optimised.empty());
  EXPECT_TRUE(r.optimised.empty());
  ASSERT_EQ(r.raw.size(), identity::kRawCount);
  std::size_t compiled = 0;
  for (std::uint32_t id = 0; id < identity::kRawCount; ++id) {
    const shadergen::Permutation* p = r.optimised_for_raw(identity::RawId(id));
    EXPECT_EQ(p, identity::kRawPruned[id] ? nullptr : &r.raw[id]);
    compiled += p != nullptr;
  }
  EXPECT_EQ(compiled, 405u);
  constexpr std::uint32_t kAlbedoNormal = (identity::raw_bit::ALBEDO_MAP | identity::raw_bit::NORMAL_MAP).value();
  ASSERT_EQ(r.raw[kAlbedoNormal].defines.size(), 2u);
  EXPECT_EQ(r.raw[kAlbedoNormal].defines[1], "USE_NORMAL_MAP");
}

// Without collapse, optimised_id() is the raw ID itself, and checked like every lookup.
TEST(IdentityRegistry, LookupsByRawIdAreChecked) {
  static_assert(identity::optimised_id(identity::RawId(0)) == identity::OptimisedId(0));
  static_assert(identity::optimised_id(identity::RawId(identity::kRawCount)) == std::nullopt);
  const registry_lookups::Counts counts = registry_lookups::expect_checked_lookups(
      identity::registry(),
      {identity::kRawCount, identity::kRawPruned, {}, identity::is_valid_raw_id, identity::optimised_id});
  EXPECT_EQ(counts.valid, 405u);
  EXPECT_EQ(counts.pruned, 2048u - 405u);
}

// Every hash in the generated code is the SHA-256 of its words, by coreutils' implementation.
TEST(IdentityRegistry, HashesAreTheSha256OfTheirWords) {
  EXPECT_GT(registry_digests::expect_hashes_are_sha256_of_words(identity::registry()), 0u);
}

}  // namespace
