// Every string the code generator writes into C++ goes through cpp_text.h: a name with a
// newline, a quote or a trailing backslash must read back as written and never end a literal
// or a comment early. Also the enumerator spelling of valued features' values.
#include <gtest/gtest.h>

#include "output/cpp_text.h"

namespace {

struct Case {
  std::string text;
  std::string literal;
  std::string comment;
};

TEST(CppText, LiteralsAndCommentsEscapeEverythingThatWouldBreakThem) {
  const std::vector<Case> cases = {
      {"plain", "\"plain\"", "plain"},
      {"a\"b", "\"a\\\"b\"", "a\"b"},
      {"back\\slash", "\"back\\\\slash\"", "back\\\\slash"},
      {"ends with \\", "\"ends with \\\\\"", "ends with \\\\"},
      {"two\nlines", "\"two\\nlines\"", "two\\nlines"},
      {"cr\rtab\t", "\"cr\\rtab\\t\"", "cr\\rtab\\t"},
      {std::string("nul\0"
                   "7",
                   5),
       "\"nul\\0007\"", "nul\\0007"},
      {"\x1b[0m\x7f", "\"\\033[0m\\177\"", "\\033[0m\\177"},
      {"caf\xc3\xa9", "\"caf\xc3\xa9\"", "caf\xc3\xa9"},
      {"", "\"\"", ""},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(shadergen::cpp_string_literal(c.text), c.literal);
    EXPECT_EQ(shadergen::cpp_comment_text(c.text), c.comment);
    EXPECT_EQ(shadergen::cpp_comment_text(c.text).find('\n'), std::string::npos);
  }
}

TEST(CppText, ValuesBecomeEnumerators) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"2", "_2"}, {"0", "_0"}, {"-1", "_m1"}, {"ACES", "ACES"}, {"_low", "_low"}, {"1024", "_1024"}};
  for (const auto& [value, name] : cases) EXPECT_EQ(shadergen::enumerator_name(value), name) << value;
}

}  // namespace
