// manifest.json as nlohmann writes it, on a hand-made compiled domain (no GLSL): strings come
// back byte for byte (UTF-8, control characters, quotes), each number keeps its JSON type, and
// the layout is the documented one (two-space indentation, "\n" line ends, a final newline).
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

#include "output/manifest.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

using nlohmann::ordered_json;

std::uint32_t bits_of(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// A domain with no permutations and one blob whose reflection has one constant of each type.
CompiledDomain domain_named(const std::string& name, const std::string& uber_file) {
  CompiledDomain d;
  d.spec.name = name;
  d.spec.uber.path = std::filesystem::path("shaders") / uber_file;
  Blob blob;
  blob.hash = std::string(64, 'a');
  blob.reflection.specialization_constants = {{1, "FLAG", ScalarType::boolean, 1},
                                              {2, "OFFSET", ScalarType::int32, static_cast<std::uint32_t>(-5)},
                                              {3, "LARGE", ScalarType::uint32, 4000000000u},
                                              {4, "SCALE", ScalarType::float32, bits_of(0.1f)},
                                              {5, "ONE", ScalarType::float32, bits_of(1.0f)}};
  d.blobs.push_back(blob);
  return d;
}

TEST(ManifestJson, StringsComeBackByteForByte) {
  const std::string name = "caf\xC3\xA9 \xF0\x9F\x98\x80 tab\t newline\n bell\x07 quote\" backslash\\";
  const std::string uber =
      "\xC3\xBC"
      "ber.frag";  // "über.frag"
  std::string text = write_manifest(domain_named(name, uber));
  ordered_json manifest = ordered_json::parse(text);
  EXPECT_EQ(manifest["domain"].get<std::string>(), name);
  EXPECT_EQ(manifest["uber_shader"].get<std::string>(), uber);
  // UTF-8 is written as it is, control characters as escapes.
  EXPECT_TRUE(sgtest::contains(text,
                               "\"uber_shader\": \"\xC3\xBC"
                               "ber.frag\",\n"))
      << text;
  EXPECT_TRUE(sgtest::contains(text, "bell\\u0007 quote\\\" backslash\\\\\",\n")) << text;
}

TEST(ManifestJson, NumbersKeepTheirTypesAndTheLayoutIsTheDocumentedOne) {
  std::string text = write_manifest(domain_named("types", "u.frag"));
  ASSERT_EQ(text.rfind("{\n  \"format\": 1,\n  \"generator\": \"shadergen ", 0), 0u) << text;
  ASSERT_EQ(text.substr(text.size() - 3), "\n}\n");
  EXPECT_EQ(text.find('\r'), std::string::npos);
  ordered_json constants = ordered_json::parse(text)["blobs"][0]["specialization_constants"];
  ASSERT_EQ(constants.size(), 5u);
  EXPECT_EQ(constants[0]["default"].dump(), "true");
  EXPECT_EQ(constants[1]["default"].dump(), "-5");
  EXPECT_EQ(constants[2]["default"].dump(), "4000000000");
  EXPECT_EQ(constants[3]["default"].dump(), "0.1") << "the float's shortest form, not 0.10000000149011612";
  EXPECT_EQ(constants[4]["default"].dump(), "1.0") << "a float constant's default is a JSON float";
  EXPECT_EQ(constants[0]["id"].dump(), "1");
  EXPECT_TRUE(sgtest::contains(text, "\"default\": 4000000000\n")) << text;
}

// A permutation's "defines" are the text the compiler saw: a value-style boolean is compiled as
// (0 == 1), and SKY=0 handed back to glslang fails "boolean expression expected" (issue 51).
TEST(ManifestJson, DefinesAreTheTextTheCompilerSaw) {
  auto spec = parse_domain(R"({"name": "v", "uber_shader": {"path": "v.frag"}, "define_style": "value",
    "raw": {"features": [{"name": "SKY", "bit": 0, "define": "SKY"},
                         {"name": "FOG", "bit": 1, "define": "HAS_FOG", "define_style": "presence"},
                         {"name": "TAPS", "bit": 2, "define": "TAPS", "values": [1, 4]}]},
    "optimised": {"bits": [{"name": "LIT", "bit": 0, "when": "SKY"}],
                  "variants": [{"when": "LIT", "raw_features": ["SKY"]}]}})",
                           "v.json");
  ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
  auto plan = expand(*spec);
  ASSERT_TRUE(plan.ok()) << plan.errors().front().to_string();
  CompiledDomain d;
  d.spec = *spec;
  d.plan = *plan;
  const ordered_json m = ordered_json::parse(write_manifest(d));
  EXPECT_EQ(m["raw"][0]["defines"], ordered_json::array({"SKY=(0 == 1)", "TAPS=1"}));
  EXPECT_EQ(m["raw"][7]["defines"], ordered_json::array({"SKY=(1 == 1)", "HAS_FOG", "TAPS=4"}));
  EXPECT_EQ(m["optimised"][1]["defines"], ordered_json::array({"SKY=(1 == 1)", "TAPS=1"}));
}

}  // namespace
}  // namespace shadergen
