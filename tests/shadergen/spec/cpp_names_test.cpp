// Names that become C++ names in the generated registry (spec/cpp_names.h): each case gives a
// small valid spec one name that is a keyword, reserved, or clashes with a generated name, and
// asserts the exact diagnostic at the key that wrote it. The accepted cases show the rules
// refuse no more than they must.
#include <gtest/gtest.h>

#include <string>

#include "shadergen/domain.h"
#include "spec/cpp_names.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

// Line numbers in the expectations below refer to this text.
const std::string kBase = R"({
  "format": 1,
  "name": "tiny",
  "uber_shader": { "path": "tiny.frag", "stage": "fragment" },
  "raw": {
    "features": [
      { "name": "A", "bit": 0, "define": "HAS_A" },
      { "name": "LEVEL", "bit": 1, "define": "HAS_LEVEL", "values": [0, 1, 2] },
      { "name": "MODE", "bit": 3, "define": "HAS_MODE", "values": ["soft", "hard"] }
    ]
  },
  "optimised": {
    "bits": [ { "name": "X", "bit": 0, "when": "LEVEL == 1" } ],
    "variants": [ { "when": "X", "raw_features": ["LEVEL=1"] } ]
  }
}
)";

struct NameCase {
  const char* name;
  std::string text;
  std::string expected;
};

void PrintTo(const NameCase& c, std::ostream* os) { *os << c.name; }

class CppNameTable : public ::testing::TestWithParam<NameCase> {};

TEST_P(CppNameTable, ExactDiagnostic) { EXPECT_EQ(sgtest::first_spec_error(GetParam().text), GetParam().expected); }

const std::string kReserved = "the generated registry cannot declare it";

INSTANTIATE_TEST_SUITE_P(
    Cases, CppNameTable,
    ::testing::Values(
        NameCase{"base_is_valid", kBase, "(no error)"},
        NameCase{
            "feature_keyword", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"int\""),
            "spec.json:7:17: error: raw.features[0].name: \"int\" is a C++ keyword or reserved name; " + kReserved},
        NameCase{
            "feature_alternative_token", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"not\""),
            "spec.json:7:17: error: raw.features[0].name: \"not\" is a C++ keyword or reserved name; " + kReserved},
        NameCase{
            "feature_char8_t", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"char8_t\""),
            "spec.json:7:17: error: raw.features[0].name: \"char8_t\" is a C++ keyword or reserved name; " + kReserved},
        NameCase{"feature_underscore_capital", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"_Sky\""),
                 "spec.json:7:17: error: raw.features[0].name: \"_Sky\" is reserved in C++ (an underscore and a "
                 "capital letter begin it); " +
                     kReserved},
        NameCase{"feature_double_underscore", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"SKY__LIT\""),
                 "spec.json:7:17: error: raw.features[0].name: \"SKY__LIT\" is reserved in C++ (it holds a double "
                 "underscore); " +
                     kReserved},
        NameCase{"feature_named_Features", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"Features\""),
                 "spec.json:7:17: error: raw.features[0].name: \"Features\" is a name the generated registry "
                 "declares itself"},
        NameCase{"feature_named_RawId", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"RawId\""),
                 "spec.json:7:17: error: raw.features[0].name: \"RawId\" is a name the generated registry declares "
                 "itself"},
        NameCase{"feature_named_registry", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"registry\""),
                 "spec.json:7:17: error: raw.features[0].name: \"registry\" is a name the generated registry "
                 "declares itself"},
        NameCase{"feature_named_kRawBits", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"kRawBits\""),
                 "spec.json:7:17: error: raw.features[0].name: \"kRawBits\" is a name the generated registry "
                 "declares itself"},
        NameCase{"value_keyword", sgtest::replace_once(kBase, "[\"soft\", \"hard\"]", "[\"soft\", \"class\"]"),
                 "spec.json:9:76: error: raw.features[2].values[1]: \"class\" is a C++ keyword or reserved name; " +
                     kReserved},
        NameCase{"value_reserved", sgtest::replace_once(kBase, "[\"soft\", \"hard\"]", "[\"_Soft\", \"hard\"]"),
                 "spec.json:9:68: error: raw.features[2].values[0]: \"_Soft\" is reserved in C++ (an underscore and "
                 "a capital letter begin it); " +
                     kReserved},
        NameCase{"values_make_one_enumerator", sgtest::replace_once(kBase, "[0, 1, 2]", "[-1, \"_m1\", 2]"),
                 "spec.json:8:74: error: raw.features[1].values[1]: values -1 and _m1 both become the enumerator "
                 "LEVEL_value::_m1 in the generated C++"},
        NameCase{"integer_and_underscore_digit", sgtest::replace_once(kBase, "[0, 1, 2]", "[0, \"_1\", 1]"),
                 "spec.json:8:79: error: raw.features[1].values[2]: values _1 and 1 both become the enumerator "
                 "LEVEL_value::_1 in the generated C++"},
        NameCase{"feature_named_another_enum",
                 sgtest::replace_once(kBase, "\"name\": \"MODE\"", "\"name\": \"LEVEL_value\""),
                 "spec.json:9:17: error: raw.features[2].name: \"LEVEL_value\" clashes with the enum of valued "
                 "feature LEVEL in the generated C++"},
        NameCase{"valued_feature_after_its_enum_name",
                 sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"to_MODE\""),
                 "spec.json:9:17: error: raw.features[2].name: the value conversion of valued feature MODE, to_MODE, "
                 "clashes with feature \"to_MODE\" in the generated C++"},
        NameCase{"boolean_named_a_mask", sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"LEVEL_mask\""),
                 "spec.json:8:17: error: raw.features[1].name: raw_bit::LEVEL_mask of valued feature LEVEL, "
                 "LEVEL_mask, clashes with feature \"LEVEL_mask\" in the generated C++"},
        // A valued feature has no raw_bit::<NAME> of its own: LEVEL_shift valued beside LEVEL is fine.
        NameCase{"valued_named_a_shift", sgtest::replace_once(kBase, "\"name\": \"MODE\"", "\"name\": \"LEVEL_shift\""),
                 "(no error)"},
        // Identifiers with a special meaning in some places only, and names of locals, are fine.
        NameCase{"contextual_names",
                 sgtest::replace_once(sgtest::replace_once(kBase, "\"name\": \"A\"", "\"name\": \"final\""),
                                      "[\"soft\", \"hard\"]", "[\"import\", \"value\"]"),
                 "(no error)"},
        NameCase{
            "optimised_bit_keyword", sgtest::replace_once(kBase, "\"name\": \"X\"", "\"name\": \"xor\""),
            "spec.json:13:25: error: optimised.bits[0].name: \"xor\" is a C++ keyword or reserved name; " + kReserved},
        NameCase{"optimised_bit_reserved", sgtest::replace_once(kBase, "\"name\": \"X\"", "\"name\": \"__X\""),
                 "spec.json:13:25: error: optimised.bits[0].name: \"__X\" is reserved in C++ (it holds a double "
                 "underscore); " +
                     kReserved}),
    [](const ::testing::TestParamInfo<NameCase>& param_info) { return std::string(param_info.param.name); });

// Every keyword of C++20 and every alternative token is refused, and only those (with the
// reserved forms): one list in the test, written from the standard, against the rule's own.
TEST(CppNames, EveryKeywordAndAlternativeTokenIsRefused) {
  const char* keywords[] = {
      "alignas",       "alignof",     "asm",       "auto",      "bool",         "break",
      "case",          "catch",       "char",      "char8_t",   "char16_t",     "char32_t",
      "class",         "concept",     "const",     "consteval", "constexpr",    "constinit",
      "const_cast",    "continue",    "co_await",  "co_return", "co_yield",     "decltype",
      "default",       "delete",      "do",        "double",    "dynamic_cast", "else",
      "enum",          "explicit",    "export",    "extern",    "false",        "float",
      "for",           "friend",      "goto",      "if",        "inline",       "int",
      "long",          "mutable",     "namespace", "new",       "noexcept",     "nullptr",
      "operator",      "private",     "protected", "public",    "register",     "reinterpret_cast",
      "requires",      "return",      "short",     "signed",    "sizeof",       "static",
      "static_assert", "static_cast", "struct",    "switch",    "template",     "this",
      "thread_local",  "throw",       "true",      "try",       "typedef",      "typeid",
      "typename",      "union",       "unsigned",  "using",     "virtual",      "void",
      "volatile",      "wchar_t",     "while",     "and",       "and_eq",       "bitand",
      "bitor",         "compl",       "not",       "not_eq",    "or",           "or_eq",
      "xor",           "xor_eq"};
  for (const char* k : keywords)
    EXPECT_EQ(cpp_identifier_problem(k),
              "\"" + std::string(k) + "\" is a C++ keyword or reserved name; the generated registry cannot declare it");
  for (const char* fine : {"A", "_a", "a_", "_1", "_m1", "final", "override", "module", "import", "Int", "AND"})
    EXPECT_EQ(cpp_identifier_problem(fine), "") << fine;
}

}  // namespace
}  // namespace shadergen
