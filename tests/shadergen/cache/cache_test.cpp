// The content cache never serves a bad entry: truncated, corrupted or foreign entries are
// recompiled, and a rebuild over a damaged cache is byte-identical to a cold build.
#include <gtest/gtest.h>

#include "cache/cache.h"
#include "compile/toolchain.h"
#include "shadergen/build.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

namespace fs = std::filesystem;

const std::string kKey(64, 'a');
const std::string kOtherKey(64, 'b');

CachedBlob sample_blob() { return CachedBlob{{0x07230203u, 1u, 2u, 3u}, false, {}}; }

TEST(CacheEntry, RoundTrips) {
  std::string bytes = encode_cache_entry(kKey, sample_blob());
  auto decoded = decode_cache_entry(kKey, bytes);
  ASSERT_TRUE(decoded.has_value());
  EXPECT_EQ(decoded->words, sample_blob().words);
}

TEST(CacheEntry, RejectsEveryKindOfDamage) {
  std::string good = encode_cache_entry(kKey, sample_blob());
  EXPECT_FALSE(decode_cache_entry(kOtherKey, good)) << "an entry for another key";
  for (std::size_t cut = 0; cut < good.size(); ++cut)
    EXPECT_FALSE(decode_cache_entry(kKey, good.substr(0, cut))) << "truncated to " << cut;
  for (std::size_t at = 0; at < good.size(); ++at) {
    std::string flipped = good;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x01);
    auto decoded = decode_cache_entry(kKey, flipped);
    // Flipping a byte of the fallback reason is the only change that still decodes (there is
    // none in this entry), so every flip must be rejected.
    EXPECT_FALSE(decoded) << "byte " << at << " flipped";
  }
  EXPECT_FALSE(decode_cache_entry(kKey, good + "x")) << "trailing bytes";
  EXPECT_FALSE(decode_cache_entry(kKey, ""));
}

// An entry written by another shadergen version, another compiler or optimiser library, for
// another target or with another optimiser recipe sits under another key, so it is never read.
TEST(CacheKey, EveryPartOfTheToolDescriptionChangesTheKey) {
  const CacheKeyParts current = current_cache_key_parts();
  EXPECT_EQ(current.tool_version, SHADERGEN_VERSION_STRING);
  EXPECT_FALSE(current.glslang_version.empty());
  EXPECT_FALSE(current.spirv_tools_version.empty());
  const std::string key = cache_key(current, "frag", "void main() {}");
  for (std::string CacheKeyParts::*part :
       {&CacheKeyParts::tool_version, &CacheKeyParts::glslang_version, &CacheKeyParts::spirv_tools_version,
        &CacheKeyParts::target, &CacheKeyParts::optimiser_recipe}) {
    CacheKeyParts other = current;
    other.*part += "-other";
    EXPECT_NE(cache_key(other, "frag", "void main() {}"), key) << current.*part;
  }
  EXPECT_NE(cache_key(current, "vert", "void main() {}"), key);
  EXPECT_NE(cache_key(current, "frag", "void main() { }"), key);
  // Fields are length-delimited: moving a character from one field to the next is a new key.
  CacheKeyParts shifted = current;
  shifted.target += shifted.optimiser_recipe.substr(0, 1);
  shifted.optimiser_recipe.erase(0, 1);
  EXPECT_NE(cache_key(shifted, "frag", "void main() {}"), key);
}

TEST(CacheEntry, DefaultDirectoryFollowsTheEnvironment) {
  const sgtest::ScopedEnvironment restored({"SHADERGEN_CACHE_DIR", "XDG_CACHE_HOME", "HOME"});
  ::setenv("SHADERGEN_CACHE_DIR", "/tmp/explicit-cache", 1);
  EXPECT_EQ(default_cache_directory(), fs::path("/tmp/explicit-cache"));
  ::unsetenv("SHADERGEN_CACHE_DIR");
  ::setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(default_cache_directory(), fs::path("/tmp/xdg/shadergen"));
  ::unsetenv("XDG_CACHE_HOME");
  ::setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(default_cache_directory(), fs::path("/home/someone/.cache/shadergen"));
}

Result<BuildSummary> build_toy(const fs::path& out, const fs::path& cache, bool use_cache) {
  BuildOptions options = sgtest::build_options(sgtest::toy_spec(), out, cache);
  options.use_cache = use_cache;
  return build(options);
}

TEST(CacheIntegrity, RebuildOverACorruptedCacheEqualsAColdBuild) {
  sgtest::TempDir corrupt_dir("corrupt");
  const fs::path& dir = corrupt_dir.path();
  ASSERT_TRUE(build_toy(dir / "cold", dir / "unused", false).ok());
  ASSERT_TRUE(build_toy(dir / "first", dir / "cache", true).ok());

  std::vector<fs::path> entries;
  for (const auto& e : fs::recursive_directory_iterator(dir / "cache"))
    if (e.is_regular_file()) entries.push_back(e.path());
  std::sort(entries.begin(), entries.end());
  ASSERT_GE(entries.size(), 4u);
  // Truncate one, flip a byte in another, put a foreign (valid, other key) entry in a third,
  // and a valid entry of a different blob under a fourth's name.
  std::string bytes = sgtest::read_file(entries[0]);
  sgtest::write_file(entries[0], bytes.substr(0, bytes.size() / 2));
  bytes = sgtest::read_file(entries[1]);
  bytes[bytes.size() - 3] = static_cast<char>(bytes[bytes.size() - 3] ^ 0x40);
  sgtest::write_file(entries[1], bytes);
  sgtest::write_file(entries[2], encode_cache_entry(kOtherKey, sample_blob()));
  sgtest::write_file(entries[3], sgtest::read_file(entries[4]));

  auto summary = build_toy(dir / "warm", dir / "cache", true);
  ASSERT_TRUE(summary.ok());
  EXPECT_EQ(summary->compiled, 4u) << "the four damaged entries are recompiled";
  EXPECT_EQ(sgtest::snapshot(dir / "warm"), sgtest::snapshot(dir / "cold"));

  // The damaged entries were replaced: the next build is all hits.
  auto again = build_toy(dir / "again", dir / "cache", true);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->compiled, 0u);
}

TEST(CacheIntegrity, UnwritableCacheOnlyCostsTime) {
  sgtest::TempDir readonly_dir("readonly");
  const fs::path& dir = readonly_dir.path();
  sgtest::write_file(dir / "cache", "a file where the cache folder should be");
  auto summary = build_toy(dir / "out", dir / "cache", true);
  ASSERT_TRUE(summary.ok()) << summary.errors().front().to_string();
  EXPECT_TRUE(fs::exists(dir / "out" / "manifest.json"));
}

}  // namespace
}  // namespace shadergen
