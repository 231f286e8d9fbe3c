// The input-set cache (input_cache.h) and the recompile counts, on a copy of the toy fixture
// in a temporary folder: a warm build that skips preprocessing writes exactly what a cold
// build writes (depfile included); a corrupted or foreign entry reads as a miss; any change to
// a file the preprocessor read, or a file appearing where an include was probed, forces
// preprocessing; and editing code inside one #ifdef block (in place or by adding a line)
// recompiles exactly the permutations that define that feature.
#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "base/sha256.h"
#include "cache/input_cache.h"
#include "cache/source_key.h"
#include "cli/build_stats.h"
#include "shadergen/build.h"
#include "test_helpers.h"

// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace input_cache_test {
namespace {

namespace fs = sgtest::fs;
using nlohmann::json;

// A private copy of the toy fixture with its own cache, so edits touch nothing shared.
class ToyCopy {
 public:
  ToyCopy() : dir_("input-cache") {
    fs::copy(sgtest::fixtures_dir() / "toy", dir_ / "toy", fs::copy_options::recursive);
  }

  fs::path spec() const { return dir_ / "toy" / "toy.json"; }
  fs::path file(const std::string& relative) const { return dir_ / "toy" / relative; }
  fs::path cache() const { return dir_ / "cache"; }
  fs::path path(const std::string& name) const { return dir_ / name; }

  shadergen::Result<shadergen::BuildSummary> build(const std::string& out, bool use_cache = true) const {
    shadergen::BuildOptions options = sgtest::build_options(spec(), dir_ / out, cache());
    options.use_cache = use_cache;
    options.depfile = dir_ / (out + ".d");
    return shadergen::build(options);
  }

  // The one input-set entry the builds so far have written.
  fs::path only_entry() const {
    std::vector<fs::path> entries;
    for (const auto& entry : fs::directory_iterator(cache() / "inputs")) entries.push_back(entry.path());
    EXPECT_EQ(entries.size(), 1u);
    return entries.empty() ? fs::path() : entries.front();
  }

  void replace_in(const std::string& relative, const std::string& from, const std::string& to) const {
    std::string text = sgtest::read_file(file(relative));
    auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    sgtest::write_file(file(relative), text.replace(at, from.size(), to));
  }

 private:
  sgtest::TempDir dir_;
};

std::string first_error(const shadergen::Result<shadergen::BuildSummary>& result) {
  return result.ok() ? std::string() : result.errors().front().to_string();
}

// Output folder and depfile of one build, for byte comparisons.
std::map<std::string, std::string> outputs(const ToyCopy& toy, const std::string& out) {
  auto files = sgtest::snapshot(toy.path(out));
  files["(depfile)"] = sgtest::read_file(toy.path(out + ".d"));
  return files;
}

// Re-targets a depfile written for `from` at `to`, so builds into two folders compare.
std::map<std::string, std::string> retargeted(std::map<std::string, std::string> files, const ToyCopy& toy,
                                              const std::string& from, const std::string& to) {
  std::string& depfile = files["(depfile)"];
  std::string old_target = (toy.path(from) / "toy_particles.h").string();
  if (depfile.rfind(old_target, 0) == 0)
    depfile.replace(0, old_target.size(), (toy.path(to) / "toy_particles.h").string());
  return files;
}

TEST(InputCache, WarmBuildSkipsPreprocessingAndWritesWhatAColdBuildWrites) {
  ToyCopy toy;
  auto first = toy.build("first");
  ASSERT_TRUE(first.ok()) << first_error(first);
  EXPECT_FALSE(first->inputs_reused);
  EXPECT_EQ(first->recompiled, 17u);
  auto warm = toy.build("warm");
  ASSERT_TRUE(warm.ok()) << first_error(warm);
  EXPECT_TRUE(warm->inputs_reused);
  EXPECT_EQ(warm->recompiled, 0u);
  EXPECT_EQ(warm->reused, 17u);
  EXPECT_EQ(warm->cache_hits, 13u);
  auto cold = toy.build("cold", false);
  ASSERT_TRUE(cold.ok()) << first_error(cold);
  EXPECT_FALSE(cold->inputs_reused) << "--no-cache reads no input-set entry";
  auto warm_files = retargeted(outputs(toy, "warm"), toy, "warm", "cold");
  auto cold_files = outputs(toy, "cold");
  EXPECT_EQ(warm_files, cold_files) << sgtest::describe_difference(warm_files, cold_files);
}

TEST(InputCache, EntryRoundTripsAndEveryCorruptionReadsAsAMiss) {
  const std::string key = shadergen::sha256_hex("some build");
  shadergen::InputSet set;
  set.files = {{"a/b c.glsl", true, shadergen::sha256_hex("x")}, {"a/missing.glsl", false, {}}};
  set.source_keys = {shadergen::sha256_hex("1"), shadergen::sha256_hex("2"), shadergen::sha256_hex("1")};
  std::string bytes = shadergen::encode_input_set(key, set);
  auto decoded = shadergen::decode_input_set(key, bytes);
  ASSERT_TRUE(decoded.has_value());
  ASSERT_EQ(decoded->files.size(), 2u);
  EXPECT_EQ(decoded->files[0].path, fs::path("a/b c.glsl"));
  EXPECT_EQ(decoded->files[0].digest, set.files[0].digest);
  EXPECT_FALSE(decoded->files[1].found);
  EXPECT_EQ(decoded->source_keys, set.source_keys);

  EXPECT_FALSE(shadergen::decode_input_set(shadergen::sha256_hex("other build"), bytes)) << "foreign key";
  EXPECT_FALSE(shadergen::decode_input_set(key, bytes.substr(0, bytes.size() / 2))) << "truncated";
  EXPECT_FALSE(shadergen::decode_input_set(key, "")) << "empty";
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x01);
    EXPECT_FALSE(shadergen::decode_input_set(key, flipped)) << "byte " << at << " flipped";
  }
}

// The shards' parts (build --shard with a secret): a key per (build, I, N), and the merge's
// join keeps each path once and the keys in shard order, refusing two parts that read a file
// differently.
TEST(InputSetParts, KeysDifferPerShardAndJoinedPartsAreTheWholeSet) {
  const std::string whole = shadergen::sha256_hex("some build");
  std::set<std::string> keys{whole};
  for (std::uint32_t count : {1u, 2u, 3u})
    for (std::uint32_t i = 0; i < count; ++i)
      EXPECT_TRUE(keys.insert(shadergen::input_set_part_key(whole, i, count)).second) << i << "/" << count;
  EXPECT_EQ(shadergen::input_set_part_key(whole, 1, 3), shadergen::input_set_part_key(whole, 1, 3));
  EXPECT_NE(shadergen::input_set_part_key(whole, 1, 3), shadergen::input_set_part_key(whole, 1, 4));

  const std::string a = shadergen::sha256_hex("a"), b = shadergen::sha256_hex("b");
  shadergen::InputSet first{{{"shared.glsl", true, a}, {"only0.glsl", false, {}}}, {a, b}};
  shadergen::InputSet second{{{"shared.glsl", true, a}, {"only1.glsl", true, b}}, {b}};
  auto joined = shadergen::join_input_parts({first, second});
  ASSERT_TRUE(joined.ok());
  EXPECT_EQ(joined->source_keys, (std::vector<std::string>{a, b, b}));
  ASSERT_EQ(joined->files.size(), 3u);
  EXPECT_EQ(joined->files[0].path, fs::path("only0.glsl"));
  EXPECT_EQ(joined->files[1].path, fs::path("only1.glsl"));
  EXPECT_EQ(joined->files[2].path, fs::path("shared.glsl"));

  second.files[0].digest = b;  // shard 1 read other bytes of shared.glsl
  auto refused = shadergen::join_input_parts({first, second});
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.errors().front().message,
            "shards 0/2 and 1/2 read different bytes of shared.glsl: it changed while the shards ran; rerun the "
            "shards");
}

TEST(InputCache, CorruptedEntryOnDiskIsAMissAndTheBuildIsStillRight) {
  ToyCopy toy;
  ASSERT_TRUE(toy.build("first").ok());
  fs::path entry = toy.only_entry();
  std::string bytes = sgtest::read_file(entry);
  // One bit of the first job's key flipped: still well-formed, but the checksum disagrees.
  std::string corrupted = bytes;
  std::size_t jobs_line = corrupted.find("jobs ");
  ASSERT_NE(jobs_line, std::string::npos);
  corrupted[corrupted.find('\n', jobs_line) + 1] ^= 0x04;
  sgtest::write_file(entry, corrupted);
  auto rebuilt = toy.build("second");
  ASSERT_TRUE(rebuilt.ok()) << first_error(rebuilt);
  EXPECT_FALSE(rebuilt->inputs_reused);
  EXPECT_EQ(rebuilt->recompiled, 0u) << "the content cache still answers";
  auto second = retargeted(outputs(toy, "second"), toy, "second", "first");
  auto first = outputs(toy, "first");
  EXPECT_EQ(second, first) << sgtest::describe_difference(second, first);
  EXPECT_EQ(sgtest::read_file(entry), bytes) << "the preprocessed build writes the entry again";
  auto third = toy.build("third");
  ASSERT_TRUE(third.ok()) << first_error(third);
  EXPECT_TRUE(third->inputs_reused);
}

TEST(InputCache, EditedIncludeIsPreprocessedAgain) {
  ToyCopy toy;
  ASSERT_TRUE(toy.build("before").ok());
  toy.replace_in("include/particle_common.glsl", "\n", "\n// an edit that changes no code\n");
  auto after = toy.build("after");
  ASSERT_TRUE(after.ok()) << first_error(after);
  EXPECT_FALSE(after->inputs_reused);
  EXPECT_EQ(after->recompiled, 0u) << "a comment and a line break change no content key";
  auto again = toy.build("again");
  ASSERT_TRUE(again.ok()) << first_error(again);
  EXPECT_TRUE(again->inputs_reused);
}

// particle.frag includes "particle_common.glsl": glslang looks beside particle.frag first and
// then in include/. A file created beside it takes over, so the old keys must not be used.
TEST(InputCache, FileAppearingWhereAnIncludeWasProbedIsPreprocessedAgain) {
  ToyCopy toy;
  ASSERT_TRUE(toy.build("before").ok());
  fs::copy_file(toy.file("include/particle_common.glsl"), toy.file("particle_common.glsl"));
  sgtest::write_file(toy.file("particle_common.glsl"),
                     sgtest::read_file(toy.file("particle_common.glsl")) + "const float shadowing_copy = 1.0;\n");
  auto after = toy.build("after");
  ASSERT_TRUE(after.ok()) << first_error(after);
  EXPECT_FALSE(after->inputs_reused);
  EXPECT_GT(after->recompiled, 0u) << "the shadowing copy changes the preprocessed text";
  std::string depfile = sgtest::read_file(toy.path("after.d"));
  EXPECT_NE(depfile.find(fs::absolute(toy.file("particle_common.glsl")).lexically_normal().string()), std::string::npos)
      << depfile;
}

// Permutations (raw, not pruned, and optimised) whose defines include `define`, from the manifest.
std::uint32_t permutations_defining(const json& manifest, const std::string& define) {
  std::uint32_t count = 0;
  for (const char* section : {"raw", "optimised"})
    for (const json& entry : manifest[section]) {
      if (entry.value("pruned", false)) continue;
      for (const json& d : entry["defines"]) count += d.get<std::string>() == define;
    }
  return count;
}

TEST(InputCache, EditInsideOneIfdefRecompilesExactlyThePermutationsDefiningIt) {
  ToyCopy toy;
  auto first = toy.build("out");
  ASSERT_TRUE(first.ok()) << first_error(first);
  toy.replace_in("particle.frag", "color.a *= clamp((scene - gl_FragCoord.z) * 50.0, 0.0, 1.0);",
                 "color.a *= clamp((scene - gl_FragCoord.z) * 40.0, 0.0, 1.0);");
  auto edited = toy.build("out");
  ASSERT_TRUE(edited.ok()) << first_error(edited);
  json manifest = json::parse(sgtest::read_file(toy.path("out") / "manifest.json"));
  std::uint32_t expected = permutations_defining(manifest, "SOFT_PARTICLES");
  EXPECT_EQ(expected, 8u) << "6 unpruned raw with SOFT + optimised 2 and 3";
  EXPECT_FALSE(edited->inputs_reused);
  EXPECT_EQ(edited->recompiled, expected);
  EXPECT_EQ(edited->reused, edited->permutations - expected);
  EXPECT_TRUE(edited->output_changed);

  // A new line inside the block moves every later line of every permutation; only the
  // permutations that keep the block have new code.
  toy.replace_in("particle.frag", "#ifdef SOFT_PARTICLES\n", "#ifdef SOFT_PARTICLES\n    float unused_edit = 0.0;\n");
  auto inserted = toy.build("out");
  ASSERT_TRUE(inserted.ok()) << first_error(inserted);
  EXPECT_EQ(inserted->recompiled, expected);
}

TEST(SourceKey, DropsBlankLinesAndLineDirectivesOnly) {
  EXPECT_EQ(
      shadergen::key_text("#version 450\n\n   \n#line 1 \"a.glsl\"\nfloat x;\n  # line 7\n#linear\nvoid main() {}"),
      "#version 450\nfloat x;\n#linear\nvoid main() {}\n");
  EXPECT_EQ(shadergen::key_text("a\n\nb\n"), shadergen::key_text("a\nb\n\n\n"));
  EXPECT_NE(shadergen::key_text("a b\n"), shadergen::key_text("ab\n"));
}

TEST(InputCache, CliStatsLineCountsRecompiledAndReusedPermutations) {
  ToyCopy toy;
  std::vector<std::string> args{"build",       toy.spec().string(),  "--out",  toy.path("out").string(),
                                "--cache-dir", toy.cache().string(), "--stats"};
  auto first = sgtest::run_process(sgtest::shadergen_exe(), args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_TRUE(
      sgtest::contains(first.out, "\nshadergen: permutations: 17 (17 recompiled, 0 reused); inputs preprocessed\n"))
      << first.out;
  auto second = sgtest::run_process(sgtest::shadergen_exe(), args);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_TRUE(sgtest::contains(
      second.out, "\nshadergen: permutations: 17 (0 recompiled, 17 reused); inputs unchanged, preprocessing skipped\n"))
      << second.out;
  json stats = json::parse(sgtest::read_file(toy.path("out") / "stats.json"));
  EXPECT_EQ(stats["recompiled_permutations"], 0);
  EXPECT_EQ(stats["reused_permutations"], 17);
  EXPECT_EQ(stats["inputs_reused"], true);
  EXPECT_FALSE(stats["phases_ms"].contains("preprocess"));
  EXPECT_TRUE(stats["phases_ms"].contains("compile or load"));
}

TEST(InputCache, StatsLinesSayRecompiledReusedAndThePhases) {
  shadergen::BuildSummary summary;
  summary.permutations = 17;
  summary.recompiled = 8;
  summary.reused = 9;
  summary.phases = {{"parse spec", 1.5}, {"preprocess", 20.0}};
  EXPECT_EQ(shadergen::format_build_stats(summary),
            "shadergen: permutations: 17 (8 recompiled, 9 reused); inputs preprocessed\n"
            "shadergen: phases (ms): parse spec 1.5, preprocess 20.0\n");
  summary.inputs_reused = true;
  EXPECT_NE(shadergen::format_build_stats(summary).find("inputs unchanged, preprocessing skipped\n"),
            std::string::npos);
}

}  // namespace
}  // namespace input_cache_test
