// Sharded builds (`build --shard I/N`, then the merge `--require-remote-hits`) against Debian's
// nginx, started by each test on 127.0.0.1: every shard stands in for one machine with its own
// local cache; the merge runs on a machine of its own and must write the bytes of a plain local
// build, or nothing at all when a shard's sources are missing. The partition itself is checked
// on its own, and the CLI's usage errors by their exit code.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include <testsupport/local_port.h>
#include <testsupport/nginx_server.h>
#include "compile/shard_partition.h"
#include "remote_builds.h"
#include "shadergen/build.h"
#include "shadergen/cli.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

namespace fs = std::filesystem;
using testsupport::NginxServer;

constexpr std::uint32_t kToySources = 13;  // the toy domain's distinct sources

struct ShardRun {
  std::optional<BuildSummary> summary;
  std::vector<std::string> errors;
  std::vector<std::string> warnings;
};

// One build of the toy domain as machine `name` (its own local cache), tweaked by `set`.
ShardRun run(const fs::path& dir, const std::string& name, const std::string& url,
             const std::function<void(BuildOptions&)>& set) {
  BuildOptions options = sgtest::build_options(sgtest::toy_spec(), dir / (name + ".out"), dir / (name + ".cache"));
  options.jobs = 2;
  options.remote_cache_url = url;
  ShardRun result;
  options.log = [&](const std::string& line) {
    if (line.rfind("warning: ", 0) == 0) result.warnings.push_back(line);
  };
  set(options);
  auto summary = build(options);
  if (summary)
    result.summary = *summary;
  else
    for (const Diagnostic& d : summary.errors()) result.errors.push_back(d.to_string());
  return result;
}

// `local_cache` false: as --no-cache, a farm's fresh node.
ShardRun shard(const fs::path& dir, const std::string& url, std::uint32_t index, std::uint32_t count,
               const std::string& secret = {}, bool local_cache = true) {
  return run(dir, "shard" + std::to_string(index), url, [&](BuildOptions& o) {
    o.shard = Shard{index, count};
    o.out_dir.clear();
    o.remote_cache_secret = secret;
    o.use_cache = local_cache;
  });
}

ShardRun merge(const fs::path& dir, const std::string& url, std::uint32_t shards, const std::string& secret = {},
               bool local_cache = true) {
  return run(dir, "merge", url, [&](BuildOptions& o) {
    o.require_remote_hits = true;
    o.shards = shards;
    o.remote_cache_secret = secret;
    o.use_cache = local_cache;
  });
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

#define START_SERVER(server, ...)  \
  NginxServer server(__VA_ARGS__); \
  ASSERT_TRUE(server.running()) << server.error()

TEST(ShardPartition, DisjointCoveringAndBalanced) {
  for (std::size_t sources : {0u, 1u, 2u, 7u, 13u, 100u, 4097u})
    for (std::uint32_t count : {1u, 2u, 3u, 8u, 13u, 64u, 4096u}) {
      std::size_t next = 0, smallest = sources, largest = 0;
      for (std::uint32_t i = 0; i < count; ++i) {
        SourceRange r = shard_range(sources, i, count);
        ASSERT_EQ(r.first, next) << sources << " sources, shard " << i << "/" << count;
        ASSERT_LE(r.first, r.last);
        for (std::size_t s = r.first; s < r.last; ++s) ASSERT_EQ(shard_of(s, sources, count), i);
        smallest = std::min(smallest, r.last - r.first), largest = std::max(largest, r.last - r.first);
        next = r.last;
      }
      EXPECT_EQ(next, sources) << "the shards cover every source";
      EXPECT_LE(largest - smallest, 1u) << sources << " sources in " << count << " shards";
    }
}

TEST(ShardedBuild, ShardsThenMergeWriteTheBytesOfALocalBuild) {
  sgtest::TempDir run_dir("shards");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  std::uint32_t owned = 0;
  for (std::uint32_t i = 0; i < 3; ++i) {
    ShardRun s = shard(dir, server.url(), i, 3);
    ASSERT_TRUE(s.summary) << joined(s.errors);
    EXPECT_TRUE(s.summary->sharded);
    EXPECT_EQ(s.summary->shard_index, i);
    EXPECT_EQ(s.summary->shard_uploaded, s.summary->shard_sources);
    EXPECT_EQ(s.summary->shard_on_server, 0u);
    EXPECT_EQ(s.summary->unique_sources, kToySources);
    owned += s.summary->shard_sources;
    EXPECT_FALSE(fs::exists(dir / ("shard" + std::to_string(i) + ".out"))) << "a shard writes no output";
  }
  EXPECT_EQ(owned, kToySources);
  EXPECT_EQ(sgtest::files_under(server.data_dir()).size(), kToySources);

  ShardRun merged = merge(dir, server.url(), 3);
  ASSERT_TRUE(merged.summary) << joined(merged.errors);
  EXPECT_EQ(merged.summary->compiled, 0u);
  EXPECT_EQ(merged.summary->remote->fetched, kToySources);
  EXPECT_TRUE(merged.warnings.empty()) << joined(merged.warnings);
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));

  // A shard run again elsewhere finds its sources on the server and uploads nothing.
  ShardRun again = run(dir, "again", server.url(), [](BuildOptions& o) { o.shard = Shard{1, 3}, o.out_dir.clear(); });
  ASSERT_TRUE(again.summary) << joined(again.errors);
  EXPECT_EQ(again.summary->shard_uploaded, 0u);
  EXPECT_EQ(again.summary->shard_on_server, again.summary->shard_sources);
}

TEST(ShardedBuild, MergeRefusesAMissingShardAndLeavesTheOutput) {
  sgtest::TempDir run_dir("missing");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  for (std::uint32_t i : {0u, 2u}) ASSERT_TRUE(shard(dir, server.url(), i, 3).summary);
  // An earlier output stays as it was.
  fs::create_directories(dir / "merge.out");
  std::ofstream(dir / "merge.out" / "earlier.txt") << "earlier";
  const auto before = sgtest::snapshot(dir / "merge.out");

  ShardRun merged = merge(dir, server.url(), 3);
  ASSERT_FALSE(merged.summary);
  SourceRange missing = shard_range(kToySources, 1, 3);
  const std::size_t n = missing.last - missing.first;
  ASSERT_EQ(merged.errors.size(), 2u) << joined(merged.errors);
  EXPECT_EQ(merged.errors[0], "error: " + std::to_string(n) + " of 13 distinct sources missing from the remote cache " +
                                  server.url() +
                                  " (or failing verification); --require-remote-hits compiles nothing, so nothing "
                                  "was written");
  EXPECT_EQ(merged.errors[1], "error: shard 1/3: " + std::to_string(n) + " sources missing");
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), before);

  // Without --require-remote-hits the merge compiles what is missing, as any build does.
  ShardRun completed = run(dir, "merge", server.url(), [](BuildOptions&) {});
  ASSERT_TRUE(completed.summary) << joined(completed.errors);
  EXPECT_EQ(completed.summary->compiled, n);
}

TEST(ShardedBuild, SignedShardsAndMerge) {
  sgtest::TempDir run_dir("signed");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  for (std::uint32_t i = 0; i < 2; ++i) ASSERT_TRUE(shard(dir, server.url(), i, 2, "farm secret").summary);
  ShardRun wrong = merge(dir, server.url(), 2, "another secret");
  ASSERT_FALSE(wrong.summary) << "entries signed with another secret are not there for this merge";
  EXPECT_NE(wrong.errors.front().find("13 of 13 distinct sources missing"), std::string::npos) << wrong.errors.front();
  ShardRun merged = merge(dir, server.url(), 2, "farm secret");
  ASSERT_TRUE(merged.summary) << joined(merged.errors);
  EXPECT_EQ(merged.summary->compiled, 0u);
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));
}

// A farm's fresh nodes run with --no-cache: the input set still comes from the server, so only
// the first shard preprocesses and the merge does not.
TEST(ShardedBuild, WithoutLocalCachesTheInputSetComesFromTheServer) {
  sgtest::TempDir run_dir("no_local_cache");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  for (std::uint32_t i = 0; i < 2; ++i) {
    ShardRun s = shard(dir, server.url(), i, 2, "farm secret", /*local_cache=*/false);
    ASSERT_TRUE(s.summary) << joined(s.errors);
    EXPECT_EQ(s.summary->inputs_reused, i == 1) << "shard " << i;
  }
  ShardRun merged = merge(dir, server.url(), 2, "farm secret", /*local_cache=*/false);
  ASSERT_TRUE(merged.summary) << joined(merged.errors);
  EXPECT_TRUE(merged.summary->inputs_reused);
  EXPECT_FALSE(fs::exists(dir / "merge.cache")) << "--no-cache writes no local cache";
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));
}

TEST(ShardedBuild, AShardWithoutAServerFailsNamingWhatIsMissing) {
  sgtest::TempDir run_dir("dead");
  // Nothing listens there: every attempt is refused at once, so the retries cost their pauses only.
  std::string url = "http://127.0.0.1:" + std::to_string(testsupport::unused_local_port()) + "/cache";
  ShardRun s = shard(run_dir.path(), url, 0, 2);
  ASSERT_FALSE(s.summary);
  EXPECT_NE(joined(s.errors).find("shard 0/2: 6 of its 6 distinct sources are not on the remote cache"),
            std::string::npos)
      << joined(s.errors);
  ASSERT_EQ(s.warnings.size(), 1u);
}

struct CliRun {
  int code;
  std::string err;
};

CliRun cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  int code = run_cli(args, out, err);
  return {code, err.str()};
}

TEST(ShardedBuildCli, UsageErrorsExitTwo) {
  const std::string spec = sgtest::toy_spec().string();
  const std::string url = "http://127.0.0.1:9/cache";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"build", spec, "--shard", "0/2"}, "shadergen: error: --shard needs --remote-cache"},
      {{"build", spec, "--shard", "0/2", "--remote-cache", url, "--remote-cache-readonly"},
       "shadergen: error: --shard cannot use --remote-cache-readonly: a shard uploads\n"},
      {{"build", spec, "--shard", "2/2", "--remote-cache", url},
       "shadergen: error: --shard 2/2: expected I/N with 0 <= I < N <= 4096\n"},
      {{"build", spec, "--shard", "1/4097", "--remote-cache", url},
       "shadergen: error: --shard 1/4097: expected I/N with 0 <= I < N <= 4096\n"},
      {{"build", spec, "--shard", "x/2", "--remote-cache", url},
       "shadergen: error: --shard x/2: expected I/N with 0 <= I < N <= 4096\n"},
      {{"build", spec}, "shadergen: error: --out is required (except with --shard)\n"},
      {{"build", spec, "--out", "o", "--require-remote-hits"},
       "shadergen: error: --require-remote-hits needs --remote-cache (or SHADERGEN_REMOTE_CACHE)\n"},
      {{"build", spec, "--out", "o", "--shards", "4", "--remote-cache", url},
       "shadergen: error: --shards only goes with --require-remote-hits\n"},
  };
  for (const auto& [args, message] : cases) {
    CliRun r = cli(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.rfind(message, 0), 0u) << r.err;
  }
}

}  // namespace
}  // namespace shadergen
