// The whole build, end to end, on the toy fixture domain (tests/fixtures/toy): manifest
// contents, every blob valid for shadergen's validator and for the external spirv-val,
// reflection merged into one pipeline layout, determinism across job counts and cache use,
// warm rebuilds that hit the cache and leave the output (bytes and timestamps) alone, and the
// generated C++ header.
//
// The toy domain: raw bits LIT 0, TEXTURED 1, SOFT 2, DISTORT 3 (declared out of bit order);
// impossible DISTORT && LIT (raw 9, 11, 13, 15); optimised SHADED 0 = LIT || DISTORT,
// SAMPLED 1 = TEXTURED || SOFT; one compute companion "sort".
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "compile/spirv_passes.h"
#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

using nlohmann::json;
using sgtest::fs::path;

// The toy LUT written out by hand from the spec's rules; -1 = pruned.
constexpr std::array<int, 16> kToyTable = {0, 1, 2, 3, 2, 3, 2, 3, 1, -1, 3, -1, 3, -1, 3, -1};

shadergen::Result<shadergen::BuildSummary> build_toy(const path& out, const path& cache, unsigned jobs,
                                                     bool use_cache) {
  shadergen::BuildOptions options = sgtest::build_options(sgtest::toy_spec(), out, cache);
  options.use_cache = use_cache;
  options.jobs = jobs;
  return shadergen::build(options);
}

std::string first_error(const shadergen::Result<shadergen::BuildSummary>& result) {
  return result.ok() ? std::string() : result.errors().front().to_string();
}

std::vector<std::uint32_t> words_of(const std::string& bytes) {
  std::vector<std::uint32_t> words(bytes.size() / sizeof(std::uint32_t));
  if (!words.empty()) std::memcpy(words.data(), bytes.data(), words.size() * sizeof(std::uint32_t));
  return words;
}

// One cold build (-j8, cache on, fresh cache folder) shared by the tests of this suite.
class ToyBuild : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<sgtest::TempDir>("toy-build");
    auto summary = build_toy(out(), cache(), 8, true);
    if (!summary.ok()) {
      setup_error_ = first_error(summary);
      return;
    }
    summary_ = std::make_unique<shadergen::BuildSummary>(*summary);
    manifest_ = std::make_unique<json>(json::parse(sgtest::read_file(out() / "manifest.json")));
  }
  static void TearDownTestSuite() {
    manifest_.reset();
    summary_.reset();
    dir_.reset();
  }
  // A failed shared build must fail every test, not skip them.
  void SetUp() override {
    ASSERT_TRUE(setup_error_.empty()) << setup_error_;
    ASSERT_TRUE(summary_ && manifest_);
  }

  static path out() { return dir_->path() / "out"; }
  static path cache() { return dir_->path() / "cache"; }
  static const json& manifest() { return *manifest_; }

  // Every SPIR-V file the manifest names (raw, optimised and companions), deduplicated.
  static std::set<std::string> blob_paths() {
    std::set<std::string> paths;
    for (const char* section : {"raw", "optimised", "companions"})
      for (const json& entry : manifest()[section])
        if (entry.contains("spirv")) paths.insert(entry["spirv"].get<std::string>());
    return paths;
  }

  static inline std::unique_ptr<sgtest::TempDir> dir_;
  static inline std::unique_ptr<shadergen::BuildSummary> summary_;
  static inline std::unique_ptr<json> manifest_;
  static inline std::string setup_error_;
};

TEST_F(ToyBuild, SummaryCounts) {
  EXPECT_EQ(summary_->raw, 16u);
  EXPECT_EQ(summary_->pruned, 4u);
  EXPECT_EQ(summary_->optimised, 4u);
  EXPECT_EQ(summary_->companions, 1u);
  // 12 compilable raw permutations, each optimised one shares its raw twin's source, plus the companion.
  EXPECT_EQ(summary_->unique_sources, 13u);
  EXPECT_EQ(summary_->compiled, 13u) << "a fresh cache folder: everything is compiled";
  EXPECT_EQ(summary_->cache_hits, 0u);
  EXPECT_EQ(summary_->optimiser_fallbacks, 0u);
  EXPECT_TRUE(summary_->output_changed);
}

TEST_F(ToyBuild, ManifestHas16RawWith4PrunedAnd4Optimised) {
  EXPECT_EQ(manifest()["format"], 1);
  EXPECT_EQ(manifest()["generator"], "shadergen 0.1.0");
  EXPECT_EQ(manifest()["domain"], "toy_particles");
  EXPECT_EQ(manifest()["uber_shader"], "particle.frag");
  EXPECT_EQ(manifest()["stage"], "fragment");
  const json& raw = manifest()["raw"];
  ASSERT_EQ(raw.size(), 16u);
  ASSERT_EQ(manifest()["optimised"].size(), 4u);
  std::set<std::uint32_t> pruned;
  for (std::uint32_t id = 0; id < 16; ++id) {
    const json& entry = raw[id];
    SCOPED_TRACE("raw " + std::to_string(id));
    EXPECT_EQ(entry["id"], id);
    const bool is_pruned = entry["pruned"].get<bool>();
    EXPECT_EQ(is_pruned, kToyTable[id] < 0);
    if (is_pruned) {
      pruned.insert(id);
      EXPECT_FALSE(entry.contains("spirv"));
      EXPECT_FALSE(entry.contains("hash"));
    } else {
      EXPECT_EQ(entry["optimised"], kToyTable[id]);
      ASSERT_TRUE(entry.contains("spirv"));
      ASSERT_TRUE(entry.contains("hash"));
      const std::string hash = entry["hash"];
      EXPECT_EQ(hash.size(), 64u);
      EXPECT_EQ(entry["spirv"], "spirv/" + hash.substr(0, 16) + ".spv");
    }
  }
  EXPECT_EQ(pruned, (std::set<std::uint32_t>{9, 11, 13, 15}));
}

TEST_F(ToyBuild, RawDefinesFollowTheBitsNotTheDeclarationOrder) {
  const json& raw = manifest()["raw"];
  EXPECT_EQ(raw[0]["defines"], json::array());
  EXPECT_EQ(raw[4]["defines"], json::array({"SOFT_PARTICLES"}));
  EXPECT_EQ(raw[7]["defines"], json::array({"LIT", "USE_TEXTURE", "SOFT_PARTICLES"}));
  EXPECT_EQ(raw[14]["defines"], json::array({"USE_TEXTURE", "SOFT_PARTICLES", "DISTORTION"}));
  const json& features = manifest()["raw_features"];
  ASSERT_EQ(features.size(), 4u);
  const std::array<const char*, 4> names = {"LIT", "TEXTURED", "SOFT", "DISTORT"};
  for (std::size_t bit = 0; bit < 4; ++bit) {
    EXPECT_EQ(features[bit]["bit"], bit);
    EXPECT_EQ(features[bit]["name"], names[bit]);
  }
}

TEST_F(ToyBuild, EveryOptimisedPermutationSharesItsRawTwinsBlob) {
  const json& raw = manifest()["raw"];
  const std::array<std::uint32_t, 4> twin = {0, 1, 6, 7};  // raw IDs with the variants' defines
  const std::array<std::uint32_t, 4> mapped = {1, 2, 3, 6};
  for (std::uint32_t id = 0; id < 4; ++id) {
    const json& o = manifest()["optimised"][id];
    SCOPED_TRACE("optimised " + std::to_string(id));
    EXPECT_EQ(o["id"], id);
    EXPECT_EQ(o["raw_equivalent"], twin[id]);
    EXPECT_EQ(o["raw_mapped"], mapped[id]);
    EXPECT_EQ(o["defines"], raw[twin[id]]["defines"]);
    EXPECT_EQ(o["hash"], raw[twin[id]]["hash"]);
    EXPECT_EQ(o["spirv"], raw[twin[id]]["spirv"]);
  }
}

TEST_F(ToyBuild, EverySpirvFileExistsAndOnlyThoseAreWritten) {
  std::set<std::string> named = blob_paths();
  std::set<std::string> on_disk;
  for (const auto& entry : sgtest::fs::directory_iterator(out() / "spirv"))
    on_disk.insert("spirv/" + entry.path().filename().string());
  EXPECT_EQ(named, on_disk);
  EXPECT_EQ(on_disk.size(), summary_->unique_blobs);
  std::set<std::string> top;
  for (const auto& entry : sgtest::fs::directory_iterator(out())) top.insert(entry.path().filename().string());
  EXPECT_EQ(top, (std::set<std::string>{"manifest.json", "spirv", "toy_particles.h", "toy_particles.cpp"}));
}

TEST_F(ToyBuild, EveryBlobPassesShadergensValidator) {
  std::set<std::string> paths = blob_paths();
  ASSERT_EQ(paths.size(), summary_->unique_blobs);
  for (const std::string& relative : paths) {
    SCOPED_TRACE(relative);
    std::string bytes = sgtest::read_file(out() / relative);
    ASSERT_EQ(bytes.size() % 4, 0u);
    std::vector<std::uint32_t> words = words_of(bytes);
    ASSERT_GT(words.size(), 5u);
    EXPECT_EQ(words[0], 0x07230203u);
    shadergen::Status valid = shadergen::validate_spirv(words);
    EXPECT_TRUE(valid.ok()) << (valid.ok() ? "" : valid.errors().front().to_string());
  }
}

TEST_F(ToyBuild, EveryBlobPassesExternalSpirvVal) {
  std::set<std::string> paths = blob_paths();
  ASSERT_FALSE(paths.empty());
  for (const std::string& relative : paths) {
    sgtest::ProcessResult r = sgtest::spirv_val(out() / relative);
    EXPECT_EQ(r.exit_code, 0) << "spirv-val --target-env vulkan1.2 " << relative << "\n" << r.out << r.err;
  }
}

// A second implementation of SHA-256: coreutils sha256sum over the .spv files, which hold the
// little-endian SPIR-V words the manifest's hash covers. Every hash the manifest states (raw,
// optimised, companions) must be the digest of the file it names.
TEST_F(ToyBuild, EveryManifestHashIsTheSha256sumOfItsSpirvFile) {
  std::vector<std::string> files;
  for (const std::string& relative : blob_paths()) files.push_back((out() / relative).string());
  ASSERT_FALSE(files.empty());
  sgtest::ProcessResult r = sgtest::run_process("sha256sum", files);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, std::string> digest_of;  // "spirv/<name>.spv" -> sha256sum's digest
  std::istringstream lines(r.out);
  for (std::string digest, file; lines >> digest >> file;)
    digest_of["spirv/" + path(file).filename().string()] = digest;
  ASSERT_EQ(digest_of.size(), files.size()) << r.out;
  std::size_t checked = 0;
  for (const char* section : {"raw", "optimised", "companions"})
    for (const json& entry : manifest()[section]) {
      if (!entry.contains("spirv")) continue;
      const std::string relative = entry["spirv"];
      SCOPED_TRACE(std::string(section) + " " + relative);
      EXPECT_EQ(entry["hash"], digest_of[relative]);
      ++checked;
    }
  EXPECT_EQ(checked, 12u + 4u + 1u) << "12 compilable raw, 4 optimised, 1 companion";
}

TEST_F(ToyBuild, MergedPipelineLayoutMatchesTheShaders) {
  const json& layout = manifest()["pipeline_layout"];
  const json expected_bindings = json::parse(R"([
        {"set": 0, "binding": 0, "kind": "uniform_buffer", "count": 1, "stages": ["fragment"], "name": "ParticleParams"},
        {"set": 0, "binding": 1, "kind": "combined_image_sampler", "count": 1, "stages": ["fragment"],
         "name": "particle_texture"},
        {"set": 0, "binding": 2, "kind": "combined_image_sampler", "count": 1, "stages": ["fragment"],
         "name": "scene_depth"},
        {"set": 1, "binding": 0, "kind": "storage_buffer", "count": 1, "stages": ["compute"], "name": "Keys"}
    ])");
  EXPECT_EQ(layout["bindings"], expected_bindings) << layout["bindings"].dump(2);
  EXPECT_EQ(layout["push_constants"], json::parse(R"([{"size": 4, "stages": ["compute"]}])"))
      << layout["push_constants"].dump(2);
}

TEST_F(ToyBuild, CompanionIsCompiledWithItsOwnDefines) {
  const json& companions = manifest()["companions"];
  ASSERT_EQ(companions.size(), 1u);
  EXPECT_EQ(companions[0]["name"], "sort");
  EXPECT_EQ(companions[0]["stage"], "compute");
  EXPECT_EQ(companions[0]["defines"], json::array({"WIDE_GROUPS"}));
  EXPECT_EQ(companions[0]["shared_layout"], true);
  ASSERT_TRUE(companions[0].contains("spirv"));
  EXPECT_TRUE(sgtest::fs::exists(out() / companions[0]["spirv"].get<std::string>()));
}

TEST_F(ToyBuild, GeneratedHeaderCarriesBannerTableAndStaticAssert) {
  const std::string header = sgtest::read_file(out() / "toy_particles.h");
  EXPECT_EQ(header.rfind("// Generated by shadergen 0.1.0 from toy.json (domain \"toy_particles\").\n", 0), 0u)
      << header.substr(0, 200);
  EXPECT_TRUE(sgtest::contains(header, "// Do not edit: edit the domain spec or the shaders and rebuild.\n"));
  EXPECT_TRUE(sgtest::contains(header, "namespace toy_particles {"));
  EXPECT_TRUE(sgtest::contains(header, "inline constexpr std::uint32_t kRawCount = 16;\n"));
  EXPECT_TRUE(sgtest::contains(header, "inline constexpr std::uint32_t kOptimisedCount = 4;\n"));
  // The exact LUT line (pruned entries carry the value the rules give them).
  EXPECT_TRUE(sgtest::contains(header,
                               "inline constexpr std::array<std::uint8_t, kRawCount> kRawToOptimised = {{\n"
                               "    0, 1, 2, 3, 2, 3, 2, 3, 1, 1, 3, 3, 3, 3, 3, 3,\n}};\n"))
      << header;
  EXPECT_TRUE(sgtest::contains(header,
                               "    false, false, false, false, false, false, false, false, false, true, false, "
                               "true, false, true, false, true,\n"))
      << header;
  // Raw and optimised bits and IDs are types of their own (shadergen/registry.h).
  EXPECT_TRUE(
      sgtest::contains(header, "using RawId = shadergen::RawId;\nusing OptimisedId = shadergen::OptimisedId;\n"));
  EXPECT_TRUE(sgtest::contains(header, "inline constexpr RawBits SOFT{1u << 2};  // #define SOFT_PARTICLES\n"));
  EXPECT_TRUE(sgtest::contains(header, "inline constexpr OptimisedBits SAMPLED{1u << 1};\n"));
  // Every lookup by raw ID is checked before it indexes a table, and raw_id() checks too.
  EXPECT_TRUE(sgtest::contains(header,
                               "constexpr bool is_valid_raw_id(RawId raw_id) {\n"
                               "  return raw_id.value() < kRawCount && !kRawPruned[raw_id.value()];\n}\n"))
      << header;
  EXPECT_TRUE(sgtest::contains(header,
                               "constexpr std::optional<OptimisedId> optimised_id(RawId raw_id) {\n"
                               "  if (!is_valid_raw_id(raw_id)) return std::nullopt;\n"
                               "  return OptimisedId(kRawToOptimised[raw_id.value()]);\n}\n"))
      << header;
  EXPECT_TRUE(sgtest::contains(header,
                               "constexpr std::optional<RawId> raw_id([[maybe_unused]] const Features& "
                               "features) {\n  std::uint32_t id = 0;\n  if (features.SOFT) id |= 1u << 2;\n"
                               "  if (features.LIT) id |= 1u << 0;\n  if (features.TEXTURED) id |= 1u << 1;\n"
                               "  if (features.DISTORT) id |= 1u << 3;\n"
                               "  if (!is_valid_raw_id(RawId(id))) return std::nullopt;\n  return RawId(id);\n}\n"))
      << header;
  // is_possible() is the impossible rule itself, translated; features() decodes a raw ID.
  EXPECT_TRUE(sgtest::contains(header,
                               "constexpr bool is_possible([[maybe_unused]] const Features& features) {\n"
                               "  // DISTORT && LIT: distortion particles are never lit\n"
                               "  if (features.DISTORT && features.LIT) return false;\n  return true;\n}\n"))
      << header;
  EXPECT_TRUE(sgtest::contains(header, "  decoded.DISTORT = ((raw_id.value() >> 3) & 1u) != 0;\n")) << header;
  // The one grammar's parser lives in <shadergen/registry.h>; the header hands it kFeatures and
  // refuses what is impossible.
  EXPECT_TRUE(sgtest::contains(header,
                               "constexpr std::optional<RawId> find_raw_id(std::string_view text) {\n"
                               "  const std::optional<std::uint32_t> id = shadergen::find_raw_id(kFeatures, text);\n"
                               "  if (!id || !is_possible(features(RawId(*id)))) return std::nullopt;\n"
                               "  return RawId(*id);\n}\n"))
      << header;
  EXPECT_TRUE(sgtest::contains(header, "inline std::string to_string(RawId raw_id) {")) << header;
  EXPECT_TRUE(sgtest::contains(header, "    if (kRawPruned[id] == is_possible(features(RawId(id)))) return false;\n"))
      << header;
  EXPECT_TRUE(sgtest::contains(header, "static_assert("));
  EXPECT_TRUE(sgtest::contains(header, "const shadergen::Registry& registry();"));
  EXPECT_FALSE(sgtest::contains(header, "0x07230203")) << "SPIR-V words belong in the source, not the header";

  const std::string source = sgtest::read_file(out() / "toy_particles.cpp");
  EXPECT_TRUE(sgtest::contains(source, "#include \"toy_particles.h\""));
  EXPECT_TRUE(sgtest::contains(
      source, "// " + std::to_string(summary_->unique_blobs) + " distinct SPIR-V blobs, stored once each.\n"));
  // One word array holding each distinct blob once: as many magic numbers as blobs.
  EXPECT_EQ(sgtest::count_of(source, "0x07230203u"), summary_->unique_blobs);
}

TEST_F(ToyBuild, SerialColdBuildWithoutCacheIsByteIdentical) {
  sgtest::TempDir other("toy-serial");
  auto summary = build_toy(other / "out", other / "unused-cache", 1, false);
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  EXPECT_EQ(summary->cache_hits, 0u);
  EXPECT_EQ(summary->compiled, 13u);
  EXPECT_FALSE(sgtest::fs::exists(other / "unused-cache")) << "--no-cache must not create the cache folder";
  auto mine = sgtest::snapshot(other / "out");
  auto shared = sgtest::snapshot(out());
  EXPECT_EQ(mine, shared) << sgtest::describe_difference(mine, shared);
}

TEST_F(ToyBuild, WarmBuildIntoANewFolderHitsTheCacheAndIsByteIdentical) {
  sgtest::TempDir other("toy-warm");
  auto summary = build_toy(other / "out", cache(), 3, true);
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  EXPECT_EQ(summary->compiled, 0u);
  EXPECT_EQ(summary->cache_hits, summary->unique_sources);
  EXPECT_EQ(summary->cache_hits, 13u);
  EXPECT_TRUE(summary->output_changed) << "a new folder is a change";
  auto mine = sgtest::snapshot(other / "out");
  auto shared = sgtest::snapshot(out());
  EXPECT_EQ(mine, shared) << sgtest::describe_difference(mine, shared);
}

TEST_F(ToyBuild, RebuildIntoTheSameFolderChangesNothing) {
  auto bytes_before = sgtest::snapshot(out());
  auto times_before = sgtest::mtimes(out());
  for (bool use_cache : {true, false}) {
    SCOPED_TRACE(use_cache ? "warm cache" : "--no-cache");
    auto summary = build_toy(out(), cache(), use_cache ? 2 : 8, use_cache);
    ASSERT_TRUE(summary.ok()) << first_error(summary);
    EXPECT_FALSE(summary->output_changed);
    if (use_cache) {
      EXPECT_EQ(summary->compiled, 0u);
      EXPECT_EQ(summary->cache_hits, 13u);
    }
    EXPECT_EQ(sgtest::snapshot(out()), bytes_before);
    EXPECT_EQ(sgtest::mtimes(out()), times_before) << "unchanged files must keep their timestamps";
  }
  // Nothing is left beside the output folder (no staging or backup folders).
  std::set<std::string> siblings;
  for (const auto& entry : sgtest::fs::directory_iterator(dir_->path()))
    siblings.insert(entry.path().filename().string());
  EXPECT_EQ(siblings, (std::set<std::string>{"cache", "out"}));
}

TEST_F(ToyBuild, StatsReportCountsEveryStage) {
  sgtest::TempDir other("toy-stats");
  shadergen::BuildOptions options = sgtest::build_options(sgtest::toy_spec(), other / "out", cache());
  options.write_stats = true;
  auto summary = shadergen::build(options);
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  json stats = json::parse(sgtest::read_file(other / "out" / "stats.json"));
  const json& stages = stats["stages"];
  EXPECT_EQ(stages["raw"], 16);
  EXPECT_EQ(stages["pruned"], 4);
  EXPECT_EQ(stages["canonical"], 12 + 4 + 1) << "compilable raw + optimised + companion";
  EXPECT_EQ(stages["unique_sources"], 13);
  EXPECT_EQ(stages["cache_hits"], 13);
  EXPECT_EQ(stages["unique_blobs"], summary_->unique_blobs);
  EXPECT_EQ(stages["optimiser_fallbacks"], 0);
  EXPECT_EQ(stats["permutations"].size(), 17u);
  // Everything but stats.json is the same as without --stats.
  auto with_stats = sgtest::snapshot(other / "out");
  ASSERT_EQ(with_stats.erase("stats.json"), 1u);
  auto shared = sgtest::snapshot(out());
  EXPECT_EQ(with_stats, shared) << sgtest::describe_difference(with_stats, shared);
}

TEST_F(ToyBuild, CancelledBuildFailsAndLeavesTheOutputAlone) {
  auto bytes_before = sgtest::snapshot(out());
  auto times_before = sgtest::mtimes(out());
  shadergen::BuildOptions options = sgtest::build_options(sgtest::toy_spec(), out(), {});
  options.use_cache = false;                  // something to compile, so the poll is reached
  options.cpp_namespace = "other_namespace";  // the output would change if it were written
  options.cancelled = [] { return true; };
  auto summary = shadergen::build(options);
  ASSERT_FALSE(summary.ok());
  EXPECT_EQ(sgtest::snapshot(out()), bytes_before);
  EXPECT_EQ(sgtest::mtimes(out()), times_before);
}

TEST(ToyBuildCache, AnExplicitCacheFolderIsTheOnlyOneUsed) {
  sgtest::TempDir dir("toy-cache-env");
  // If the build consulted the default location, it would create this folder.
  const std::string decoy = (dir / "env-cache").string();
  const char* previous = std::getenv("SHADERGEN_CACHE_DIR");
  const std::string saved = previous ? previous : "";
  ::setenv("SHADERGEN_CACHE_DIR", decoy.c_str(), 1);
  auto summary = build_toy(dir / "out", dir / "explicit-cache", 2, true);
  if (previous)
    ::setenv("SHADERGEN_CACHE_DIR", saved.c_str(), 1);
  else
    ::unsetenv("SHADERGEN_CACHE_DIR");
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  EXPECT_FALSE(sgtest::fs::exists(decoy));
  std::size_t entries = 0, input_sets = 0;
  for (const auto& entry : sgtest::fs::recursive_directory_iterator(dir / "explicit-cache"))
    if (entry.is_regular_file()) {
      if (entry.path().parent_path().filename() == "inputs")
        ++input_sets;
      else
        ++entries;
    }
  EXPECT_EQ(entries, 13u) << "one entry per distinct source";
  EXPECT_EQ(input_sets, 1u) << "one input-set entry for the one spec";
}

TEST(ToyBuildNames, CppNameAndNamespaceOptionsNameTheGeneratedFiles) {
  sgtest::TempDir dir("toy-names");
  shadergen::BuildOptions options = sgtest::build_options(sgtest::toy_spec(), dir / "out", dir / "cache");
  options.cpp_name = "particles_gen";
  options.cpp_namespace = "game::fx";
  auto summary = shadergen::build(options);
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  EXPECT_TRUE(sgtest::fs::exists(dir / "out" / "particles_gen.h"));
  EXPECT_TRUE(sgtest::fs::exists(dir / "out" / "particles_gen.cpp"));
  EXPECT_FALSE(sgtest::fs::exists(dir / "out" / "toy_particles.h"));
  EXPECT_TRUE(sgtest::contains(sgtest::read_file(dir / "out" / "particles_gen.h"), "namespace game::fx {"));
  EXPECT_TRUE(sgtest::contains(sgtest::read_file(dir / "out" / "particles_gen.cpp"), "#include \"particles_gen.h\""));
}

TEST(ToyBuildNames, InvalidNamespaceIsRefusedBeforeAnythingIsWritten) {
  sgtest::TempDir dir("toy-bad-ns");
  shadergen::BuildOptions options = sgtest::build_options(sgtest::toy_spec(), dir / "out", dir / "cache");
  options.cpp_namespace = "game::2fx";
  auto summary = shadergen::build(options);
  ASSERT_FALSE(summary.ok());
  EXPECT_EQ(summary.errors().front().to_string(),
            "error: --namespace: \"game::2fx\" is not a C++ namespace (identifiers joined by ::)");
  EXPECT_FALSE(sgtest::fs::exists(dir / "out"));
}

// "compile": "optimised": the 4 optimised permutations and the companion are compiled, the raw
// ones keep their IDs, defines and table entries but carry no SPIR-V.
TEST(ToyBuildCompileSet, OptimisedOnlyCompilesTheOptimisedPermutations) {
  sgtest::TempDir dir("toy-optimised-only");
  sgtest::fs::copy(sgtest::toy_spec().parent_path(), dir / "toy", sgtest::fs::copy_options::recursive);
  std::string spec = sgtest::read_file(dir / "toy" / "toy.json");
  spec.insert(spec.find('{') + 1, "\n  \"compile\": \"optimised\",");
  sgtest::write_file(dir / "toy" / "toy.json", spec);
  auto summary = shadergen::build(sgtest::build_options(dir / "toy" / "toy.json", dir / "out", dir / "cache"));
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  EXPECT_EQ(summary->raw, 16u);
  EXPECT_EQ(summary->permutations, 5u) << "4 optimised + the companion";
  EXPECT_EQ(summary->unique_sources, 5u);
  json manifest = json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["compile"], "optimised");
  for (std::uint32_t id = 0; id < 16; ++id) {
    SCOPED_TRACE("raw " + std::to_string(id));
    EXPECT_FALSE(manifest["raw"][id].contains("spirv"));
    if (kToyTable[id] >= 0) {
      EXPECT_EQ(manifest["raw"][id]["optimised"], kToyTable[id]);
    }
  }
  for (const json& optimised : manifest["optimised"]) EXPECT_TRUE(optimised.contains("spirv"));
  // The registry keeps the raw IDs' own pruned flags (4 of 16), so its lookups still draw the
  // 12 others through the table: a raw permutation without SPIR-V is not a pruned one.
  const std::string source = sgtest::read_file(dir / "out" / "toy_particles.cpp");
  std::size_t pruned = 0, unpruned = 0;
  for (std::size_t at = 0; (at = source.find("), true, {}, \"\", {}}", at)) != std::string::npos; ++at) ++pruned;
  for (std::size_t at = 0; (at = source.find("), false, {}, \"\", {}}", at)) != std::string::npos; ++at) ++unpruned;
  EXPECT_EQ(pruned, 4u);
  EXPECT_EQ(unpruned, 12u);

  // Without a collapse there is nothing else to compile: refused at the key.
  std::string identity = sgtest::read_file(sgtest::fixtures_dir() / "identity" / "identity.json");
  identity.insert(identity.find('{') + 1, "\n  \"compile\": \"optimised\",");
  sgtest::fs::copy(sgtest::fixtures_dir() / "identity", dir / "identity", sgtest::fs::copy_options::recursive);
  sgtest::write_file(dir / "identity" / "identity.json", identity);
  auto refused = shadergen::build(sgtest::build_options(dir / "identity" / "identity.json", dir / "id", dir / "cache"));
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.errors().front().to_string(),
            (dir / "identity" / "identity.json").string() +
                ":2:14: error: compile: \"optimised\" needs an \"optimised\" section: without a collapse the raw "
                "permutations are the only ones");
}

}  // namespace
