// The tables tilelight_sweep --update-doc writes into docs/results.md: only what lies between
// a section's markers changes.

#include "sweep/doc_update.h"

#include "tilelight/base/error.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using tilelight::sweep::replace_marked_sections;

const std::string kDocument =
    "# Results\n"
    "text before\n"
    "<!-- sweep:a -->\n"
    "| old | table |\n"
    "<!-- /sweep:a -->\n"
    "between\n"
    "<!-- sweep:b -->\n"
    "<!-- /sweep:b -->\n"
    "after\n";

std::string message_of(const std::string& document, const std::map<std::string, std::string>& sections) {
  try {
    (void)replace_marked_sections(document, sections, "doc.md");
  } catch (const tilelight::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DocUpdate, ReplacesOnlyBetweenTheMarkers) {
  const std::string out = replace_marked_sections(kDocument, {{"a", "| new |\n| rows |\n"}, {"b", "line"}}, "doc.md");
  EXPECT_EQ(out,
            "# Results\n"
            "text before\n"
            "<!-- sweep:a -->\n"
            "| new |\n"
            "| rows |\n"
            "<!-- /sweep:a -->\n"
            "between\n"
            "<!-- sweep:b -->\n"
            "line\n"
            "<!-- /sweep:b -->\n"
            "after\n");
}

TEST(DocUpdate, IsIdempotentAndLeavesOtherSectionsAlone) {
  const std::string once = replace_marked_sections(kDocument, {{"b", "x\n"}}, "doc.md");
  EXPECT_EQ(replace_marked_sections(once, {{"b", "x\n"}}, "doc.md"), once);
  EXPECT_NE(once.find("| old | table |\n"), std::string::npos);
}

TEST(DocUpdate, MarkersMustBeWholeLines) {
  const std::string inline_marker = "see <!-- sweep:a --> here\n<!-- /sweep:a -->\n";
  EXPECT_EQ(message_of(inline_marker, {{"a", "x"}}), "doc.md: no '<!-- sweep:a -->' line");
}

TEST(DocUpdate, NamesTheMissingMarker) {
  EXPECT_EQ(message_of(kDocument, {{"c", "x"}}), "doc.md: no '<!-- sweep:c -->' line");
  EXPECT_EQ(message_of("<!-- sweep:a -->\ntable\n", {{"a", "x"}}),
            "doc.md: no '<!-- /sweep:a -->' line after '<!-- sweep:a -->'");
}

}  // namespace
