// Scaling (tests/fixtures/scale16): 16 boolean features, 65,536 raw IDs, 41,344 of them pruned
// by 4 rules, and a shader that tests only 2 features: the 24,196 compile jobs preprocess to
// 4 distinct sources. Expansion, pruning, deduplication and the lookups by ID are linear in
// the permutation count; a quadratic step would take minutes here. docs/results.md has its
// time and peak memory.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "shadergen/build.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "test_helpers.h"

namespace {

sgtest::fs::path scale_spec() { return sgtest::fixtures_dir() / "scale16" / "scale16.json"; }

TEST(Scaling, SixteenFeaturesExpandToEveryRawId) {
  auto spec = shadergen::load_domain(scale_spec());
  ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
  auto plan = shadergen::expand(*spec);
  ASSERT_TRUE(plan.ok()) << plan.errors().front().to_string();
  ASSERT_EQ(plan->raw.size(), 65536u);
  std::size_t pruned = 0;
  for (const shadergen::RawPermutation& raw : plan->raw) {
    bool expected = ((raw.id >> 10) & 3u) == 3u || ((raw.id >> 12) & 3u) == 3u || ((raw.id >> 14) & 3u) == 3u ||
                    ((raw.id >> 2) & 7u) == 7u;
    ASSERT_EQ(raw.pruned, expected) << "raw " << raw.id;
    pruned += raw.pruned;
  }
  EXPECT_EQ(pruned, 41344u);
}

TEST(Scaling, SixteenFeaturesBuildToFourDistinctSources) {
  sgtest::TempDir dir("scale16");
  auto cold = sgtest::build(scale_spec(), dir / "out", dir / "cache");
  ASSERT_TRUE(cold.ok()) << cold.errors().front().to_string();
  EXPECT_EQ(cold->raw, 65536u);
  EXPECT_EQ(cold->pruned, 41344u);
  EXPECT_EQ(cold->permutations, 24196u) << "24,192 compiled raw IDs and 4 optimised";
  EXPECT_EQ(cold->unique_sources, 4u);
  EXPECT_EQ(cold->compiled, 4u);
  std::string header = sgtest::read_file(dir / "out" / "scale16.h");
  EXPECT_TRUE(sgtest::contains(header, "inline constexpr std::uint32_t kRawCount = 65536;"));
  auto warm = sgtest::build(scale_spec(), dir / "out", dir / "cache");
  ASSERT_TRUE(warm.ok()) << warm.errors().front().to_string();
  EXPECT_TRUE(warm->inputs_reused);
  EXPECT_FALSE(warm->output_changed);
}

}  // namespace
