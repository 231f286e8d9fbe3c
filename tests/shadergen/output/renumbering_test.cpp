// The previous output's numbering, read from its manifest, against a new plan (issue 51).
#include <gtest/gtest.h>

#include <string>

#include "output/renumbering.h"
#include "test_helpers.h"

namespace renumbering_test {
namespace {

using shadergen::PreviousNumbering;

TEST(Renumbering, TheManifestIsReadToTheEndOfItsRawArrayOnly) {
  sgtest::TempDir dir("renumbering-read");
  // What follows "raw" is broken on purpose: the reader has stopped before it.
  sgtest::write_file(dir / "manifest.json", R"({"format": 1, "defines": ["A=1"], "raw_features": [
    {"name": "FOG", "bit": 0, "define": "FOG", "kind": "specialization", "constant_id": 0},
    {"name": "SOFT", "bit": 1, "define": "SOFT", "define_style": "value"}],
    "raw": [{"id": 0, "defines": [], "pruned": false, "specialization": {"FOG": false}, "optimised": 0},
            {"id": 1, "defines": [], "pruned": false, "optimised": 2}],
    "blobs": [ {"id": )");
  const PreviousNumbering read = shadergen::previous_numbering(dir / "manifest.json");
  EXPECT_EQ(read.kinds, (std::map<std::string, std::string>{{"FOG", "specialization"}, {"SOFT", "variant"}}));
  EXPECT_EQ(read.table, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 0}, {1, 2}}));
  EXPECT_TRUE(shadergen::previous_numbering(dir / "none.json").table.empty());
}

TEST(Renumbering, CountsTheRawIdsWhoseOptimisedIdChangedAndNamesTheKindsThatMoved) {
  auto spec = shadergen::parse_domain(R"({"name": "k", "uber_shader": {"path": "k.frag"},
    "raw": {"features": [{"name": "FOG", "bit": 0, "define": "FOG", "kind": "specialization"},
                         {"name": "SOFT", "bit": 1, "define": "SOFT"}]},
    "optimised": {"ignore": [{"feature": "SOFT", "when": "false"}]}})",
                                      "k.json");
  ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
  auto plan = shadergen::expand(*spec);
  ASSERT_TRUE(plan.ok()) << plan.errors().front().to_string();
  // Now raw 0 and 1 (FOG a constant) share optimised 0, raw 2 and 3 optimised 1.
  PreviousNumbering same{{{"FOG", "specialization"}, {"SOFT", "variant"}}, {{0, 0}, {1, 0}, {2, 1}, {3, 1}}};
  EXPECT_EQ(shadergen::renumbering(same, *spec, *plan).raw_ids, 0u);
  PreviousNumbering before{{{"FOG", "variant"}, {"SOFT", "variant"}}, {{0, 0}, {1, 1}, {2, 2}, {3, 3}}};
  const shadergen::Renumbering r = shadergen::renumbering(before, *spec, *plan);
  EXPECT_EQ(r.raw_ids, 3u);
  EXPECT_EQ(r.features, (std::vector<std::string>{"FOG (variant -> specialization)"}));
  EXPECT_EQ(shadergen::renumbering({}, *spec, *plan).raw_ids, 0u) << "a first build";
}

}  // namespace
}  // namespace renumbering_test
