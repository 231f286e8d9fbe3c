// The build's options as the library checks them, for callers that skip the CLI: a role is
// valid by construction (its factories refuse what --shard and --shards refuse), and validate()
// and build() refuse a role the remote-cache options cannot serve, with the CLI's own messages.
#include <gtest/gtest.h>

#include "shadergen/build.h"
#include "shadergen/build_options.h"
#include "test_helpers.h"

namespace shadergen {
namespace build_options_test {
namespace {

std::string first_error(const Status& status) { return status ? std::string() : status.errors().front().message; }

TEST(BuildRole, FactoriesRefuseWhatTheCommandLineRefuses) {
  EXPECT_TRUE(BuildRole().is_whole());
  auto shard = BuildRole::shard(3, 8);
  ASSERT_TRUE(shard);
  EXPECT_TRUE(shard->is_shard());
  EXPECT_TRUE(shard->networked());
  EXPECT_EQ(shard->place().index, 3u);
  EXPECT_EQ(shard->place().count, 8u);
  auto parsed = BuildRole::shard("4095/4096");
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->place().index, 4095u);
  for (const char* bad : {"2/2", "1/4097", "x/2", "/2", "1/", "0/0", "12345678901234567/2", "1//2"}) {
    auto role = BuildRole::shard(bad);
    ASSERT_FALSE(role) << bad;
    EXPECT_EQ(role.errors().front().message,
              "--shard " + std::string(bad) + ": expected I/N with 0 <= I < N <= " + std::to_string(kMaxShards));
  }
  EXPECT_FALSE(BuildRole::shard(5, 5));
  auto merge = BuildRole::merge(8);
  ASSERT_TRUE(merge);
  EXPECT_TRUE(merge->is_merge());
  EXPECT_EQ(merge->shards(), 8u);
  EXPECT_EQ(BuildRole::merge()->shards(), 0u) << "0: the shards are not known";
  ASSERT_FALSE(BuildRole::merge(kMaxShards + 1));
  EXPECT_EQ(BuildRole::merge(kMaxShards + 1).errors().front().message, "--shards 4097: at most 4096");
}

TEST(BuildOptionsValidate, RolesAgainstTheRemoteCache) {
  BuildOptions options;
  options.spec_path = sgtest::toy_spec();
  EXPECT_EQ(first_error(validate(options)), "--out is required (except with --shard)");
  options.out_dir = "out";
  EXPECT_TRUE(validate(options));
  options.role = *BuildRole::shard(0, 2);
  options.out_dir.clear();
  EXPECT_EQ(first_error(validate(options)).rfind("--shard needs --remote-cache", 0), 0u);
  options.remote_cache_url = "http://127.0.0.1:9/cache";
  EXPECT_TRUE(validate(options)) << "a shard needs no output folder";
  options.remote_cache_read_only = true;
  EXPECT_EQ(first_error(validate(options)),
            "--shard cannot use --remote-cache-readonly: a shard uploads what it compiles");
  options.role = *BuildRole::merge(2);
  options.out_dir = "out";
  EXPECT_TRUE(validate(options)) << "a merge uploads nothing anyway";
  options.remote_cache_url = "ftp://host/cache";
  EXPECT_EQ(
      first_error(validate(options)).rfind("--remote-cache: \"ftp://host/cache\" is not an http:// or https:// URL", 0),
      0u);
  options.remote_cache_url.clear();
  EXPECT_EQ(first_error(validate(options)).rfind("--require-remote-hits needs --remote-cache", 0), 0u);
}

TEST(BuildOptionsValidate, BuildChecksThemForCallersThatSkipTheCli) {
  sgtest::TempDir dir("validate");
  BuildOptions options = sgtest::build_options(sgtest::toy_spec(), dir.path() / "out", dir.path() / "cache");
  options.role = *BuildRole::shard(1, 4);
  auto summary = build(options);
  ASSERT_FALSE(summary);
  EXPECT_EQ(summary.errors().front().message.rfind("--shard needs --remote-cache", 0), 0u);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "cache")) << "refused before anything ran";
}

}  // namespace
}  // namespace build_options_test
}  // namespace shadergen
