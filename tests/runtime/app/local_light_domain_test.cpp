// The local-light domain (permutations/local_lights.json): the raw IDs its rules prune are
// exactly those the model rules out, every other one compiles in both builds (multi-
// and single-sampled G-buffer), and the generated typed API names the same IDs.
#include <local_lights_1x_shaders.h>
#include <local_lights_shaders.h>

#include <gtest/gtest.h>

namespace tilelight::test {
namespace {

// ---------------------------------------------------------------------------------------------
// The domain: 2 bits of light type (3 values), GLOBE, BACK_COLOUR, MSAA_EDGE, SHADOWED.

constexpr std::uint32_t kTypeMask = 3u;
constexpr std::uint32_t kBox = 2u;
constexpr std::uint32_t kBackColourBit = 1u << 3;
constexpr std::uint32_t kShadowedBit = 1u << 5;

// What the spec's rules say: the type field's fourth index has no value, and only box lights
// have a back colour.
bool rules_prune(std::uint32_t raw) {
  const std::uint32_t type = raw & kTypeMask;
  return type == 3u || ((raw & kBackColourBit) != 0 && type != kBox);
}

TEST(LocalLightDomain, PrunedIdsAreThoseTheRulesSayAndTheRestCompile) {
  static_assert(local_lights::kRawCount == 64);
  for (const shadergen::Registry* registry : {&local_lights::registry(), &local_lights_1x::registry()}) {
    ASSERT_EQ(registry->raw.size(), 64u);
    std::uint32_t compiled = 0;
    for (const shadergen::Permutation& p : registry->raw) {
      EXPECT_EQ(p.pruned, rules_prune(p.id)) << registry->name << " raw " << p.id;
      EXPECT_EQ(p.spirv.empty(), p.pruned) << registry->name << " raw " << p.id;
      compiled += p.pruned ? 0 : 1;
    }
    EXPECT_EQ(compiled, 32u) << registry->name;
    EXPECT_NE(registry->companion("full_screen"), nullptr);
    EXPECT_NE(registry->companion("shadow_caster"), nullptr);
  }
  // The typed API names the same IDs.
  using local_lights::LIGHT_TYPE_value;
  EXPECT_EQ(local_lights::raw_id({.LIGHT_TYPE = LIGHT_TYPE_value::POINT, .BACK_COLOUR = true}), std::nullopt);
  EXPECT_EQ(local_lights::raw_id({.LIGHT_TYPE = LIGHT_TYPE_value::BOX, .BACK_COLOUR = true}),
            local_lights::RawId(kBox | kBackColourBit));
  EXPECT_EQ(local_lights::raw_id({.LIGHT_TYPE = LIGHT_TYPE_value::SPOT, .SHADOWED = true}),
            local_lights::RawId(1u | kShadowedBit));
}

}  // namespace
}  // namespace tilelight::test
