// The whole build on the real domain and on the fixture: counts, validity of every blob (by
// shadergen and by the external spirv-val), one pipeline layout, determinism, no-op rebuilds.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstring>
#include <set>

#include "compile/spirv_passes.h"
#include "shadergen/build.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

namespace fs = std::filesystem;

Result<BuildSummary> build_into(const fs::path& spec, const fs::path& out, const fs::path& cache, unsigned jobs = 0,
                                bool use_cache = true) {
  BuildOptions options = sgtest::build_options(spec, out, cache);
  options.use_cache = use_cache;
  options.jobs = jobs;
  return build(options);
}

std::vector<std::uint32_t> words_of(const std::string& bytes) {
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

// One cold build of Split/Second shared by the tests below (it takes a few seconds).
class SplitSecondBuild : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new sgtest::TempDir("split-second-build");
    auto summary = build_into(sgtest::split_second_spec(), *root_ / "out", *root_ / "cache", 0, true);
    if (!summary.ok()) {
      setup_error_ = new std::string(summary.errors().front().to_string());
      return;
    }
    summary_ = new BuildSummary(*summary);
    manifest_ = new nlohmann::json(nlohmann::json::parse(sgtest::read_file(*root_ / "out" / "manifest.json")));
  }
  static void TearDownTestSuite() {
    delete manifest_;
    delete summary_;
    delete root_;
    delete setup_error_;
  }
  // A failed shared build fails every test (an ASSERT in SetUpTestSuite would only skip them).
  void SetUp() override {
    ASSERT_EQ(setup_error_, nullptr) << *setup_error_;
    ASSERT_NE(manifest_, nullptr);
  }
  static fs::path out() { return *root_ / "out"; }
  // The spec lists two uber-shaders ("uber_shaders"): the raster light pass, then the compute one.
  static const nlohmann::json& entry(std::size_t i) { return (*manifest_)["uber_shaders"][i]; }
  static inline sgtest::TempDir* root_ = nullptr;
  static inline BuildSummary* summary_ = nullptr;
  static inline nlohmann::json* manifest_ = nullptr;
  static inline std::string* setup_error_ = nullptr;
};

TEST_F(SplitSecondBuild, ManifestHas128RawWith32PrunedAnd32Optimised) {
  const auto& raw = (*manifest_)["raw"];
  const auto& optimised = (*manifest_)["optimised"];
  ASSERT_EQ(raw.size(), 128u);
  ASSERT_EQ(optimised.size(), 32u);
  int pruned = 0;
  for (std::size_t id = 0; id < raw.size(); ++id) {
    const auto& entry = raw[id];
    EXPECT_EQ(entry["id"], id);
    for (const char* key : {"id", "defines", "pruned", "optimised"}) EXPECT_TRUE(entry.contains(key)) << key;
    // The blobs are each uber-shader's, listed under "uber_shaders".
    EXPECT_FALSE(entry.contains("spirv") || entry.contains("hash")) << id;
    pruned += entry["pruned"].get<bool>();
  }
  EXPECT_EQ(pruned, 32);
  ASSERT_EQ(manifest_->at("uber_shaders").size(), 2u);
  EXPECT_EQ(entry(0)["name"], "raster");
  EXPECT_EQ(entry(0)["stage"], "fragment");
  EXPECT_EQ(entry(1)["name"], "compute");
  EXPECT_EQ(entry(1)["stage"], "compute");
  for (std::size_t e = 0; e < 2; ++e) {
    // Every raw ID that is not pruned has a blob of each uber-shader, and no pruned one has.
    std::set<std::uint32_t> with_blob;
    for (const auto& blob : entry(e)["raw"]) {
      EXPECT_TRUE(blob.contains("spirv") && blob.contains("hash")) << blob.dump();
      with_blob.insert(blob["id"].get<std::uint32_t>());
    }
    EXPECT_EQ(with_blob.size(), 96u);
    for (std::uint32_t id : with_blob) EXPECT_FALSE(raw[id]["pruned"].get<bool>()) << id;
    EXPECT_EQ(entry(e)["optimised"].size(), 32u);
  }
  EXPECT_EQ(summary_->raw, 128u);
  EXPECT_EQ(summary_->pruned, 32u);
  EXPECT_EQ(summary_->optimised, 32u);
}

TEST_F(SplitSecondBuild, EveryBlobValidatesWithShadergenAndSpirvVal) {
  std::set<std::string> paths;
  for (std::size_t e = 0; e < 2; ++e)
    for (const char* section : {"raw", "optimised", "companions"})
      for (const auto& blob : entry(e)[section])
        if (blob.contains("spirv")) paths.insert(blob["spirv"].get<std::string>());
  ASSERT_GT(paths.size(), 96u);
  for (const std::string& relative : paths) {
    fs::path file = out() / relative;
    ASSERT_TRUE(fs::exists(file)) << file;
    auto words = words_of(sgtest::read_file(file));
    ASSERT_FALSE(words.empty());
    EXPECT_EQ(words[0], 0x07230203u);
    Status valid = validate_spirv(words);
    EXPECT_TRUE(valid.ok()) << relative << ": " << (valid.ok() ? "" : valid.errors().front().message);
    sgtest::ProcessResult val = sgtest::spirv_val(file);
    EXPECT_EQ(val.exit_code, 0) << relative << "\n" << val.out << val.err;
  }
}

TEST_F(SplitSecondBuild, IdenticalBlobsAreStoredOnce) {
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(out() / "spirv")) files += e.is_regular_file();
  // A fragment and a compute shader never share words: the entries' blobs are distinct files.
  EXPECT_EQ(files, summary_->unique_blobs);
  std::size_t blobs = 0, companions = 0;
  for (std::size_t e = 0; e < 2; ++e) {
    // Per uber-shader: 96 compiled raw permutations plus one blob per companion (the tile vertex
    // shaders, the runtime's classification, index-build and scene shaders; the compute
    // baselines and tile-list build), at most.
    std::set<std::string> hashes;
    for (const auto& blob : entry(e)["raw"]) hashes.insert(blob["hash"].get<std::string>());
    const std::size_t own = entry(e)["companions"].size();
    EXPECT_GE(own, 1u);
    EXPECT_LE(entry(e)["blobs"].size(), 96u + own);
    EXPECT_LE(hashes.size(), 96u);
    blobs += entry(e)["blobs"].size(), companions += own;
  }
  EXPECT_EQ(blobs, summary_->unique_blobs);
  EXPECT_EQ(companions, summary_->companions);
  // Every optimised permutation has a raw twin with the same source: no extra compiles.
  EXPECT_EQ(summary_->unique_sources, 2 * 96u + companions);
}

TEST_F(SplitSecondBuild, RawEntriesCarryTheLookupTable) {
  for (const auto& entry : (*manifest_)["raw"]) {
    std::uint32_t id = entry["id"];
    bool solid = id & 1, soft = id & 2, fade = id & 4, sun = id & 64;
    std::uint32_t expected =
        ((id >> 3) & 7) | ((solid && fade && sun) || (!solid && sun && soft) ? 8u : 0u) | (!solid && sun ? 16u : 0u);
    EXPECT_EQ(entry["optimised"].get<std::uint32_t>(), expected) << "raw " << id;
  }
}

// Set 0 of lighting_params.glsl: the parameters, RT0..RT3, the shadow map and the coverage
// flags (which the MSAA_EDGE permutations read).
TEST_F(SplitSecondBuild, AllPermutationsShareOnePipelineLayout) {
  const auto& bindings = entry(0)["pipeline_layout"]["bindings"];
  ASSERT_EQ(bindings.size(), 7u);
  EXPECT_EQ(bindings[0]["kind"], "uniform_buffer");
  EXPECT_EQ(bindings[6]["name"], "gbuffer_coverage_flags");
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(bindings[i]["set"], 0);
    EXPECT_EQ(bindings[i]["binding"], i);
    if (i > 0) {
      EXPECT_EQ(bindings[i]["kind"], "combined_image_sampler");
    }
  }
  const auto& push = entry(0)["pipeline_layout"]["push_constants"];
  ASSERT_EQ(push.size(), 1u);
  EXPECT_EQ(push[0]["size"], 8);  // tile.vert's inv_viewport
  // The compute form has a layout of its own, with the same parameters at set 0 binding 0.
  const auto& compute = entry(1)["pipeline_layout"]["bindings"];
  ASSERT_FALSE(compute.empty());
  EXPECT_EQ(compute[0]["set"], 0);
  EXPECT_EQ(compute[0]["binding"], 0);
  EXPECT_EQ(compute[0]["kind"], "uniform_buffer");
  EXPECT_NE(compute, bindings);
}

TEST_F(SplitSecondBuild, GeneratedCppHasTheTableAndBanner) {
  std::string header = sgtest::read_file(out() / "split_second.h");
  EXPECT_NE(header.find("Do not edit"), std::string::npos);
  EXPECT_NE(header.find("inline constexpr std::array<std::uint8_t, kRawCount> kRawToOptimised"), std::string::npos);
  EXPECT_NE(header.find("\n    16, 0, 24, 0, 16, 8, 24, 8, 17, 1, 25, 1, 17, 9, 25, 9,\n"), std::string::npos)
      << "row 64 of the LUT (pruned entries carry the rules' value)";
  EXPECT_NE(header.find("static_assert"), std::string::npos);
  EXPECT_EQ(header.find("0x07230203"), std::string::npos) << "SPIR-V words belong in the source, not the header";
  // One registry per uber-shader, and the companions by name.
  EXPECT_NE(header.find("namespace raster {\nconst shadergen::Registry& registry();"), std::string::npos);
  EXPECT_NE(header.find("namespace compute {\nconst shadergen::Registry& registry();"), std::string::npos);
  EXPECT_NE(header.find("const shadergen::CompanionShader& tile_lists();"), std::string::npos);
  std::string source = sgtest::read_file(out() / "split_second.cpp");
  EXPECT_NE(source.find("0x07230203u"), std::string::npos);
}

TEST_F(SplitSecondBuild, WarmRebuildHitsTheCacheAndChangesNothing) {
  auto before = sgtest::snapshot(out());
  auto time_before = fs::last_write_time(out() / "split_second.cpp");
  auto summary = build_into(sgtest::split_second_spec(), out(), *root_ / "cache");
  ASSERT_TRUE(summary.ok());
  EXPECT_EQ(summary->compiled, 0u);
  EXPECT_EQ(summary->cache_hits, summary->unique_sources);
  EXPECT_FALSE(summary->output_changed);
  EXPECT_EQ(sgtest::snapshot(out()), before);
  EXPECT_EQ(fs::last_write_time(out() / "split_second.cpp"), time_before);
}

TEST_F(SplitSecondBuild, DeterministicWhateverTheJobCountAndCache) {
  sgtest::TempDir serial_dir("serial");
  const fs::path& other = serial_dir.path();
  auto summary = build_into(sgtest::split_second_spec(), other / "out", other / "cache", 1, false);
  ASSERT_TRUE(summary.ok());
  EXPECT_EQ(summary->cache_hits, 0u);
  EXPECT_EQ(sgtest::snapshot(other / "out"), sgtest::snapshot(out()));
}

TEST(ToyBuild, FixtureDomainBuildsWithItsOwnLayout) {
  sgtest::TempDir toy_dir("toy");
  const fs::path& dir = toy_dir.path();
  auto summary = build_into(sgtest::toy_spec(), dir / "out", dir / "cache", 4);
  ASSERT_TRUE(summary.ok()) << summary.errors().front().to_string();
  EXPECT_EQ(summary->raw, 16u);
  EXPECT_EQ(summary->pruned, 4u);
  auto manifest = nlohmann::json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["domain"], "toy_particles");
  const auto& bindings = manifest["pipeline_layout"]["bindings"];
  ASSERT_EQ(bindings.size(), 4u);
  EXPECT_EQ(bindings[3]["set"], 1);
  EXPECT_EQ(bindings[3]["kind"], "storage_buffer");
  EXPECT_EQ(bindings[3]["stages"], nlohmann::json::array({"compute"}));
  EXPECT_EQ(manifest["pipeline_layout"]["push_constants"][0]["size"], 4);
  EXPECT_TRUE(fs::exists(dir / "out" / "toy_particles.h"));
}

TEST(ToyBuild, ConflictingBindingsAcrossPermutationsAreAnError) {
  sgtest::TempDir conflict_dir("conflict");
  const fs::path& dir = conflict_dir.path();
  fs::copy(sgtest::toy_spec().parent_path(), dir / "domain", fs::copy_options::recursive);
  // In textured permutations, binding 2 becomes a uniform buffer instead of a sampler.
  std::string shader = sgtest::read_file(dir / "domain" / "particle.frag");
  shader.replace(shader.find("void main() {"), 13,
                 "#ifdef USE_TEXTURE\nlayout(set = 0, binding = 2) uniform Clash { vec4 c; } clash;\n#endif\n"
                 "void main() {\n#ifdef USE_TEXTURE\n    vec4 unused = clash.c;\n#endif");
  shader.replace(shader.find("out_color = color;"), 18,
                 "out_color = color;\n#ifdef USE_TEXTURE\n    out_color += clash.c;\n#endif");
  shader.replace(shader.find("#ifdef SOFT_PARTICLES"), 21, "#if defined(SOFT_PARTICLES) && !defined(USE_TEXTURE)");
  sgtest::write_file(dir / "domain" / "particle.frag", shader);
  auto summary = build_into(dir / "domain" / "toy.json", dir / "out", dir / "cache");
  ASSERT_FALSE(summary.ok());
  std::string message = summary.errors().front().to_string();
  EXPECT_NE(message.find("permutations disagree on set 0 binding 2"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace shadergen
