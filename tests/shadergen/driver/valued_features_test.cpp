// Valued features (tests/fixtures/valued): a feature with "values" takes the fewest bits that
// hold them, each raw ID is compiled with `#define NAME <value>`, IDs whose field holds no
// value are pruned, and rules compare values. The fixture: SHARPEN bit 0 (boolean),
// TAA_QUALITY bits 1-2 (0, 1, 2), TONEMAP bits 3-4 (LINEAR, ACES, FILMIC); impossible
// "TAA_QUALITY == 0 && SHARPEN"; TEMPORAL = TAA_QUALITY >= 1, CURVED = TONEMAP != LINEAR.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "shadergen/build.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "test_helpers.h"

namespace {

using nlohmann::json;

sgtest::fs::path valued_spec() { return sgtest::fixtures_dir() / "valued" / "valued.json"; }

struct Fields {
  bool sharpen;
  std::uint32_t taa, tonemap;  // value indices
};
Fields fields_of(std::uint32_t raw) { return {(raw & 1u) != 0, (raw >> 1) & 3u, (raw >> 3) & 3u}; }

class ValuedFeatures : public ::testing::Test {
 protected:
  void SetUp() override {
    auto spec = shadergen::load_domain(valued_spec());
    ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
    spec_ = std::move(spec).value();
    auto plan = shadergen::expand(spec_);
    ASSERT_TRUE(plan.ok()) << plan.errors().front().to_string();
    plan_ = std::move(plan).value();
  }
  shadergen::DomainSpec spec_;
  shadergen::PermutationPlan plan_;
};

TEST_F(ValuedFeatures, EachTakesTheFewestBitsThatHoldItsValues) {
  ASSERT_EQ(spec_.raw_features.size(), 3u);
  EXPECT_EQ(spec_.raw_features[1].width, 2u);
  EXPECT_EQ(spec_.raw_features[1].values, (std::vector<std::string>{"0", "1", "2"}));
  EXPECT_EQ(spec_.raw_features[2].values, (std::vector<std::string>{"LINEAR", "ACES", "FILMIC"}));
  EXPECT_EQ(spec_.raw_bits(), 5u);
  EXPECT_EQ(plan_.raw.size(), 32u);
}

// The table and the pruning, worked out here from the fields instead of the rule engine.
TEST_F(ValuedFeatures, FieldsWithoutAValueArePrunedAndRulesCompareValues) {
  for (std::uint32_t id = 0; id < 32; ++id) {
    SCOPED_TRACE("raw " + std::to_string(id));
    Fields f = fields_of(id);
    bool no_value = f.taa == 3 || f.tonemap == 3;
    EXPECT_EQ(plan_.raw[id].pruned, no_value || (f.taa == 0 && f.sharpen));
    EXPECT_EQ(plan_.raw[id].unvalued >= 0, no_value);
    EXPECT_EQ(plan_.raw[id].optimised,
              (f.taa >= 1 && f.taa < 3 ? 1u : 0u) | (f.tonemap == 1 || f.tonemap == 2 ? 2u : 0u));
  }
}

TEST_F(ValuedFeatures, EveryRawPermutationIsCompiledWithItsValues) {
  const std::vector<std::string> tonemaps = {"LINEAR", "ACES", "FILMIC"};
  for (std::uint32_t id = 0; id < 32; ++id) {
    Fields f = fields_of(id);
    if (plan_.raw[id].unvalued >= 0) continue;
    std::vector<std::string> expected;
    if (f.sharpen) expected.push_back("SHARPEN");
    expected.push_back("TAA_QUALITY=" + std::to_string(f.taa));
    expected.push_back("TONEMAP=" + tonemaps[f.tonemap]);
    EXPECT_EQ(shadergen::raw_defines(spec_, id), expected) << "raw " << id;
  }
  // Variants name a valued feature with its value.
  EXPECT_EQ(plan_.optimised[3].defines, (std::vector<std::string>{"SHARPEN", "TAA_QUALITY=2", "TONEMAP=ACES"}));
  EXPECT_EQ(plan_.optimised[3].raw_equivalent, 0b01101u);
  EXPECT_EQ(plan_.optimised[0].defines, (std::vector<std::string>{"TAA_QUALITY=0", "TONEMAP=LINEAR"}));
}

TEST_F(ValuedFeatures, LutListAndExplainPrintTheValues) {
  std::string lut = shadergen::format_lut(spec_, plan_);
  EXPECT_TRUE(sgtest::contains(lut,
                               "raw bits:       0=SHARPEN, 1-2=TAA_QUALITY (0, 1, 2), 3-4=TONEMAP (LINEAR, ACES, "
                               "FILMIC)\n"))
      << lut;
  EXPECT_TRUE(sgtest::contains(lut, "           3               8  SHARPEN TAA_QUALITY=2 TONEMAP=ACES\n")) << lut;
  std::string list = shadergen::format_list(spec_, plan_);
  EXPECT_TRUE(sgtest::contains(list, "  raw   11 -> optimised   3  compiled  SHARPEN TAA_QUALITY=1 TONEMAP=ACES\n"))
      << list;
  std::string explained = shadergen::format_explanation(spec_, plan_, 11);
  EXPECT_TRUE(sgtest::contains(explained, "raw ID 11 = SHARPEN | TAA_QUALITY=1 | TONEMAP=ACES\n")) << explained;
  EXPECT_TRUE(sgtest::contains(explained, "  bits 1-2  TAA_QUALITY = 1 (#define TAA_QUALITY 1); values: 0, 1, 2\n"))
      << explained;
  EXPECT_TRUE(sgtest::contains(explained, "  bit 0  [x] TEMPORAL  because (TAA_QUALITY >= 1)\n")) << explained;
  std::string no_value = shadergen::format_explanation(spec_, plan_, 6);
  EXPECT_TRUE(sgtest::contains(no_value,
                               "pruned: bits 1-2 hold index 3, but TAA_QUALITY has 3 values; no shader is "
                               "compiled for it.\n"))
      << no_value;
}

TEST(ValuedFeaturesCli, ExplainTakesNameEqualsValue) {
  sgtest::ProcessResult r = sgtest::run_process(
      sgtest::shadergen_exe(), {"explain", valued_spec().string(), "SHARPEN|TAA_QUALITY=1|TONEMAP=ACES"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(sgtest::contains(r.out, "raw ID 11 = SHARPEN | TAA_QUALITY=1 | TONEMAP=ACES\n")) << r.out;
  sgtest::ProcessResult bad =
      sgtest::run_process(sgtest::shadergen_exe(), {"explain", valued_spec().string(), "TONEMAP=UGLY"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err, "shadergen: error: TONEMAP has no value \"UGLY\" (values: LINEAR, ACES, FILMIC)\n");
}

// Each value reaches the shader: the three TAA qualities give three different blobs.
TEST(ValuedFeaturesBuild, EveryValueReachesTheShader) {
  sgtest::TempDir dir("valued-build");
  auto summary = sgtest::build(valued_spec(), dir / "out", dir / "cache");
  ASSERT_TRUE(summary.ok()) << summary.errors().front().to_string();
  EXPECT_EQ(summary->pruned, 17u);
  EXPECT_EQ(summary->unique_sources, 15u);
  json manifest = json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["raw"][2]["defines"], json::array({"TAA_QUALITY=1", "TONEMAP=LINEAR"}));
  std::set<std::string> taa_hashes;
  for (std::uint32_t id : {0u, 2u, 4u}) taa_hashes.insert(manifest["raw"][id]["hash"].get<std::string>());
  EXPECT_EQ(taa_hashes.size(), 3u);
  std::set<std::string> tonemap_hashes;
  for (std::uint32_t id : {0u, 8u, 16u}) tonemap_hashes.insert(manifest["raw"][id]["hash"].get<std::string>());
  EXPECT_EQ(tonemap_hashes.size(), 3u);
}

}  // namespace
