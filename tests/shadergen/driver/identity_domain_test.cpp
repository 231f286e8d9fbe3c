// A domain without "optimised" (tests/fixtures/identity: 11 material features, 6 impossible
// rules, 405 of 2,048 raw IDs compiled): no collapse, every compiled raw ID is its own
// permutation, no lookup table, and the views say so.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <set>

#include "shadergen/build.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "test_helpers.h"

namespace {

using nlohmann::json;

sgtest::fs::path identity_spec() { return sgtest::fixtures_dir() / "identity" / "identity.json"; }

TEST(IdentityDomain, ExpandsToTheRawPermutationsAlone) {
  auto spec = shadergen::load_domain(identity_spec());
  ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
  EXPECT_FALSE(spec->collapsed);
  EXPECT_EQ(spec->optimised_count(), 0u);
  auto plan = shadergen::expand(*spec);
  ASSERT_TRUE(plan.ok()) << plan.errors().front().to_string();
  EXPECT_TRUE(plan->optimised.empty());
  ASSERT_EQ(plan->raw.size(), 2048u);
  std::size_t compiled = 0;
  for (const shadergen::RawPermutation& raw : plan->raw) {
    EXPECT_EQ(raw.optimised, raw.id) << "the identity";
    compiled += !raw.pruned;
  }
  EXPECT_EQ(compiled, 405u);
  std::string lut = shadergen::format_lut(*spec, *plan);
  EXPECT_TRUE(sgtest::contains(lut,
                               "Domain static_mesh: 2048 raw IDs, not collapsed (no \"optimised\" section): every "
                               "compiled raw ID is its own permutation\n"))
      << lut.substr(0, 400);
  EXPECT_FALSE(sgtest::contains(lut, "optimised ID")) << "no lookup table to print";
  std::string list = shadergen::format_list(*spec, *plan);
  EXPECT_TRUE(sgtest::contains(list, "  raw    3  compiled  USE_ALBEDO_MAP USE_NORMAL_MAP\n")) << list.substr(0, 400);
  EXPECT_TRUE(sgtest::contains(list, "optimised permutations: none (not collapsed)\n"));
  std::string explained = shadergen::format_explanation(*spec, *plan, 3);
  EXPECT_TRUE(sgtest::contains(explained, "not collapsed: raw ID 3 is its own permutation\n")) << explained;
}

TEST(IdentityDomain, BuildsEveryCompiledRawIdAsItsOwnBlob) {
  sgtest::TempDir dir("identity-build");
  auto summary = sgtest::build(identity_spec(), dir / "out", dir / "cache");
  ASSERT_TRUE(summary.ok()) << summary.errors().front().to_string();
  EXPECT_EQ(summary->optimised, 0u);
  EXPECT_EQ(summary->permutations, 405u) << "one compile job per compiled raw ID, nothing else";
  EXPECT_EQ(summary->unique_sources, 405u);
  json manifest = json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["collapsed"], false);
  EXPECT_EQ(manifest["optimised"], json::array());
  EXPECT_EQ(manifest["optimised_bits"], json::array());
  EXPECT_FALSE(manifest["raw"][0].contains("optimised")) << "no table entry to record";
  std::set<std::string> hashes;
  for (const json& raw : manifest["raw"])
    if (!raw["pruned"].get<bool>()) hashes.insert(raw["hash"].get<std::string>());
  EXPECT_EQ(hashes.size(), 405u);
  std::string header = sgtest::read_file(dir / "out" / "static_mesh.h");
  EXPECT_FALSE(sgtest::contains(header, "kRawToOptimised")) << "no lookup table in the generated C++";
  EXPECT_TRUE(sgtest::contains(header, "inline constexpr std::uint32_t kOptimisedCount = 0;"));
  // Without a table the checked lookup gives the raw ID itself.
  EXPECT_TRUE(sgtest::contains(header,
                               "constexpr std::optional<OptimisedId> optimised_id(RawId raw_id) {\n"
                               "  if (!is_valid_raw_id(raw_id)) return std::nullopt;\n"
                               "  return OptimisedId(raw_id.value());\n}\n"))
      << header;
}

}  // namespace
