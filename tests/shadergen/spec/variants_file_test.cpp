// Variants files: the raw combinations a domain builds, one per line in the one grammar of
// shadergen/registry.h. Each bad line is an error at FILE:LINE:COLUMN naming the word; a domain
// past 2^20 raw IDs needs a file; a listed domain builds only what it lists; the file is an
// input like the spec (depfile, input-set key); --variants wins over the spec's key.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

using json = nlohmann::json;

std::string first_error(const shadergen::Result<shadergen::BuildSummary>& result) {
  return result.ok() ? "(no error)" : result.errors().front().to_string();
}

// The toy fixture (SOFT bit 2, LIT bit 0, TEXTURED bit 1, DISTORT bit 3; "DISTORT && LIT" is
// impossible) copied into `dir`, with `variants` as toy.variants and the spec naming it.
sgtest::fs::path toy_with_variants(const sgtest::TempDir& dir, const std::string& variants) {
  sgtest::fs::copy(sgtest::toy_spec().parent_path(), dir / "toy", sgtest::fs::copy_options::recursive);
  std::string spec = sgtest::read_file(dir / "toy" / "toy.json");
  spec.insert(spec.find('{') + 1, "\n  \"variants_file\": \"toy.variants\",");
  sgtest::write_file(dir / "toy" / "toy.json", spec);
  sgtest::write_file(dir / "toy" / "toy.variants", variants);
  return dir / "toy" / "toy.json";
}

struct BadLine {
  std::string line;
  int column;
  std::string message;
};

// Line 3 of each file is the bad one: a comment and a good line come first.
TEST(VariantsFile, EachBadLineIsAnErrorAtItsFileLineAndWord) {
  const BadLine cases[] = {
      {"LIT | FOO", 7, "unknown feature \"FOO\" (known: SOFT, LIT, TEXTURED, DISTORT)"},
      // A misspelt name is answered with the closest feature (issue 51).
      {"LIT | TEXTRED", 7, "unknown feature \"TEXTRED\" (known: SOFT, LIT, TEXTURED, DISTORT); did you mean TEXTURED?"},
      {"LIT=1", 1, "feature LIT is a boolean: write LIT alone, or leave it out (LIT=1 is not accepted)"},
      {"LIT=0", 1, "feature LIT is a boolean: write LIT alone, or leave it out (LIT=0 is not accepted)"},
      {"  USE_TEXTURE", 3, "\"USE_TEXTURE\" is the define of feature TEXTURED; name the feature"},
      {"12", 1, "\"12\" is a number; name the features instead, joined by '|'"},
      {"SOFT | SOFT", 8, "feature SOFT is named twice (again as \"SOFT\"); name each feature once"},
      {"LIT | DISTORT  # a comment", 1,
       "\"LIT | DISTORT\" is impossible: the rule \"DISTORT && LIT\" (toy.json:19) prunes it (distortion "
       "particles are never lit)"},
  };
  for (const BadLine& bad : cases) {
    SCOPED_TRACE(bad.line);
    sgtest::TempDir dir("variants-bad");
    auto spec = toy_with_variants(dir, "# materials\nLIT | TEXTURED\n" + bad.line + "\nSOFT\n");
    auto result = sgtest::build(spec, dir / "out", dir / "cache");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.errors().size(), 1u);
    EXPECT_EQ(first_error(result),
              (dir / "toy" / "toy.variants").string() + ":3:" + std::to_string(bad.column) + ": error: " + bad.message);
    EXPECT_FALSE(sgtest::fs::exists(dir / "out")) << "nothing is written";
  }
}

TEST(VariantsFile, EveryBadLineIsReported) {
  sgtest::TempDir dir("variants-many");
  auto spec = toy_with_variants(dir, "FOG\nLIT\nBAR | LIT\n");
  auto result = sgtest::build(spec, dir / "out", dir / "cache");
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.errors().size(), 2u);
  EXPECT_EQ(result.errors()[0].line, 1);
  EXPECT_EQ(result.errors()[1].line, 3);
}

TEST(VariantsFile, AMissingOrEmptyFileIsNamedWhereItWasGiven) {
  sgtest::TempDir dir("variants-missing");
  auto spec = toy_with_variants(dir, "# nothing listed\n\n");
  auto empty = sgtest::build(spec, dir / "out", dir / "cache");
  EXPECT_EQ(first_error(empty), spec.string() +
                                    ":2: error: \"variants_file\": " + (dir / "toy" / "toy.variants").string() +
                                    ": lists no combination (a line such as \"(none)\" builds the raw ID with "
                                    "every feature off)");
  sgtest::fs::remove(dir / "toy" / "toy.variants");
  auto missing = sgtest::build(spec, dir / "out", dir / "cache");
  EXPECT_EQ(first_error(missing), spec.string() + ":2: error: \"variants_file\": " +
                                      (dir / "toy" / "toy.variants").string() + ": the file does not exist");
  auto options = sgtest::build_options(spec, dir / "out", dir / "cache");
  options.variants = dir / "nowhere.variants";
  auto from_option = shadergen::build(options);
  EXPECT_EQ(first_error(from_option),
            "error: --variants " + (dir / "nowhere.variants").string() + ": the file does not exist");
}

// Only the listed raw IDs are built, with the optimised IDs they map to; duplicates count once.
TEST(VariantsFile, ASmallDomainBuildsOnlyWhatItLists) {
  sgtest::TempDir dir("variants-small");
  auto spec = toy_with_variants(dir, "LIT | TEXTURED\n\n# again, spaced differently\nTEXTURED|LIT\nSOFT\n");
  auto summary = sgtest::build(spec, dir / "out", dir / "cache");
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  EXPECT_EQ(summary->raw, 2u);
  EXPECT_EQ(summary->pruned, 0u);
  EXPECT_EQ(summary->optimised, 2u) << "SHADED|SAMPLED (3) and SAMPLED (2)";
  json manifest = json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["raw_bits"], 4);
  EXPECT_EQ(manifest["variants_file"], "toy.variants");
  ASSERT_EQ(manifest["raw"].size(), 2u);
  EXPECT_EQ(manifest["raw"][0]["id"], 3);
  EXPECT_EQ(manifest["raw"][0]["optimised"], 3);
  EXPECT_EQ(manifest["raw"][1]["id"], 4);
  EXPECT_EQ(manifest["raw"][1]["optimised"], 2);
  ASSERT_EQ(manifest["optimised"].size(), 2u);
  EXPECT_EQ(manifest["optimised"][0]["id"], 2);
  EXPECT_EQ(manifest["optimised"][1]["id"], 3);
}

// --variants wins over the spec's key; the file is in the depfile; editing it rebuilds.
TEST(VariantsFile, TheFileIsAnInputLikeTheSpec) {
  sgtest::TempDir dir("variants-input");
  auto spec = toy_with_variants(dir, "LIT\n");
  sgtest::write_file(dir / "other.variants", "SOFT\nLIT|SOFT\n");
  auto options = sgtest::build_options(spec, dir / "out", dir / "cache");
  options.depfile = dir / "out.d";
  auto first = shadergen::build(options);
  ASSERT_TRUE(first.ok()) << first_error(first);
  EXPECT_EQ(first->raw, 1u);
  EXPECT_TRUE(sgtest::contains(sgtest::read_file(dir / "out.d"), (dir / "toy" / "toy.variants").string()));

  auto again = shadergen::build(options);
  ASSERT_TRUE(again.ok()) << first_error(again);
  EXPECT_TRUE(again->inputs_reused);
  sgtest::write_file(dir / "toy" / "toy.variants", "LIT\nTEXTURED\n");
  auto edited = shadergen::build(options);
  ASSERT_TRUE(edited.ok()) << first_error(edited);
  EXPECT_FALSE(edited->inputs_reused) << "the variants file is part of the input-set key";
  EXPECT_EQ(edited->raw, 2u);
  EXPECT_TRUE(edited->output_changed);

  options.variants = dir / "other.variants";
  auto overridden = shadergen::build(options);
  ASSERT_TRUE(overridden.ok()) << first_error(overridden);
  EXPECT_EQ(overridden->raw, 2u);
  const std::string depfile = sgtest::read_file(dir / "out.d");
  EXPECT_TRUE(sgtest::contains(depfile, (dir / "other.variants").string())) << depfile;
  EXPECT_FALSE(sgtest::contains(depfile, "toy.variants")) << depfile;
  json manifest = json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["raw"][0]["id"], 4);
  EXPECT_EQ(manifest["raw"][1]["id"], 5);
}

// 21 raw bits without a variants file: refused, naming the limit and the key.
TEST(VariantsFile, ADomainPast2To20RawIdsNeedsOne) {
  sgtest::TempDir dir("variants-needed");
  std::string features;
  for (int i = 0; i < 21; ++i)
    features += std::string(i ? ",\n" : "") + "{\"name\": \"F" + std::to_string(i) +
                "\", \"bit\": " + std::to_string(i) + ", \"define\": \"USE_F" + std::to_string(i) +
                "\", \"unread\": \"allowed\"}";
  sgtest::write_file(dir / "wide.frag",
                     "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1); }\n");
  sgtest::write_file(dir / "wide.json",
                     "{\"name\": \"wide\", \"uber_shader\": {\"path\": \"wide.frag\"},\n"
                     "\"raw\": {\"features\": [" +
                         features + "]}}\n");
  auto result = sgtest::build(dir / "wide.json", dir / "out", dir / "cache");
  EXPECT_EQ(first_error(result),
            (dir / "wide.json").string() +
                ": error: the raw features take 21 bits, 2097152 raw IDs: past 2^20 (1048576) raw IDs a domain lists "
                "the combinations it builds in a variants file (spec key \"variants_file\", or build --variants "
                "FILE)");
  sgtest::write_file(dir / "two.variants", "F20\nF0 | F20\n");
  auto options = sgtest::build_options(dir / "wide.json", dir / "out", dir / "cache");
  options.variants = dir / "two.variants";
  auto listed = shadergen::build(options);
  ASSERT_TRUE(listed.ok()) << first_error(listed);
  EXPECT_EQ(listed->raw, 2u);
  EXPECT_EQ(listed->unique_sources, 1u) << "the shader reads no define: one source";
}

// The views of a 32-bit domain: one row per listed ID, and any raw ID explained, built or not.
TEST(VariantsFile, TheViewsWorkOnA32BitDomain) {
  const auto spec = sgtest::fixtures_dir() / "wide32" / "wide32.json";
  auto lut = sgtest::run_process(sgtest::shadergen_exe(), {"lut", spec.string()});
  EXPECT_EQ(lut.exit_code, 0) << lut.err;
  EXPECT_TRUE(sgtest::contains(lut.out, "Domain wide32: 4294967296 raw IDs (32 bits), 7 listed in")) << lut.out;
  EXPECT_TRUE(sgtest::contains(lut.out, "  4026531840           512  F28 | F29 | QUALITY=3\n")) << lut.out;
  auto explain = sgtest::run_process(sgtest::shadergen_exe(), {"explain", spec.string(), "F07"});
  EXPECT_EQ(explain.exit_code, 0) << explain.err;
  EXPECT_TRUE(sgtest::contains(explain.out, "not built: ")) << explain.out;
  EXPECT_TRUE(sgtest::contains(explain.out, "-> optimised ID 4 = GROUP2\n   not built: no listed raw ID maps to it"))
      << explain.out;
  auto top = sgtest::run_process(sgtest::shadergen_exe(), {"explain", spec.string(), "0xffffffff"});
  EXPECT_EQ(top.exit_code, 0) << top.err;
  EXPECT_TRUE(sgtest::contains(top.out, "raw ID 4294967295 = ")) << top.out;
  auto past = sgtest::run_process(sgtest::shadergen_exe(), {"explain", spec.string(), "4294967296"});
  EXPECT_EQ(past.exit_code, 2);
  EXPECT_TRUE(sgtest::contains(past.err, "has raw IDs 0 to 4294967295")) << past.err;
  auto list = sgtest::run_process(sgtest::shadergen_exe(), {"list", spec.string()});
  EXPECT_EQ(list.exit_code, 0) << list.err;
  EXPECT_TRUE(sgtest::contains(list.out, "raw permutations: 7 (0 pruned, 7 compiled; the ones")) << list.out;
}

TEST(VariantsFile, TheCommandLineSaysWhereABadLineIs) {
  sgtest::TempDir dir("variants-cli");
  auto spec = toy_with_variants(dir, "LIT\nLIT | FOG\n");
  auto built = sgtest::run_process(sgtest::shadergen_exe(), {"build", spec.string(), "--out", (dir / "out").string()});
  EXPECT_EQ(built.exit_code, 1);
  EXPECT_TRUE(sgtest::contains(built.err, (dir / "toy" / "toy.variants").string() +
                                              ":2:7: error: unknown feature \"FOG\" (known: SOFT, LIT, TEXTURED, "
                                              "DISTORT)"))
      << built.err;
  sgtest::write_file(dir / "good.variants", "SOFT\n");
  auto lut = sgtest::run_process(sgtest::shadergen_exe(),
                                 {"lut", spec.string(), "--variants", (dir / "good.variants").string()});
  EXPECT_EQ(lut.exit_code, 0) << lut.err;
  EXPECT_TRUE(sgtest::contains(lut.out, "1 listed in")) << lut.out;
}

}  // namespace
