// Sharded builds (`build --shard I/N`, then the merge `--require-remote-hits`) against Debian's
// nginx, started by each test on 127.0.0.1: every shard stands in for one machine with its own
// local cache; the merge runs on a machine of its own and must write the bytes of a plain local
// build, or nothing at all when a shard's sources are missing. The partition itself is checked
// on its own, and the CLI's usage errors by their exit code.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include <testsupport/local_port.h>
#include <testsupport/nginx_server.h>
#include "cache/cache.h"
#include "compile/entry_check.h"
#include "compile/glsl_compiler.h"
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
    o.role = *BuildRole::shard(index, count);
    o.out_dir.clear();
    o.remote_cache_secret = secret;
    o.use_cache = local_cache;
  });
}

ShardRun merge(const fs::path& dir, const std::string& url, std::uint32_t shards, const std::string& secret = {},
               bool local_cache = true) {
  return run(dir, "merge", url, [&](BuildOptions& o) {
    o.role = *BuildRole::merge(shards);
    o.remote_cache_secret = secret;
    o.use_cache = local_cache;
  });
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// The content entries on the server (<key[0:2]>/<key>), without the shards' records (shards/)
// and the input sets and their parts (inputs/).
std::vector<fs::path> entries_on(const NginxServer& server) {
  std::vector<fs::path> entries;
  for (const fs::path& file : sgtest::files_under(server.data_dir()))
    if (file.parent_path().filename() != "shards" && file.parent_path().filename() != "inputs") entries.push_back(file);
  return entries;
}

// The input-set parts on the server (inputs/), signed shards only.
std::vector<fs::path> input_sets_on(const NginxServer& server) {
  const fs::path folder = server.data_dir() / "inputs";
  return fs::exists(folder) ? sgtest::files_under(folder) : std::vector<fs::path>{};
}

// The access log once nginx has written it: it logs a request after sending the answer, so a
// build can return before the line of its last request is there. Settled when unchanged for
// 100 ms.
std::string settled_log(const NginxServer& server) {
  std::string log = sgtest::read_file(server.access_log());
  for (int quiet = 0; quiet < 5;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::string now = sgtest::read_file(server.access_log());
    quiet = now == log ? quiet + 1 : 0;
    log = std::move(now);
  }
  return log;
}

// The requests that change the server (PUT, MKCOL) or ask before one (HEAD), so far.
std::size_t writes_to(const NginxServer& server) {
  const std::string log = settled_log(server);
  return sgtest::count_of(log, "\"PUT ") + sgtest::count_of(log, "\"MKCOL ") + sgtest::count_of(log, "\"HEAD ");
}

// An earlier output of the merge, which a failed merge must leave as it is; its snapshot.
auto earlier_merge_output(const fs::path& dir) {
  fs::create_directories(dir / "merge.out");
  std::ofstream(dir / "merge.out" / "earlier.txt") << "earlier";
  return sgtest::snapshot(dir / "merge.out");
}

// "shard 2/3" out of the merge's line for the one shard that lacks something; empty if not one.
std::string the_named_shard(const std::vector<std::string>& errors) {
  std::string named;
  for (const std::string& error : errors)
    if (error.rfind("error: shard ", 0) == 0) {
      if (!named.empty()) return {};
      named = error.substr(13, error.find(':', 13) - 13);
    }
  return named;
}

// A toy domain on the server from 3 shards, each with its own warm local cache, and the merge's
// machine with a warm local cache of its own (a one-machine build there first): before the
// merge read the server alone, that cache answered for whatever the server lacked.
void three_shards_and_a_warm_merge_machine(const fs::path& dir, const NginxServer& server) {
  for (std::uint32_t i = 0; i < 3; ++i) ASSERT_TRUE(shard(dir, server.url(), i, 3).summary);
  ASSERT_TRUE(run(dir, "merge", "", [](BuildOptions&) {}).summary);
  ASSERT_EQ(entries_on(server).size(), kToySources);
}

#define START_SERVER(server, ...)  \
  NginxServer server(__VA_ARGS__); \
  ASSERT_TRUE(server.running()) << server.error()

TEST(ShardPartition, DisjointCoveringAndBalanced) {
  for (std::size_t jobs : {0u, 1u, 2u, 7u, 13u, 100u, 4097u})
    for (std::uint32_t count : {1u, 2u, 3u, 8u, 13u, 64u, 4096u}) {
      std::size_t next = 0, smallest = jobs, largest = 0;
      for (std::uint32_t i = 0; i < count; ++i) {
        JobRange r = shard_range(jobs, i, count);
        ASSERT_EQ(r.first, next) << jobs << " jobs, shard " << i << "/" << count;
        ASSERT_LE(r.first, r.last);
        for (std::size_t j = r.first; j < r.last; ++j) ASSERT_EQ(shard_of(j, jobs, count), i);
        smallest = std::min(smallest, r.size()), largest = std::max(largest, r.size());
        next = r.last;
      }
      EXPECT_EQ(next, jobs) << "the shards cover every job";
      EXPECT_LE(largest - smallest, 1u) << jobs << " jobs in " << count << " shards";
    }
}

TEST(ShardedBuild, ShardsThenMergeWriteTheBytesOfALocalBuild) {
  sgtest::TempDir run_dir("shards");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  std::uint32_t jobs = 0;
  for (std::uint32_t i = 0; i < 3; ++i) {
    ShardRun s = shard(dir, server.url(), i, 3);
    ASSERT_TRUE(s.summary) << joined(s.errors);
    EXPECT_TRUE(s.summary->sharded);
    EXPECT_EQ(s.summary->shard_index, i);
    // Each shard preprocessed and compiled its third of the jobs only (shard_partition.h).
    EXPECT_EQ(s.summary->permutations, shard_range(s.summary->domain_permutations, i, 3).size());
    EXPECT_EQ(s.summary->shard_sources, s.summary->unique_sources);
    EXPECT_LT(s.summary->shard_sources, kToySources);
    EXPECT_EQ(s.summary->shard_uploaded + s.summary->shard_on_server, s.summary->shard_sources);
    jobs += s.summary->permutations;
    EXPECT_FALSE(fs::exists(dir / ("shard" + std::to_string(i) + ".out"))) << "a shard writes no output";
  }
  EXPECT_EQ(jobs, 17u) << "the toy domain's 12 unpruned raw, 4 optimised and 1 companion jobs, each in one shard";
  EXPECT_EQ(entries_on(server).size(), kToySources);
  EXPECT_EQ(sgtest::files_under(server.data_dir() / "shards").size(), 3u) << "one record per shard";
  EXPECT_TRUE(input_sets_on(server).empty()) << "no input set is shared without a secret";

  ShardRun merged = merge(dir, server.url(), 3);
  ASSERT_TRUE(merged.summary) << joined(merged.errors);
  EXPECT_FALSE(merged.summary->inputs_reused) << "without a secret the merge preprocesses the domain itself";
  EXPECT_EQ(merged.summary->compiled, 0u);
  EXPECT_EQ(merged.summary->remote->fetched, kToySources);
  EXPECT_TRUE(merged.warnings.empty()) << joined(merged.warnings);
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));

  // A shard run again elsewhere finds its sources on the server and uploads nothing.
  ShardRun again =
      run(dir, "again", server.url(), [](BuildOptions& o) { o.role = *BuildRole::shard(1, 3), o.out_dir.clear(); });
  ASSERT_TRUE(again.summary) << joined(again.errors);
  EXPECT_EQ(again.summary->shard_uploaded, 0u);
  EXPECT_EQ(again.summary->shard_on_server, again.summary->shard_sources);
}

TEST(ShardedBuild, MergeRefusesAShardThatDidNotFinishBeforeFetchingAnything) {
  sgtest::TempDir run_dir("missing");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  for (std::uint32_t i : {0u, 2u}) ASSERT_TRUE(shard(dir, server.url(), i, 3).summary);
  const auto before = earlier_merge_output(dir);  // must stay as it is
  const std::size_t gets_before = sgtest::count_of(settled_log(server), "\"GET ");

  ShardRun merged = merge(dir, server.url(), 3);
  ASSERT_FALSE(merged.summary);
  ASSERT_EQ(merged.errors.size(), 2u) << joined(merged.errors);
  EXPECT_EQ(merged.errors[0], "error: 1 of 3 shards are not ready on the remote cache " + server.url() +
                                  "; the merge fetched no entry and wrote nothing");
  EXPECT_EQ(merged.errors[1],
            "error: shard 1/3: no record of it on the server: it has not finished, or ran with "
            "another spec, working folder or build options; rerun it: shadergen build " +
                sgtest::toy_spec().string() + " --shard 1/3 --remote-cache " + server.url() +
                " (with the shards' other options)");
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), before);
  EXPECT_EQ(sgtest::count_of(settled_log(server), "\"GET "), gets_before + 3) << "the three records, and no entry";

  // Without --shards the merge cannot name the shard, but still counts what the server lacks.
  ShardRun unnamed = merge(dir, server.url(), 0);
  ASSERT_FALSE(unnamed.summary);
  const std::size_t n = kToySources - entries_on(server).size();
  ASSERT_GT(n, 0u);
  ASSERT_EQ(unnamed.errors.size(), 2u) << joined(unnamed.errors);
  EXPECT_EQ(unnamed.errors[0], "error: " + std::to_string(n) + " of 13 distinct sources are not on the remote cache " +
                                   server.url() + " (" + std::to_string(n) +
                                   " sources missing); --require-remote-hits compiles nothing, so nothing was written");
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), before);

  // Without --require-remote-hits the merge compiles what is missing, as any build does.
  ShardRun completed = run(dir, "merge", server.url(), [](BuildOptions&) {});
  ASSERT_TRUE(completed.summary) << joined(completed.errors);
  EXPECT_EQ(completed.summary->compiled, n);
}

// The merge proves the server holds everything: a warm local cache on its machine stands in for
// nothing, it uploads nothing, and it names the shard whose rerun repairs the server.
TEST(ShardedBuild, MergeWithAWarmLocalCacheRefusesAServerMissingAnEntry) {
  sgtest::TempDir run_dir("warm_missing");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  three_shards_and_a_warm_merge_machine(dir, server);
  fs::remove(entries_on(server).front());
  const auto merge_cache = sgtest::snapshot(dir / "merge.cache");
  const std::size_t writes = writes_to(server);

  ShardRun merged = merge(dir, server.url(), 3);
  ASSERT_FALSE(merged.summary) << "the local cache must not answer for the server";
  EXPECT_EQ(merged.errors.front(), "error: 1 of 13 distinct sources are not on the remote cache " + server.url() +
                                       " (1 source missing); --require-remote-hits compiles nothing, so nothing "
                                       "was written");
  const std::string named = the_named_shard(merged.errors);
  ASSERT_FALSE(named.empty()) << joined(merged.errors);
  EXPECT_NE(joined(merged.errors).find("error: shard " + named + ": 1 source missing; rerun it: shadergen build "),
            std::string::npos)
      << joined(merged.errors);
  EXPECT_EQ(writes_to(server), writes) << "the merge made no upload";
  EXPECT_EQ(sgtest::snapshot(dir / "merge.cache"), merge_cache) << "nor wrote its local cache";

  // Rerunning the named shard, on its machine, puts the entry back; the merge then passes.
  const std::uint32_t index = static_cast<std::uint32_t>(std::stoul(named));
  ShardRun repaired = shard(dir, server.url(), index, 3);
  ASSERT_TRUE(repaired.summary) << joined(repaired.errors);
  EXPECT_EQ(repaired.summary->shard_uploaded, 1u);
  ShardRun again = merge(dir, server.url(), 3);
  ASSERT_TRUE(again.summary) << joined(again.errors);
  EXPECT_EQ(again.summary->remote->fetched, kToySources);
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));
}

TEST(ShardedBuild, MergeWithAWarmLocalCacheRefusesACorruptEntryAndTheShardReplacesIt) {
  sgtest::TempDir run_dir("warm_corrupt");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  three_shards_and_a_warm_merge_machine(dir, server);
  // One flipped byte in the middle of an entry: its checksum no longer holds.
  const fs::path victim = entries_on(server).front();
  std::string bytes = sgtest::read_file(victim);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x20);
  sgtest::write_file(victim, bytes);
  const std::size_t writes = writes_to(server);

  ShardRun merged = merge(dir, server.url(), 3);
  ASSERT_FALSE(merged.summary);
  EXPECT_EQ(merged.errors.front(), "error: 1 of 13 distinct sources are not on the remote cache " + server.url() +
                                       " (1 source corrupt); --require-remote-hits compiles nothing, so nothing "
                                       "was written");
  const std::string named = the_named_shard(merged.errors);
  ASSERT_FALSE(named.empty()) << joined(merged.errors);
  EXPECT_NE(joined(merged.errors).find("error: shard " + named + ": 1 source corrupt; rerun it: "), std::string::npos);
  EXPECT_EQ(writes_to(server), writes) << "the merge made no upload";
  ASSERT_EQ(merged.warnings.size(), 1u) << joined(merged.warnings);
  EXPECT_NE(merged.warnings[0].find("the merge counts it corrupt"), std::string::npos) << merged.warnings[0];
  EXPECT_EQ(merged.warnings[0].find("compiled here instead"), std::string::npos) << merged.warnings[0];

  // The shard holds the entry locally, but reads the server's copy, finds it corrupt and puts
  // its own in its place (it used to trust a HEAD 200, so the merge failed for ever).
  ShardRun repaired = shard(dir, server.url(), static_cast<std::uint32_t>(std::stoul(named)), 3);
  ASSERT_TRUE(repaired.summary) << joined(repaired.errors);
  EXPECT_EQ(repaired.summary->shard_replaced, 1u);
  EXPECT_EQ(repaired.summary->shard_uploaded, 1u);
  ShardRun again = merge(dir, server.url(), 3);
  ASSERT_TRUE(again.summary) << joined(again.errors);
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));
}

// Every machine must run the same shadergen: a shard that ran another version is named before
// the merge fetches an entry, where it used to show as every one of its sources missing.
TEST(ShardedBuild, MergeRefusesAShardOfAnotherShadergenUpFront) {
  sgtest::TempDir run_dir("versions");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  for (std::uint32_t i = 0; i < 3; ++i) ASSERT_TRUE(shard(dir, server.url(), i, 3).summary);
  fs::path record;
  for (const fs::path& file : sgtest::files_under(server.data_dir() / "shards"))
    if (file.filename().string().ends_with("-2-of-3")) record = file;
  ASSERT_FALSE(record.empty());
  std::string text = sgtest::read_file(record);
  const std::size_t tool = text.find("\ntool ");
  ASSERT_NE(tool, std::string::npos) << text;
  text.replace(tool + 6, text.find('\n', tool + 1) - tool - 6, "0.0.1");
  sgtest::write_file(record, text);

  ShardRun merged = merge(dir, server.url(), 3);
  ASSERT_FALSE(merged.summary);
  ASSERT_EQ(merged.errors.size(), 2u) << joined(merged.errors);
  EXPECT_EQ(merged.errors[1].rfind("error: shard 2/3: it ran shadergen 0.0.1 (glslang ", 0), 0u) << merged.errors[1];
  EXPECT_NE(merged.errors[1].find("(the shadergen version differs), so their cache keys differ: every machine must "
                                  "run the same shadergen; rerun it: shadergen build "),
            std::string::npos)
      << merged.errors[1];
}

// A merge takes its blobs from the server alone, so an error of the domain's checks (here a
// foreign shader whose layout conflicts with the rest) is reported as itself: it used to be
// retried without the server and reported as every source missing.
TEST(ShardedBuild, MergeKeepsALayoutErrorOfTheServersEntries) {
  sgtest::TempDir run_dir("layout");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  for (std::uint32_t i = 0; i < 3; ++i) ASSERT_TRUE(shard(dir, server.url(), i, 3).summary);
  // A valid fragment shader binding a texture where the toy domain has its uniform block.
  sgtest::write_file(dir / "foreign.frag",
                     "#version 450\nlayout(set = 0, binding = 0) uniform sampler2D stolen;\n"
                     "layout(location = 0) in vec2 in_uv;\nlayout(location = 0) out vec4 out_color;\n"
                     "void main() { out_color = texture(stolen, in_uv); }\n");
  auto foreign = compile(GlslSource{dir / "foreign.frag", Stage::fragment, {}, {}, {}, TargetEnv::vulkan1_2});
  ASSERT_TRUE(foreign.ok());
  bool replaced = false;
  for (const fs::path& entry : entries_on(server)) {
    const std::string key = entry.filename().string();
    auto blob = decode_cache_entry(key, sgtest::read_file(entry));
    ASSERT_TRUE(blob) << entry;
    if (wrong_stage_reason(blob->words, Stage::fragment).empty()) {
      sgtest::write_file(entry, encode_cache_entry(key, CachedBlob{*foreign, false, {}}));
      replaced = true;
      break;
    }
  }
  ASSERT_TRUE(replaced);

  ShardRun merged = merge(dir, server.url(), 3);
  ASSERT_FALSE(merged.summary);
  EXPECT_EQ(joined(merged.errors).find("not on the remote cache"), std::string::npos) << joined(merged.errors);
  EXPECT_NE(joined(merged.errors).find("set 0"), std::string::npos) << joined(merged.errors);
  EXPECT_EQ(joined(merged.warnings).find("compiled here instead"), std::string::npos) << joined(merged.warnings);
}

TEST(ShardedBuild, SignedShardsAndMerge) {
  sgtest::TempDir run_dir("signed");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  for (std::uint32_t i = 0; i < 2; ++i) ASSERT_TRUE(shard(dir, server.url(), i, 2, "farm secret").summary);
  ShardRun wrong = merge(dir, server.url(), 2, "another secret");
  ASSERT_FALSE(wrong.summary) << "entries signed with another secret are not there for this merge";
  EXPECT_NE(joined(wrong.errors).find("shard 1/2: its record is not signed with this merge's secret"),
            std::string::npos)
      << joined(wrong.errors);
  ShardRun unnamed = merge(dir, server.url(), 0, "another secret");
  ASSERT_FALSE(unnamed.summary);
  EXPECT_NE(unnamed.errors.front().find("13 of 13 distinct sources are not on the remote cache " + server.url() +
                                        " (13 sources corrupt)"),
            std::string::npos)
      << unnamed.errors.front();
  ShardRun merged = merge(dir, server.url(), 2, "farm secret");
  ASSERT_TRUE(merged.summary) << joined(merged.errors);
  EXPECT_EQ(merged.summary->compiled, 0u);
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));
}

// A farm's fresh nodes run with --no-cache. With a secret each shard preprocesses its own jobs
// and uploads its part of the input set; the merge joins the parts and preprocesses nothing.
TEST(ShardedBuild, SignedShardsUploadTheirPartsAndTheMergeJoinsThem) {
  sgtest::TempDir run_dir("no_local_cache");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  for (std::uint32_t i = 0; i < 2; ++i) {
    ShardRun s = shard(dir, server.url(), i, 2, "farm secret", /*local_cache=*/false);
    ASSERT_TRUE(s.summary) << joined(s.errors);
    EXPECT_FALSE(s.summary->inputs_reused) << "shard " << i << " preprocesses its own jobs";
    EXPECT_EQ(input_sets_on(server).size(), i + 1) << "shard " << i << " uploaded its part";
  }
  ShardRun merged = merge(dir, server.url(), 2, "farm secret", /*local_cache=*/false);
  ASSERT_TRUE(merged.summary) << joined(merged.errors);
  EXPECT_TRUE(merged.summary->inputs_reused) << "the merge joined the parts";
  EXPECT_FALSE(fs::exists(dir / "merge.cache")) << "--no-cache writes no local cache";
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));

  // A shard run again finds its part on the server and preprocesses nothing.
  ShardRun again = shard(dir, server.url(), 1, 2, "farm secret", /*local_cache=*/false);
  ASSERT_TRUE(again.summary) << joined(again.errors);
  EXPECT_TRUE(again.summary->inputs_reused);
  EXPECT_EQ(again.summary->shard_uploaded, 0u);
}

// A shard that finds a whole input set on the server (a signed build of the same spec ran
// against it) takes its jobs' keys from it, preprocessing nothing, and still uploads its part.
TEST(ShardedBuild, AShardTakingAWholeInputSetStillUploadsItsPart) {
  sgtest::TempDir run_dir("whole_set");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  const std::string secret = "farm secret";
  ShardRun whole = run(dir, "whole", server.url(), [&](BuildOptions& o) { o.remote_cache_secret = secret; });
  ASSERT_TRUE(whole.summary) << joined(whole.errors);
  ASSERT_EQ(input_sets_on(server).size(), 1u) << "the whole build's input set";
  for (std::uint32_t i = 0; i < 2; ++i) {
    ShardRun s = shard(dir, server.url(), i, 2, secret, /*local_cache=*/false);
    ASSERT_TRUE(s.summary) << joined(s.errors);
    EXPECT_TRUE(s.summary->inputs_reused) << "shard " << i;
    EXPECT_EQ(s.summary->shard_uploaded, 0u);
  }
  EXPECT_EQ(input_sets_on(server).size(), 3u) << "the whole set and the two parts";
  ShardRun merged = merge(dir, server.url(), 2, secret, /*local_cache=*/false);
  ASSERT_TRUE(merged.summary) << joined(merged.errors);
  EXPECT_TRUE(merged.summary->inputs_reused);
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));
}

// A part that is not on the server fails the merge before it fetches an entry, naming the shard
// whose rerun puts it back; a corrupt part likewise.
TEST(ShardedBuild, MergeRefusesAMissingOrCorruptPartOfTheInputSet) {
  sgtest::TempDir run_dir("parts");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  const std::string secret = "farm secret";
  ASSERT_TRUE(shard(dir, server.url(), 0, 2, secret, false).summary);
  const std::vector<fs::path> first = input_sets_on(server);
  ASSERT_EQ(first.size(), 1u);
  ASSERT_TRUE(shard(dir, server.url(), 1, 2, secret, false).summary);
  fs::path second;
  for (const fs::path& part : input_sets_on(server))
    if (part != first.front()) second = part;
  ASSERT_FALSE(second.empty());
  fs::remove(second);
  const auto before = earlier_merge_output(dir);
  const std::size_t writes = writes_to(server);
  const std::size_t gets_before = sgtest::count_of(settled_log(server), "\"GET ");

  ShardRun merged = merge(dir, server.url(), 2, secret, false);
  ASSERT_FALSE(merged.summary);
  ASSERT_EQ(merged.errors.size(), 2u) << joined(merged.errors);
  EXPECT_EQ(merged.errors[0], "error: 1 of 2 shards' parts of the input set are not on the remote cache " +
                                  server.url() + "; the merge fetched no entry and wrote nothing");
  EXPECT_EQ(merged.errors[1],
            "error: shard 1/2: its part of the input set is not on the server; rerun it: "
            "shadergen build " +
                sgtest::toy_spec().string() + " --shard 1/2 --remote-cache " + server.url() +
                " (with the shards' other options)");
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), before);
  EXPECT_EQ(writes_to(server), writes) << "the merge made no upload";
  EXPECT_EQ(sgtest::count_of(settled_log(server), "\"GET "), gets_before + 4)
      << "the two records and the two parts, and no entry";

  // One flipped byte in shard 0's part: its signature no longer holds.
  std::string bytes = sgtest::read_file(first.front());
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x20);
  sgtest::write_file(first.front(), bytes);
  ShardRun both = merge(dir, server.url(), 2, secret, false);
  ASSERT_FALSE(both.summary);
  EXPECT_NE(joined(both.errors).find("error: shard 0/2: its part of the input set fails its checks"), std::string::npos)
      << joined(both.errors);

  // Rerunning the named shards puts their parts back; the merge then passes.
  for (std::uint32_t i = 0; i < 2; ++i) ASSERT_TRUE(shard(dir, server.url(), i, 2, secret, false).summary);
  ShardRun repaired = merge(dir, server.url(), 2, secret, false);
  ASSERT_TRUE(repaired.summary) << joined(repaired.errors);
  EXPECT_TRUE(repaired.summary->inputs_reused);
  EXPECT_EQ(sgtest::snapshot(dir / "merge.out"), sgtest::reference_output(dir));
}

TEST(ShardedBuild, AShardWithoutAServerFailsNamingWhatIsMissing) {
  sgtest::TempDir run_dir("dead");
  // Nothing listens there: every attempt is refused at once, so the retries cost their pauses only.
  std::string url = "http://127.0.0.1:" + std::to_string(testsupport::unused_local_port()) + "/cache";
  ShardRun s = shard(run_dir.path(), url, 0, 2);
  ASSERT_FALSE(s.summary);
  EXPECT_NE(joined(s.errors).find("shard 0/2: 8 of its 8 distinct sources are not on the remote cache"),
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
       "shadergen: error: --shard cannot use --remote-cache-readonly: a shard uploads what it compiles\n"},
      {{"build", spec, "--shard", "2/2", "--remote-cache", url},
       "shadergen: error: --shard 2/2: expected I/N with 0 <= I < N <= 4096\n"},
      {{"build", spec, "--shard", "1/4097", "--remote-cache", url},
       "shadergen: error: --shard 1/4097: expected I/N with 0 <= I < N <= 4096\n"},
      {{"build", spec, "--shard", "x/2", "--remote-cache", url},
       "shadergen: error: --shard x/2: expected I/N with 0 <= I < N <= 4096\n"},
      {{"build", spec}, "shadergen: error: --out is required (except with --shard)\n"},
      {{"build", spec, "--out", "o", "--require-remote-hits"},
       "shadergen: error: --require-remote-hits needs --remote-cache (or SHADERGEN_REMOTE_CACHE): it takes every "
       "source from there\n"},
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
