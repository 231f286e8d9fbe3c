// "layout": "per_permutation" (tests/fixtures/per_permutation): raw bit 0 READ_SUBPASS turns
// set 0 binding 1 from a combined image sampler into an input attachment, bit 1
// SPLIT_SPECULAR adds a second output, bit 2 BINDLESS_COOKIES adds a runtime-sized texture
// array. Each permutation carries its own layout; the same spec with a shared layout is
// refused by a message that names the binding, both kinds, two permutations and the way out.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

using nlohmann::json;
using sgtest::fs::path;

path fixture_dir() { return sgtest::fixtures_dir() / "per_permutation"; }

// Where `value` holds a number written with a fraction or an exponent (a JSON float).
void find_floats(const json& value, const std::string& at, std::vector<std::string>& out) {
  if (value.is_number_float()) out.push_back(at + " = " + value.dump());
  if (value.is_object())
    for (const auto& [key, item] : value.items()) find_floats(item, at + "." + key, out);
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i) find_floats(value[i], at + "[" + std::to_string(i) + "]", out);
}

const json* binding_at(const json& layout, int set, int binding) {
  for (const json& b : layout["bindings"])
    if (b["set"] == set && b["binding"] == binding) return &b;
  return nullptr;
}

TEST(PerPermutationLayout, EachPermutationCarriesItsOwnKindsAndOutputs) {
  sgtest::TempDir dir("per-permutation");
  auto summary = sgtest::build(fixture_dir() / "per_permutation.json", dir / "out", dir / "cache");
  ASSERT_TRUE(summary.ok()) << summary.errors().front().to_string();
  json manifest = json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["layout"], "per_permutation");
  EXPECT_EQ(manifest["pipeline_layout"]["bindings"], json::array()) << "nothing is merged";
  const json& raw = manifest["raw"];
  for (int id = 0; id < 8; ++id) {
    SCOPED_TRACE("raw " + std::to_string(id));
    const json& layout = raw[id]["layout"];
    const json* albedo = binding_at(layout, 0, 1);
    ASSERT_NE(albedo, nullptr);
    bool subpass = id & 1, split = id & 2, bindless = id & 4;
    EXPECT_EQ((*albedo)["kind"], subpass ? "input_attachment" : "combined_image_sampler");
    if (subpass) {
      EXPECT_EQ((*albedo)["input_attachment_index"], 0);
    }
    EXPECT_EQ(layout["outputs"].size(), split ? 2u : 1u);
    const json* cookies = binding_at(layout, 1, 0);
    EXPECT_EQ(cookies != nullptr, bindless);
    if (cookies) {
      EXPECT_EQ((*cookies)["count"], 0);
      EXPECT_EQ((*cookies)["runtime_sized"], true);
    }
  }
  EXPECT_EQ(manifest["optimised"][1]["layout"], raw[3]["layout"]) << "optimised 1 is compiled as raw 3";
  // The FFT companion: its work-group width is specialization constant 3 (default 1, the
  // unspecialised size glslang gives it), its radix constant 4 (default 4).
  const json& fft = manifest["companions"][0];
  ASSERT_EQ(fft["name"], "fft");
  for (const json& blob : manifest["blobs"]) {
    if (blob["spirv"] != fft["spirv"]) continue;
    EXPECT_EQ(blob["local_size"], json::array({1, 1, 1}));
    EXPECT_EQ(blob["local_size_ids"], json::parse("[3, null, null]"));
    EXPECT_EQ(blob["specialization_constants"], json::parse(R"([{"id": 3, "name": "", "type": "uint", "default": 1},
                                  {"id": 4, "name": "RADIX", "type": "uint", "default": 4}])"));
  }
  // Integers are written as integers (4, not 4.0); the only JSON floats are the defaults of
  // float constants: LIGHT_SCALE = 2.0 in the fragment shader's blobs.
  std::vector<std::string> floats;
  find_floats(manifest, "$", floats);
  ASSERT_FALSE(floats.empty());
  for (const std::string& f : floats) {
    EXPECT_TRUE(sgtest::contains(f, ".specialization_constants[0].default = 2.0")) << f;
    EXPECT_EQ(f.rfind("$.blobs[", 0), 0u) << f;
  }
  for (const json& blob : manifest["blobs"]) {
    sgtest::ProcessResult val = sgtest::spirv_val(dir / "out" / blob["spirv"].get<std::string>());
    EXPECT_EQ(val.exit_code, 0) << val.out << val.err;
  }
}

// The fixture and the file it includes ("../shared_include"), copied with "layout" removed.
TEST(PerPermutationLayout, ASharedLayoutNamesTheConflictAndTheWayOut) {
  sgtest::TempDir dir("shared-conflict");
  for (const char* folder : {"per_permutation", "shared_include"})
    for (const auto& [name, bytes] : sgtest::snapshot(sgtest::fixtures_dir() / folder))
      sgtest::write_file(dir / (std::string(folder) + "/" + name), bytes);
  path spec = dir / "per_permutation" / "per_permutation.json";
  std::string text = sgtest::read_file(spec);
  text.erase(text.find("\"layout\": \"per_permutation\","), 30);
  sgtest::write_file(spec, text);
  auto result = sgtest::build(spec, dir / "out", dir / "cache");
  ASSERT_FALSE(result.ok());
  const std::string hint =
      " (the spec's \"layout\" is \"shared\"; \"layout\": \"per_permutation\" gives each "
      "permutation a layout of its own)";
  std::string all;
  for (const shadergen::Diagnostic& d : result.errors()) all += d.to_string() + "\n";
  EXPECT_TRUE(sgtest::contains(all, spec.string() +
                                        ": error: permutations disagree on set 0 binding 1: raw 0 has "
                                        "combined_image_sampler \"gbuffer_albedo\", raw 1 (READ_SUBPASS) "
                                        "has input_attachment \"gbuffer_albedo\", as do 3 more (raw 3 (READ_SUBPASS "
                                        "SPLIT_SPECULAR), raw 5 (READ_SUBPASS BINDLESS_COOKIES), raw 7 (READ_SUBPASS "
                                        "SPLIT_SPECULAR BINDLESS_COOKIES))" +
                                        hint + "\n"))
      << all;
  EXPECT_TRUE(sgtest::contains(all, spec.string() +
                                        ": error: permutations disagree on their outputs: raw 0 writes "
                                        "location 0 vec4, raw 2 (SPLIT_SPECULAR) writes location 0 vec4, "
                                        "location 1 vec4, as do 3 more (raw 3 (READ_SUBPASS SPLIT_SPECULAR), raw 6 "
                                        "(SPLIT_SPECULAR BINDLESS_COOKIES), raw 7 (READ_SUBPASS SPLIT_SPECULAR "
                                        "BINDLESS_COOKIES))" +
                                        hint + "\n"))
      << all;
  EXPECT_FALSE(sgtest::fs::exists(dir / "out"));
}

TEST(PerPermutationLayout, AnUnknownLayoutIsAnError) {
  sgtest::TempDir dir("layout-unknown");
  for (const char* folder : {"per_permutation", "shared_include"})
    for (const auto& [name, bytes] : sgtest::snapshot(sgtest::fixtures_dir() / folder))
      sgtest::write_file(dir / (std::string(folder) + "/" + name), bytes);
  path spec = dir / "per_permutation" / "per_permutation.json";
  std::string text = sgtest::read_file(spec);
  text.replace(text.find("\"per_permutation\","), 17, "\"separate\"");
  sgtest::write_file(spec, text);
  auto result = sgtest::build(spec, dir / "out", dir / "cache");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors().front().to_string(),
            spec.string() + ":6:13: error: layout: unknown layout \"separate\" (expected shared or per_permutation)");
}

}  // namespace
