// The generated C++ of a 32-bit domain built from a variants file (tests/fixtures/wide32, through
// shadergen_add_permutations(VARIANTS)): 2^32 raw IDs, 8 listed, a 10-bit optimised ID in a
// 16-bit table that lives in the generated source. Every lookup says "none" for an ID that is
// not built, and the listed ones are drawn as the spec's rules say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string_view>

#include "wide32_permutations.h"

namespace {

constexpr std::string_view kListed[] = {
    "QUALITY=0",
    "F00 | QUALITY=1",
    "F01 | F02 | QUALITY=2",
    "F28 | F29 | QUALITY=3",
    "F10 | F20 | QUALITY=1",
    "F03 | F04 | F05 | F06 | QUALITY=0",
    "F29 | QUALITY=0",
    "F15 | QUALITY=2",
};

// The optimised ID the spec's rules give: bit b when any of F(3b), F(3b+1), F(3b+2) is on.
wide32::OptimisedId optimised_by_rules(wide32::RawId raw_id) {
  std::uint32_t id = 0;
  for (std::uint32_t b = 0; b < 10; ++b)
    if (raw_id.value() & (7u << (3 * b))) id |= 1u << b;
  return wide32::OptimisedId(id);
}

TEST(Wide32Registry, TheDomainIs32BitsWideAndHoldsTheListedIds) {
  static_assert(wide32::kRawBits == 32);
  static_assert(wide32::kRawCount == 8);
  const shadergen::Registry& registry = wide32::registry();
  EXPECT_EQ(registry.raw.size(), 8u);
  EXPECT_TRUE(registry.raw_to_optimised.empty()) << "10 optimised bits: the 16-bit table";
  EXPECT_EQ(registry.raw_to_optimised_wide.size(), 8u);
  EXPECT_TRUE(std::is_sorted(registry.raw.begin(), registry.raw.end(),
                             [](const auto& a, const auto& b) { return a.id < b.id; }));
}

TEST(Wide32Registry, EveryListedCombinationIsDrawnAsTheRulesSay) {
  const shadergen::Registry& registry = wide32::registry();
  for (std::string_view text : kListed) {
    SCOPED_TRACE(std::string(text));
    std::optional<wide32::RawId> raw_id = wide32::find_raw_id(text);
    ASSERT_TRUE(raw_id.has_value());
    EXPECT_TRUE(wide32::is_valid_raw_id(*raw_id));
    EXPECT_EQ(wide32::to_string(*raw_id), text) << "explain's text, in bit order";
    EXPECT_TRUE(wide32::is_possible(wide32::features(*raw_id)));
    ASSERT_EQ(wide32::optimised_id(*raw_id), optimised_by_rules(*raw_id));
    ASSERT_EQ(registry.optimised_id(*raw_id), optimised_by_rules(*raw_id));
    const shadergen::Permutation* raw = registry.find_raw(*raw_id);
    ASSERT_NE(raw, nullptr);
    EXPECT_EQ(raw->id, raw_id->value());
    ASSERT_FALSE(raw->spirv.empty());
    EXPECT_EQ(raw->spirv[0], 0x07230203u);
    const shadergen::Permutation* drawn = registry.optimised_for_raw(*raw_id);
    ASSERT_NE(drawn, nullptr);
    EXPECT_EQ(drawn->id, optimised_by_rules(*raw_id).value());
    EXPECT_FALSE(drawn->spirv.empty());
  }
}

// Not listed, impossible, or a value out of its enum: "none" from every lookup.
TEST(Wide32Registry, WhatIsNotBuiltIsNoneEverywhere) {
  const shadergen::Registry& registry = wide32::registry();
  for (std::string_view text : {"F07", "F29 | QUALITY=1", "F08 | QUALITY=3"}) {
    SCOPED_TRACE(std::string(text));
    std::optional<wide32::RawId> raw_id = wide32::find_raw_id(text);
    ASSERT_TRUE(raw_id.has_value()) << "a possible combination has its raw ID, built or not";
    EXPECT_TRUE(wide32::is_possible(wide32::features(*raw_id)));
    EXPECT_EQ(wide32::find_raw_id(wide32::to_string(*raw_id)), raw_id);
    EXPECT_FALSE(wide32::is_valid_raw_id(*raw_id));
    EXPECT_EQ(wide32::optimised_id(*raw_id), std::nullopt);
    EXPECT_EQ(registry.find_raw(*raw_id), nullptr);
    EXPECT_EQ(registry.optimised_id(*raw_id), std::nullopt);
    EXPECT_EQ(registry.optimised_for_raw(*raw_id), nullptr);
  }
  for (std::uint32_t id : {1u, 0xffffffffu, 0x80000000u, 127u})
    EXPECT_EQ(registry.optimised_for_raw(wide32::RawId(id)), nullptr) << id;
  // The impossible rule "F00 && F29" holds in is_possible() though no table lists the IDs.
  EXPECT_EQ(wide32::find_raw_id("F00 | F29"), std::nullopt);
  EXPECT_FALSE(wide32::is_possible(wide32::Features{.F00 = true, .F29 = true}));
  EXPECT_FALSE(wide32::is_possible(wide32::features(wide32::RawId(0xffffffffu))));
  EXPECT_TRUE(wide32::is_possible(wide32::Features{.F00 = true, .F28 = true}));
  EXPECT_EQ(wide32::find_raw_id("F00 | F28"), wide32::RawId((1u << 0) | (1u << 28)));
  EXPECT_EQ(wide32::raw_id(wide32::Features{.F07 = true}), std::nullopt);
  EXPECT_EQ(wide32::raw_id(wide32::Features{.F15 = true, .QUALITY = wide32::QUALITY_value::_2}),
            wide32::find_raw_id("F15|QUALITY=2"));
  auto cast = static_cast<wide32::QUALITY_value>(9);
  EXPECT_EQ(wide32::raw_id(wide32::Features{.QUALITY = cast}), std::nullopt);
  EXPECT_EQ(registry.find_optimised(wide32::OptimisedId(4)), nullptr) << "optimised ID 4: no listed raw ID maps to it";
}

}  // namespace
