// --strip-debug and "strip_debug": true (tests/fixtures/toy): the written blobs hold no debug
// instruction and still pass spirv-val, each is smaller than its unstripped twin, and the
// manifest's reflection (binding and variable names) is what it was without stripping.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

using nlohmann::json;
using sgtest::fs::path;

// The debug opcodes the strip removes: OpSourceContinued 2, OpSource 3, OpSourceExtension 4,
// OpName 5, OpMemberName 6, OpString 7, OpLine 8, OpNoLine 317, OpModuleProcessed 330.
const std::set<std::uint32_t> kDebugOpcodes = {2, 3, 4, 5, 6, 7, 8, 317, 330};

std::set<std::uint32_t> debug_opcodes_in(const std::string& bytes) {
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  std::set<std::uint32_t> found;
  for (std::size_t i = 5; i < words.size();) {
    std::uint32_t count = words[i] >> 16, opcode = words[i] & 0xffffu;
    if (kDebugOpcodes.count(opcode)) found.insert(opcode);
    if (count == 0) break;
    i += count;
  }
  return found;
}

std::size_t blob_bytes(const path& out, const json& manifest) {
  std::size_t total = 0;
  for (const json& blob : manifest["blobs"]) total += sgtest::read_file(out / blob["spirv"].get<std::string>()).size();
  return total;
}

// The manifest's reflection without the blob file names and hashes, which stripping changes.
json reflection_of(const json& manifest) {
  json out = manifest["blobs"];
  for (json& blob : out) blob.erase("spirv");
  return json{{"pipeline_layout", manifest["pipeline_layout"]}, {"blobs", out}};
}

TEST(StripDebug, BlobsLoseDebugInstructionsAndTheManifestKeepsTheNames) {
  sgtest::TempDir dir("strip-debug");
  auto plain = sgtest::build(sgtest::toy_spec(), dir / "plain", dir / "cache");
  ASSERT_TRUE(plain.ok()) << plain.errors().front().to_string();
  shadergen::BuildOptions options = sgtest::build_options(sgtest::toy_spec(), dir / "stripped", dir / "cache");
  options.strip_debug = true;
  auto stripped = shadergen::build(options);
  ASSERT_TRUE(stripped.ok()) << stripped.errors().front().to_string();
  json before = json::parse(sgtest::read_file(dir / "plain" / "manifest.json"));
  json after = json::parse(sgtest::read_file(dir / "stripped" / "manifest.json"));
  EXPECT_EQ(reflection_of(after), reflection_of(before)) << "reflection runs before stripping";
  EXPECT_EQ(after["pipeline_layout"]["bindings"][0]["name"], before["pipeline_layout"]["bindings"][0]["name"]);
  EXPECT_FALSE(after["pipeline_layout"]["bindings"][0]["name"].get<std::string>().empty());
  for (const json& blob : after["blobs"]) {
    path file = dir / "stripped" / blob["spirv"].get<std::string>();
    EXPECT_EQ(debug_opcodes_in(sgtest::read_file(file)), std::set<std::uint32_t>{}) << file;
    sgtest::ProcessResult val = sgtest::spirv_val(file, "vulkan1.2");
    EXPECT_EQ(val.exit_code, 0) << val.err;
  }
  for (const json& blob : before["blobs"])
    EXPECT_TRUE(debug_opcodes_in(sgtest::read_file(dir / "plain" / blob["spirv"].get<std::string>())).count(5))
        << "the unstripped blobs name things (OpName)";
  EXPECT_LT(blob_bytes(dir / "stripped", after), blob_bytes(dir / "plain", before));
  EXPECT_EQ(stripped->cache_hits, stripped->unique_sources)
      << "the cache holds unstripped blobs; stripping reuses them";
}

TEST(StripDebug, TheSpecKeyStripsLikeTheFlag) {
  sgtest::TempDir dir("strip-debug-spec");
  json spec = json::parse(sgtest::read_file(sgtest::toy_spec()));
  spec["strip_debug"] = true;
  path copy = sgtest::toy_spec().parent_path();
  // The spec's paths are relative to its folder: write it beside the fixture's shaders.
  sgtest::fs::copy(copy, dir / "toy", sgtest::fs::copy_options::recursive);
  sgtest::write_file(dir / "toy" / "toy.json", spec.dump(2));
  auto by_key = sgtest::build(dir / "toy" / "toy.json", dir / "key", dir / "cache");
  ASSERT_TRUE(by_key.ok()) << by_key.errors().front().to_string();
  shadergen::BuildOptions options = sgtest::build_options(sgtest::toy_spec(), dir / "flag", dir / "cache");
  options.strip_debug = true;
  auto by_flag = shadergen::build(options);
  ASSERT_TRUE(by_flag.ok()) << by_flag.errors().front().to_string();
  json key = json::parse(sgtest::read_file(dir / "key" / "manifest.json"));
  json flag = json::parse(sgtest::read_file(dir / "flag" / "manifest.json"));
  EXPECT_EQ(key["blobs"], flag["blobs"]);
}

}  // namespace
