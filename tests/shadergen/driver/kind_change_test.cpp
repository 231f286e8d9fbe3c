// A build that gives raw IDs other optimised IDs than the output it replaces says so, naming the
// features that moved between variant and another kind (issue 51): a pipeline cache keyed by
// optimised ID is stale, and nothing else would say it. The shader is tests/fixtures/kinds'.
#include <gtest/gtest.h>

#include <string>

#include "shadergen/build.h"
#include "test_helpers.h"

namespace kind_change_test {
namespace {

// The kinds fixture's features, collapsed in the "ignore" form; `soft_kind` is SOFT's kind.
std::string spec_text(const std::string& soft_kind) {
  const std::string shader = (sgtest::fixtures_dir() / "kinds" / "kinds.frag").string();
  return R"({"format": 1, "name": "k", "uber_shader": {"path": ")" + shader + R"("}, "define_style": "value",
    "raw": {"features": [
      {"name": "FOG", "bit": 0, "define": "FOG"},
      {"name": "SOFT", "bit": 1, "define": "SOFT", "kind": ")" +
         soft_kind + R"("},
      {"name": "TAPS", "bit": 2, "define": "TAPS", "values": [1, 4, 8]},
      {"name": "SHADING", "bit": 4, "define": "SHADING", "values": ["UNLIT", "PBR"]}],
      "impossible": [{"when": "SHADING == UNLIT && SOFT"}]},
    "optimised": {"ignore": [{"feature": "TAPS"}]}})";
}

TEST(KindChange, ARebuildThatRenumbersTheOptimisedIdsSaysSoAndWhy) {
  sgtest::TempDir dir("kind-change");
  auto build = [&](const std::string& soft_kind) {
    sgtest::write_file(dir / "k.json", spec_text(soft_kind));
    return sgtest::build(dir / "k.json", dir / "out", dir / "cache");
  };
  auto first = build("variant");
  ASSERT_TRUE(first.ok()) << first.errors().front().to_string();
  EXPECT_EQ(first->renumbered_raw_ids, 0u) << "a first build";

  auto second = build("specialization");  // one word: SOFT leaves the collapse
  ASSERT_TRUE(second.ok()) << second.errors().front().to_string();
  EXPECT_GT(second->renumbered_raw_ids, 0u);
  EXPECT_EQ(second->kind_changes, (std::vector<std::string>{"SOFT (variant -> specialization)"}));

  auto again = build("specialization");
  ASSERT_TRUE(again.ok()) << again.errors().front().to_string();
  EXPECT_EQ(again->renumbered_raw_ids, 0u) << "said once, against the output it replaced";
  EXPECT_TRUE(again->kind_changes.empty());
}

}  // namespace
}  // namespace kind_change_test
