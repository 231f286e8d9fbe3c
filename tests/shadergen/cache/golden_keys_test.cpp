// The keys existing caches and servers hold: the content-cache key (cache/cache.h), the input-set
// key (cache/input_cache.h), the shard build key (cache/shard_record.h) and the checksums inside
// entries, for fixed inputs. The golden values are what f4b0d10 (the hand-written SHA-256, before
// it came from OpenSSL's libcrypto) printed, and agree with Python's hashlib on the same fields. A change here makes every existing cache miss and
// every shard record unreadable: these values may only change with a new entry format.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <system_error>

#include "cache/cache.h"
#include "cache/input_cache.h"
#include "cache/shard_record.h"

namespace golden_keys_test {
namespace {

namespace fs = std::filesystem;
using shadergen::CacheKeyParts;

CacheKeyParts fixed_tools() {
  return CacheKeyParts{"0.1.0", "12.0.0", "v2023.1", "vulkan1.2/spv1.5", "spirv-tools-performance-passes/vulkan1.2"};
}

// The input-set and shard build keys hold the working folder: each test runs them from "/".
class CacheKeyGoldenFromRoot : public ::testing::Test {
 protected:
  void SetUp() override {
    before_ = fs::current_path();
    fs::current_path("/");
  }
  void TearDown() override {
    std::error_code ec;
    fs::current_path(before_, ec);
  }

 private:
  fs::path before_;
};

TEST(CacheKeyGolden, ContentKeys) {
  EXPECT_EQ(shadergen::cache_key(fixed_tools(), "frag", "void main() {}\n"),
            "98d955b12f811539c4384bc82489a2feb0d2772a818d96c701e21dec431204ca");
  EXPECT_EQ(shadergen::cache_key(fixed_tools(), "comp", ""),
            "f6c3afbdd2d94beceebec60a99662fe1cb7d6650eafcea661b3c64edc10ad1dc");
  CacheKeyParts other = fixed_tools();
  other.target = "vulkan1.3/spv1.6";
  EXPECT_EQ(shadergen::cache_key(other, "frag", "void main() {}\n"),
            "58a8ffc7db10704e211533e16fa141f12dd4c4124aed6daa51937c3843356667");
}

// The checksum inside a content entry: the 64 hex digits before the words.
TEST(CacheKeyGolden, EntryChecksum) {
  const std::string key(64, 'c');
  const shadergen::CachedBlob blob{{0x07230203u, 0x00010500u, 7u, 0xdeadbeefu}, true, "the optimiser failed"};
  const std::string entry = shadergen::encode_cache_entry(key, blob);
  ASSERT_GT(entry.size(), 64u + 16u);
  EXPECT_EQ(entry.substr(entry.size() - 16 - 64, 64),
            "d19b51245258a892ad0b67a59cd4b33da2b3922dfa22288af34f534102dc4d96");
  EXPECT_TRUE(shadergen::decode_cache_entry(key, entry).has_value());
}

TEST_F(CacheKeyGoldenFromRoot, InputSetKey) {
  EXPECT_EQ(shadergen::input_set_key(fixed_tools(), "permutations/split_second.json", std::string(64, 'd'),
                                     "define FOO=1\nuber_shader lighting"),
            "2a076de667e8714d7d5b75c13f02f0c0641634f7bf586328cea0a16be4b0adaa");
}

TEST(InputSetGolden, EntryChecksum) {
  shadergen::InputSet set;
  set.files = {{"uber/lighting.frag", true, std::string(64, 'e')}, {"uber/include/missing.glsl", false, ""}};
  set.source_keys = {std::string(64, 'f')};
  const std::string entry = shadergen::encode_input_set(std::string(64, 'a'), set);
  const std::size_t at = entry.rfind("checksum ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(entry.substr(at), "checksum f8ec9f705edc196a7c134f00ae704fbd78ae137b3487b32d9e4cdfd77213f031\n");
  EXPECT_TRUE(shadergen::decode_input_set(std::string(64, 'a'), entry).has_value());
}

TEST_F(CacheKeyGoldenFromRoot, ShardBuildKeyAndRecordedTools) {
  EXPECT_EQ(shadergen::shard_build_key("permutations/split_second.json", std::string(64, 'd'), "define FOO=1"),
            "07d26806f965c2fa06df607e77a4b05924091b8dba293d92b81ea635c2b6dd97");
  EXPECT_EQ(shadergen::recorded_tools(fixed_tools()).optimiser_recipe,
            "2eaf9185279bd3f0ed29440b72f0fdd0597649344104f3bd50f8d6f16ba89e5c");
}

}  // namespace
}  // namespace golden_keys_test
