// Raw IDs written as text: shadergen::parse_combination() (shadergen/registry.h), the one
// parser behind the generated find_raw_id(), `shadergen explain` and variants files, and
// describe_combination_error() (spec/combination_text.h), the words for each refusal. Every
// error kind is checked for its word, its position, its feature and its exact message.
#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <string>

#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "shadergen/registry.h"
#include "spec/combination_text.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

constexpr std::array<std::string_view, 3> kTaaValues{"0", "1", "2"};
constexpr std::array<std::string_view, 3> kToneValues{"LINEAR", "ACES", "-1"};
// A name that differs from its define, a define equal to another feature's name (SKY is the
// define of HORIZON; the name SKY wins), and a valued field that ends at bit 31.
constexpr std::array<Feature, 6> kFeatures{{
    {"SHADOW_SOFT", "SOFT_SHADOW", 0, 1, {}},
    {"MSAA_EDGE", "MSAA_EDGE", 1, 1, {}},
    {"TAA_QUALITY", "TAA_Q", 2, 2, kTaaValues},
    {"SKY", "SKY_PIXEL", 4, 1, {}},
    {"HORIZON", "SKY", 5, 1, {}},
    {"TONEMAP", "TONEMAP", 30, 2, kToneValues},
}};

// At compile time, as the generated find_raw_id() is used in static_asserts.
static_assert(parse_combination(kFeatures, "SHADOW_SOFT|TAA_QUALITY=2").raw_id == (1u | (2u << 2)));
static_assert(parse_combination(kFeatures, "TONEMAP=-1").raw_id == 0x80000000u);
static_assert(parse_combination(kFeatures, "MSAA_EDGE=1").error == CombinationError::boolean_with_value);
static_assert(find_raw_id(kFeatures, " (none) ") == 0u);
static_assert(!find_raw_id(kFeatures, "SOFT_SHADOW"));

struct Case {
  std::string_view text;
  std::uint32_t raw_id;
  CombinationError error;
  std::string_view word;
  std::size_t position;
  std::size_t feature;
  std::string_view message;
};

constexpr std::uint32_t kSoft = 1u, kEdge = 2u, kSky = 16u, kHorizon = 32u;

const Case kAccepted[] = {
    {"", 0, CombinationError::none, "", 0, 0, ""},
    {" \t ", 0, CombinationError::none, "", 0, 0, ""},
    {"(none)", 0, CombinationError::none, "", 0, 0, ""},
    {"  (none)\t", 0, CombinationError::none, "", 0, 0, ""},
    {"SHADOW_SOFT", kSoft, CombinationError::none, "", 0, 0, ""},
    {"SHADOW_SOFT|MSAA_EDGE", kSoft | kEdge, CombinationError::none, "", 0, 0, ""},
    {" MSAA_EDGE |\tSHADOW_SOFT ", kSoft | kEdge, CombinationError::none, "", 0, 0, ""},
    {"SKY", kSky, CombinationError::none, "", 0, 0, ""},
    {"SKY|HORIZON", kSky | kHorizon, CombinationError::none, "", 0, 0, ""},
    {"TAA_QUALITY=0", 0, CombinationError::none, "", 0, 0, ""},
    {"TAA_QUALITY = 1", 1u << 2, CombinationError::none, "", 0, 0, ""},
    {"TAA_QUALITY=2|SKY", (2u << 2) | kSky, CombinationError::none, "", 0, 0, ""},
    {"TONEMAP=ACES", 1u << 30, CombinationError::none, "", 0, 0, ""},
    {"TONEMAP=-1|SHADOW_SOFT", (2u << 30) | kSoft, CombinationError::none, "", 0, 0, ""},
};

const Case kRefused[] = {
    {"SKY||MSAA_EDGE", 0, CombinationError::empty_word, "", 4, 0,
     "an empty word at offset 4: two '|' in a row, or one at the start or the end"},
    {"SKY|", 0, CombinationError::empty_word, "", 4, 0,
     "an empty word at offset 4: two '|' in a row, or one at the start or the end"},
    {"| SKY", 0, CombinationError::empty_word, "", 0, 0,
     "an empty word at offset 0: two '|' in a row, or one at the start or the end"},
    {"SKY| =2", 0, CombinationError::empty_word, "=2", 5, 0, "\"=2\" names no feature before its '='"},
    {"SKY|FOO", 0, CombinationError::unknown_name, "FOO", 4, 0,
     "unknown feature \"FOO\" (known: SHADOW_SOFT, MSAA_EDGE, TAA_QUALITY, SKY, HORIZON, TONEMAP)"},
    {"SHADOW_SOTF", 0, CombinationError::unknown_name, "SHADOW_SOTF", 0, 0,
     "unknown feature \"SHADOW_SOTF\" (known: SHADOW_SOFT, MSAA_EDGE, TAA_QUALITY, SKY, HORIZON, TONEMAP); did you "
     "mean SHADOW_SOFT?"},
    {"sky", 0, CombinationError::unknown_name, "sky", 0, 0,
     "unknown feature \"sky\" (known: SHADOW_SOFT, MSAA_EDGE, TAA_QUALITY, SKY, HORIZON, TONEMAP)"},
    {"SHADOW SOFT", 0, CombinationError::unknown_name, "SHADOW SOFT", 0, 0,
     "unknown feature \"SHADOW SOFT\" (known: SHADOW_SOFT, MSAA_EDGE, TAA_QUALITY, SKY, HORIZON, TONEMAP)"},
    {"SKY+MSAA_EDGE", 0, CombinationError::unknown_name, "SKY+MSAA_EDGE", 0, 0,
     "unknown feature \"SKY+MSAA_EDGE\" (known: SHADOW_SOFT, MSAA_EDGE, TAA_QUALITY, SKY, HORIZON, TONEMAP)"},
    {"SKY,MSAA_EDGE", 0, CombinationError::unknown_name, "SKY,MSAA_EDGE", 0, 0,
     "unknown feature \"SKY,MSAA_EDGE\" (known: SHADOW_SOFT, MSAA_EDGE, TAA_QUALITY, SKY, HORIZON, TONEMAP)"},
    {"(none)|SKY", 0, CombinationError::unknown_name, "(none)", 0, 0,
     "\"(none)\" stands alone: it means every feature off"},
    {"SKY|\x1b[2J", 0, CombinationError::unknown_name, "\x1b[2J", 4, 0,
     "unknown feature \"\\x1b[2J\" (known: SHADOW_SOFT, MSAA_EDGE, TAA_QUALITY, SKY, HORIZON, TONEMAP)"},
    {"MSAA_EDGE|SOFT_SHADOW", 0, CombinationError::define_name, "SOFT_SHADOW", 10, 0,
     "\"SOFT_SHADOW\" is the define of feature SHADOW_SOFT; name the feature"},
    {"TAA_Q=1", 0, CombinationError::define_name, "TAA_Q", 0, 2,
     "\"TAA_Q\" is the define of feature TAA_QUALITY; name the feature"},
    {"12", 0, CombinationError::number, "12", 0, 0, "\"12\" is a number; name the features instead, joined by '|'"},
    {"SKY | 0x5", 0, CombinationError::number, "0x5", 6, 0,
     "\"0x5\" is a number; name the features instead, joined by '|'"},
    {"0b11", 0, CombinationError::number, "0b11", 0, 0,
     "\"0b11\" is a number; name the features instead, joined by '|'"},
    {"12abc", 0, CombinationError::unknown_name, "12abc", 0, 0,
     "unknown feature \"12abc\" (known: SHADOW_SOFT, MSAA_EDGE, TAA_QUALITY, SKY, HORIZON, TONEMAP)"},
    {"MSAA_EDGE=1", 0, CombinationError::boolean_with_value, "MSAA_EDGE=1", 0, 1,
     "feature MSAA_EDGE is a boolean: write MSAA_EDGE alone, or leave it out (MSAA_EDGE=1 is not accepted)"},
    {"SKY|MSAA_EDGE = 0", 0, CombinationError::boolean_with_value, "MSAA_EDGE = 0", 4, 1,
     "feature MSAA_EDGE is a boolean: write MSAA_EDGE alone, or leave it out (MSAA_EDGE = 0 is not accepted)"},
    {"SKY=yes", 0, CombinationError::boolean_with_value, "SKY=yes", 0, 3,
     "feature SKY is a boolean: write SKY alone, or leave it out (SKY=yes is not accepted)"},
    {"SKY=", 0, CombinationError::boolean_with_value, "SKY=", 0, 3,
     "feature SKY is a boolean: write SKY alone, or leave it out (SKY= is not accepted)"},
    {"SKY|TAA_QUALITY", 0, CombinationError::missing_value, "TAA_QUALITY", 4, 2,
     "feature TAA_QUALITY takes a value: write TAA_QUALITY=<value> (values: 0, 1, 2)"},
    {"TAA_QUALITY=7", 0, CombinationError::unknown_value, "7", 12, 2,
     "TAA_QUALITY has no value \"7\" (values: 0, 1, 2)"},
    {"TAA_QUALITY=", 0, CombinationError::unknown_value, "", 12, 2, "TAA_QUALITY has no value \"\" (values: 0, 1, 2)"},
    {"TONEMAP=aces", 0, CombinationError::unknown_value, "aces", 8, 5,
     "TONEMAP has no value \"aces\" (values: LINEAR, ACES, -1)"},
    {"TAA_QUALITY=1=2", 0, CombinationError::unknown_value, "1=2", 12, 2,
     "TAA_QUALITY has no value \"1=2\" (values: 0, 1, 2)"},
    {"SKY|MSAA_EDGE|SKY", 0, CombinationError::repeated, "SKY", 14, 3,
     "feature SKY is named twice (again as \"SKY\"); name each feature once"},
    {"TAA_QUALITY=0|TAA_QUALITY=0", 0, CombinationError::repeated, "TAA_QUALITY=0", 14, 2,
     "feature TAA_QUALITY is named twice (again as \"TAA_QUALITY=0\"); name each feature once"},
};

void expect_case(const Case& c) {
  SCOPED_TRACE("text \"" + std::string(c.text) + "\"");
  const ParsedCombination parsed = parse_combination(kFeatures, c.text);
  EXPECT_EQ(parsed.error, c.error);
  EXPECT_EQ(parsed.raw_id, c.raw_id);
  EXPECT_EQ(parsed.word, c.word);
  EXPECT_EQ(parsed.position, c.position);
  EXPECT_EQ(parsed.feature, c.feature);
  EXPECT_EQ(static_cast<bool>(parsed), c.error == CombinationError::none);
  if (!parsed) {
    EXPECT_EQ(parsed.word.data(), c.text.data() + c.position) << "the word is a view into the text";
  }
  EXPECT_EQ(describe_combination_error(parsed, kFeatures), c.message);
  const std::optional<std::uint32_t> found = find_raw_id(kFeatures, c.text);
  EXPECT_EQ(found, parsed ? std::optional<std::uint32_t>(c.raw_id) : std::nullopt);
}

TEST(CombinationText, AcceptsNamesValuesBlanksAndNone) {
  for (const Case& c : kAccepted) expect_case(c);
}

TEST(CombinationText, RefusesEachErrorKindNamingTheWord) {
  for (const Case& c : kRefused) expect_case(c);
  // Every kind but none has a case above.
  for (auto kind : {CombinationError::empty_word, CombinationError::unknown_name, CombinationError::define_name,
                    CombinationError::number, CombinationError::boolean_with_value, CombinationError::missing_value,
                    CombinationError::unknown_value, CombinationError::repeated}) {
    bool covered = false;
    for (const Case& c : kRefused) covered = covered || c.error == kind;
    EXPECT_TRUE(covered) << static_cast<int>(kind);
  }
}

// The first refused word is the one reported, wherever it is.
TEST(CombinationText, ReportsTheFirstRefusedWord) {
  const ParsedCombination parsed = parse_combination(kFeatures, "SKY|FOO|MSAA_EDGE=1");
  EXPECT_EQ(parsed.error, CombinationError::unknown_name);
  EXPECT_EQ(parsed.word, "FOO");
}

// describe_raw() prints a raw ID the parser reads back: "A | B=v", "(none)" for 0.
TEST(CombinationText, ReadsBackWhatDescribeRawPrintsForEveryRawId) {
  auto loaded = load_domain(sgtest::fixtures_dir() / "valued" / "valued.json");
  ASSERT_TRUE(loaded.ok());
  const DomainSpec& spec = *loaded;
  const FeatureTable table(spec);
  std::size_t read = 0;
  for (std::uint32_t id = 0; id < spec.raw_space(); ++id) {
    const std::string text = describe_raw(spec, id);
    if (text.find('?') != std::string::npos) continue;  // a field holding no value: not a combination
    EXPECT_EQ(find_raw_id(table.features(), text), id) << text;
    ++read;
  }
  EXPECT_GT(read, 0u);
}

// combination_text() (the generated to_string()) prints exactly what describe_raw() (`shadergen
// explain`) prints, for every raw ID of fixtures with features out of bit order, valued fields
// and fields past their values; and "(none)" where no boolean is on and nothing is valued.
TEST(CombinationText, CombinationTextIsExplainsText) {
  for (const char* name : {"valued", "typed_api", "toy"}) {
    auto loaded = load_domain(sgtest::fixtures_dir() / name / (std::string(name) + ".json"));
    ASSERT_TRUE(loaded.ok()) << name;
    const FeatureTable table(*loaded);
    for (std::uint32_t id = 0; id < loaded->raw_space(); ++id)
      EXPECT_EQ(combination_text(table.features(), id), describe_raw(*loaded, id)) << name << " raw " << id;
  }
  EXPECT_EQ(combination_text(kFeatures, 0), "TAA_QUALITY=0 | TONEMAP=LINEAR");
  EXPECT_EQ(combination_text(std::span<const Feature>(kFeatures).first(2), 0), "(none)");
  EXPECT_EQ(combination_text(kFeatures, kSky | kEdge | (3u << 2) | 0x80000000u),
            "MSAA_EDGE | TAA_QUALITY=? | SKY | TONEMAP=-1");
}

// FeatureTable lists a spec's features in spec order, as the generated kFeatures does.
TEST(CombinationText, FeatureTableFollowsTheSpecOrder) {
  auto loaded = load_domain(sgtest::fixtures_dir() / "typed_api" / "typed_api.json");
  ASSERT_TRUE(loaded.ok());
  FeatureTable table(*loaded);
  const FeatureTable moved(std::move(table));
  std::span<const Feature> features = moved.features();
  ASSERT_EQ(features.size(), 4u);
  EXPECT_EQ(features[0].name, "TONEMAP");
  EXPECT_EQ(features[0].bit, 3u);
  EXPECT_EQ(features[0].width, 2u);
  ASSERT_EQ(features[0].values.size(), 3u);
  EXPECT_EQ(features[0].values[2], "FILMIC");
  EXPECT_EQ(features[1].name, "SHARPEN");
  EXPECT_EQ(features[1].define, "USE_SHARPEN");
  EXPECT_EQ(features[3].values[0], "-1");
  EXPECT_EQ(find_raw_id(features, "TONEMAP=FILMIC|BIAS=1|QUALITY=0"), (2u << 3) | (1u << 5));
}

}  // namespace
}  // namespace shadergen
