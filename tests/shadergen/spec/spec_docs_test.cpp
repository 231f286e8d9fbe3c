// docs/spec-format.md documents every key the spec reader accepts: each key of spec_keys::kAll
// (the table the reader itself checks keys against) is a row of the key table in its object's
// section. A key added to the reader without docs fails here.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <string_view>

#include "spec/spec_keys.h"
#include "test_helpers.h"

namespace spec_docs_test {
namespace {

// Where each object of the format is described: the heading its key table sits under.
const std::map<std::string_view, std::string> kSections{
    {"spec", "## Top level"},
    {"uber_shader", "### `uber_shader`"},
    {"uber_shaders.<name>", "### `uber_shaders`: one domain, several uber-shaders"},
    {"program", "### `program`: a permuted vertex + fragment pair"},
    {"companions[]", "### `companions`"},
    {"raw", "## `raw`: features and impossible sets"},
    {"raw.features[]", "### `raw.features`"},
    {"raw.impossible[]", "### `raw.impossible`"},
    {"optimised", "## `optimised`: the collapse rules"},
    {"optimised.bits[]", "### `optimised.bits`"},
    {"optimised.ignore[]", "### `optimised.ignore`: what the optimised shaders leave out"},
    {"optimised.variants[]", "### `optimised.variants`: what each optimised ID is compiled with"},
    {"branch_block", "#### `branch_block`"},
};

// The text under `heading` up to the next heading; empty when the doc has no such heading.
std::string section(const std::string& doc, const std::string& heading) {
  const std::size_t at = doc.find("\n" + heading + "\n");
  if (at == std::string::npos) return {};
  const std::size_t start = at + heading.size() + 2;
  std::size_t end = doc.find("\n#", start);
  return doc.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

TEST(SpecDocs, EveryKeyTheReaderAcceptsIsARowOfItsObjectsTable) {
  const std::string doc = sgtest::read_file(sgtest::source_dir() / "docs" / "spec-format.md");
  std::size_t checked = 0;
  for (const shadergen::spec_keys::ObjectKeys& object : shadergen::spec_keys::kAll) {
    auto heading = kSections.find(object.object);
    ASSERT_NE(heading, kSections.end()) << object.object << ": no section is named for it in this test";
    const std::string text = section(doc, heading->second);
    ASSERT_FALSE(text.empty()) << "docs/spec-format.md has no heading \"" << heading->second << "\"";
    for (std::string_view key : object.keys) {
      EXPECT_TRUE(sgtest::contains(text, "\n| `" + std::string(key) + "` |"))
          << object.object << "." << key << " is not a row of the table under \"" << heading->second << "\"";
      ++checked;
    }
  }
  EXPECT_GE(checked, 50u);
}

}  // namespace
}  // namespace spec_docs_test
