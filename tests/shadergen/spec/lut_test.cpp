// The Split/Second lookup table: the spec's rules must reproduce Listing 4.8 (with the
// book's misplaced brace corrected as docs/lut.md explains) for all 128 raw IDs.
#include <gtest/gtest.h>

#include <array>
#include <set>

#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

// Listing 4.8, written out independently of the spec: -1 marks the impossible IDs.
constexpr std::array<int, 128> kListing48 = {
    0,  0,  0,  -1, 0,  0,  0,  -1, 1,  1,  1,  -1, 1,  1,  1,  -1, 2,  2,  2,  -1, 2,  2,  2,  -1, 3,  3,
    3,  -1, 3,  3,  3,  -1, 4,  4,  4,  -1, 4,  4,  4,  -1, 5,  5,  5,  -1, 5,  5,  5,  -1, 6,  6,  6,  -1,
    6,  6,  6,  -1, 7,  7,  7,  -1, 7,  7,  7,  -1, 16, 0,  24, -1, 16, 8,  24, -1, 17, 1,  25, -1, 17, 9,
    25, -1, 18, 2,  26, -1, 18, 10, 26, -1, 19, 3,  27, -1, 19, 11, 27, -1, 20, 4,  28, -1, 20, 12, 28, -1,
    21, 5,  29, -1, 21, 13, 29, -1, 22, 6,  30, -1, 22, 14, 30, -1, 23, 7,  31, -1, 23, 15, 31, -1,
};

// The same table computed from the listing's logic, written from the chapter's prose.
int listing_logic(std::uint32_t raw) {
  bool solid = raw & 1, soft = raw & 2, fade = raw & 4, sun = raw & 64;
  if (solid && soft) return -1;
  std::uint32_t optimised = (raw >> 3) & 7;  // scattering, MSAA edge, sky copy across
  bool sun_1 = !solid && sun;
  bool sun_0 = (solid && fade && sun) || (!solid && sun && soft);
  return static_cast<int>(optimised | (sun_0 ? 8u : 0u) | (sun_1 ? 16u : 0u));
}

class SplitSecondPlan : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto loaded = load_domain(sgtest::split_second_spec());
    if (!loaded.ok()) return;
    spec_ = new DomainSpec(std::move(loaded).value());
    auto expanded = expand(*spec_);
    if (!expanded.ok()) return;
    plan_ = new PermutationPlan(std::move(expanded).value());
  }
  // A failure to load fails every test rather than skipping them.
  void SetUp() override {
    ASSERT_NE(spec_, nullptr) << "cannot load " << sgtest::split_second_spec();
    ASSERT_NE(plan_, nullptr) << "cannot expand " << sgtest::split_second_spec();
  }
  static void TearDownTestSuite() {
    delete plan_;
    delete spec_;
  }
  static inline DomainSpec* spec_ = nullptr;
  static inline PermutationPlan* plan_ = nullptr;
};

// The product's table against the listing's logic: two independent statements of Listing 4.8
// (the literal above, and this), so a typo in either cannot hide an error in the spec's rules.
TEST_F(SplitSecondPlan, LookupTableEqualsTheListingsLogicForEveryRawId) {
  ASSERT_EQ(plan_->raw.size(), 128u);
  for (std::uint32_t raw = 0; raw < 128; ++raw) {
    const RawPermutation& p = plan_->raw[raw];
    EXPECT_EQ(p.pruned ? -1 : static_cast<int>(p.optimised), listing_logic(raw)) << "raw " << raw;
  }
}

TEST_F(SplitSecondPlan, LookupTableEqualsListing48ForEveryRawId) {
  ASSERT_EQ(plan_->raw.size(), 128u);
  ASSERT_EQ(plan_->optimised.size(), 32u);
  for (std::uint32_t raw = 0; raw < 128; ++raw) {
    const RawPermutation& p = plan_->raw[raw];
    EXPECT_EQ(p.id, raw);
    EXPECT_EQ(p.pruned, kListing48[raw] < 0) << "raw " << raw;
    if (!p.pruned) {
      EXPECT_EQ(static_cast<int>(p.optimised), kListing48[raw]) << "raw " << raw;
    }
  }
}

TEST_F(SplitSecondPlan, SpotChecksFromTheDesignTable) {
  EXPECT_EQ(plan_->raw[65].optimised, 0u);    // solid shadow + sun, no fade: no sun code
  EXPECT_EQ(plan_->raw[69].optimised, 8u);    // solid + fade + sun
  EXPECT_EQ(plan_->raw[64].optimised, 16u);   // sun, lit
  EXPECT_EQ(plan_->raw[66].optimised, 24u);   // sun + soft
  EXPECT_EQ(plan_->raw[126].optimised, 31u);  // everything but solid
  EXPECT_TRUE(plan_->raw[127].pruned);
}

TEST_F(SplitSecondPlan, PrunedSetIsExactlySolidWithSoft) {
  std::set<std::uint32_t> pruned;
  for (const RawPermutation& p : plan_->raw)
    if (p.pruned) pruned.insert(p.id);
  std::set<std::uint32_t> expected;
  for (std::uint32_t raw = 0; raw < 128; ++raw)
    if ((raw & 3u) == 3u) expected.insert(raw);
  EXPECT_EQ(pruned, expected);
  EXPECT_EQ(pruned.size(), 32u);
}

// LIGHT_SCATTERING and SKY are value-style (light_pass.glsl reads them as expressions, so that
// the kinds specs build the same text): always defined, as NAME=0 or NAME=1, in bit order.
TEST_F(SplitSecondPlan, RawDefinesFollowTheBits) {
  EXPECT_EQ(shadergen::raw_defines(*spec_, 0), (std::vector<std::string>{"LIGHT_SCATTERING=0", "SKY=0"}));
  EXPECT_EQ(shadergen::raw_defines(*spec_, 69),
            (std::vector<std::string>{"SOLID_SHADOW", "SHADOW_FADE", "LIGHT_SCATTERING=0", "SKY=0", "SUN_LIGHT"}));
  EXPECT_EQ(shadergen::raw_defines(*spec_, 40), (std::vector<std::string>{"LIGHT_SCATTERING=1", "SKY=1"}));
}

TEST_F(SplitSecondPlan, EveryOptimisedPermutationIsACompilableRawOne) {
  for (const OptimisedPermutation& o : plan_->optimised) {
    const RawPermutation& twin = plan_->raw[o.raw_equivalent];
    EXPECT_FALSE(twin.pruned) << "optimised " << o.id;
    EXPECT_EQ(o.defines, shadergen::raw_defines(*spec_, twin.id)) << "optimised " << o.id;
  }
  EXPECT_EQ(plan_->optimised[31].defines, (std::vector<std::string>{"SOFT_SHADOW", "SHADOW_FADE", "LIGHT_SCATTERING=1",
                                                                    "MSAA_EDGE", "SKY=1", "SUN_LIGHT"}));
  EXPECT_EQ(plan_->optimised[0].defines, (std::vector<std::string>{"SOLID_SHADOW", "LIGHT_SCATTERING=0", "SKY=0"}));
  EXPECT_EQ(plan_->optimised[16].defines, (std::vector<std::string>{"LIGHT_SCATTERING=0", "SKY=0", "SUN_LIGHT"}));
}

TEST_F(SplitSecondPlan, EveryOptimisedIdIsReachedAndCountsAddUp) {
  std::uint32_t total = 0;
  for (const OptimisedPermutation& o : plan_->optimised) {
    EXPECT_GT(o.raw_mapped, 0u) << "optimised " << o.id << " is never used";
    total += o.raw_mapped;
  }
  EXPECT_EQ(total, 96u);
}

TEST_F(SplitSecondPlan, ExplanationNamesTheRuleAndTheTarget) {
  std::string text = format_explanation(*spec_, *plan_, 69);
  EXPECT_NE(text.find("raw ID 69 = SHADOW_SOLID | SHADOW_FADE | SUN_LIGHT"), std::string::npos) << text;
  EXPECT_NE(text.find("-> optimised ID 8 = SUN_0"), std::string::npos) << text;
  std::string pruned = format_explanation(*spec_, *plan_, 3);
  EXPECT_NE(pruned.find("pruned: it matches the impossible rule \"SHADOW_SOLID && SHADOW_SOFT\""), std::string::npos)
      << pruned;
}

TEST(ToyPlan, SecondDomainWithOtherBitsAndRules) {
  auto spec = load_domain(sgtest::toy_spec());
  ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
  EXPECT_EQ(spec->raw_space(), 16u);
  EXPECT_EQ(spec->optimised_count(), 4u);
  // Features are declared out of bit order; the spec indexes them by bit.
  EXPECT_EQ(spec->raw_features[0].name, "LIT");
  EXPECT_EQ(spec->raw_features[2].define, "SOFT_PARTICLES");
  auto plan = expand(*spec);
  ASSERT_TRUE(plan.ok());
  const std::array<int, 16> expected = {0, 1, 2, 3, 2, 3, 2, 3, 1, -1, 3, -1, 3, -1, 3, -1};
  for (std::uint32_t raw = 0; raw < 16; ++raw) {
    EXPECT_EQ(plan->raw[raw].pruned, expected[raw] < 0) << raw;
    if (expected[raw] >= 0) {
      EXPECT_EQ(static_cast<int>(plan->raw[raw].optimised), expected[raw]) << raw;
    }
  }
  EXPECT_EQ(plan->optimised[3].defines, (std::vector<std::string>{"LIT", "USE_TEXTURE", "SOFT_PARTICLES"}));
}

}  // namespace
}  // namespace shadergen
