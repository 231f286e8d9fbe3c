// shadergen/build_options.h - what `shadergen build` is asked to do: the options of one build,
// the part it plays in a sharded build, and the rules between them. The CLI binds its options
// straight into a BuildOptions; the library validates it again for callers that skip the CLI.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "cache/remote_defaults.h"
#include "shadergen/diagnostic.h"

namespace shadergen {

// `--shard I/N`: part I (0-based) of N of a domain's distinct sources.
struct Shard {
  std::uint32_t index = 0;
  std::uint32_t count = 1;
};
inline constexpr std::uint32_t kMaxShards = 4096;

// The part a build plays (docs/distributed.md). A value is always a valid role: the factories
// enforce 0 <= I < N <= kMaxShards and at most kMaxShards for a merge, and say why not.
//   - whole: the whole domain into out_dir (the default).
//   - shard I/N: compile only this shard's distinct sources (after pruning, collapse and
//     dedup) and make sure each is on the remote cache; nothing is written under out_dir (which
//     may be empty). The build fails, naming how many, unless every source of the shard is on
//     the server. Needs a remote cache that is not read-only.
//   - merge (`--require-remote-hits`): compile nothing, and take every distinct source from the
//     server alone, checked as remote entries are (key, checksum, signature), never from the
//     local cache, which it neither reads nor writes. It uploads nothing (no HEAD, PUT or MKCOL),
//     whatever remote_cache_read_only says. A source missing from the server, or failing the
//     checks, fails the build, counted by kind ("2 sources missing, 1 corrupt"), per shard with
//     the command that reruns it when the shards are known, and nothing is written. With the
//     shards known, every shard's record (cache/shard_record.h) is checked first: a shard that
//     has not finished or ran another shadergen fails the merge before any entry is fetched.
//     Needs a remote cache.
class BuildRole {
 public:
  enum class Kind { whole, shard, merge };

  BuildRole() = default;  // whole
  static Result<BuildRole> shard(std::uint32_t index, std::uint32_t count);
  // "I/N" as `--shard` takes it; the error quotes `text`.
  static Result<BuildRole> shard(std::string_view text);
  // `shards`: how many shards filled the cache, for the record check and the per-shard counts;
  // 0: unknown.
  static Result<BuildRole> merge(std::uint32_t shards = 0);

  Kind kind() const { return kind_; }
  bool is_whole() const { return kind_ == Kind::whole; }
  bool is_shard() const { return kind_ == Kind::shard; }
  bool is_merge() const { return kind_ == Kind::merge; }
  // A shard or a merge: it lives on the network (no budget, retries).
  bool networked() const { return kind_ != Kind::whole; }
  // Precondition: is_shard().
  const Shard& place() const { return place_; }
  // A merge's shard count (0: unknown); 0 for the other roles.
  std::uint32_t shards() const { return shards_; }

 private:
  Kind kind_ = Kind::whole;
  Shard place_;
  std::uint32_t shards_ = 0;
};

struct BuildOptions {
  std::filesystem::path spec_path;
  std::filesystem::path out_dir;
  // `--variants`: the raw combinations to build, one per line; replaces the spec's
  // "variants_file". Empty: the spec's, or every raw ID (docs/spec-format.md).
  std::filesystem::path variants;
  unsigned jobs = 0;                // 0 = one per hardware thread
  bool use_cache = true;            // false: compile everything (a cold build)
  std::filesystem::path cache_dir;  // empty: default_cache_directory()
  std::filesystem::path depfile;    // empty: none. Make syntax, target = the generated header
  std::string cpp_name;             // base name of the generated .h/.cpp; empty: the domain name
  std::string cpp_namespace;        // C++ namespace of the generated code; empty: the domain name
  // `--define` arguments, "NAME=VALUE" or "NAME" (= 1): they add to and replace the spec's
  // top-level "defines", so they reach every shader of the domain. They change the outputs
  // only through the preprocessed text, which is what the content cache is keyed on.
  std::vector<std::string> defines;
  // `--target-env`: "vulkan1.0" ... "vulkan1.3"; empty: the spec's "target_env" (default vulkan1.2).
  std::string target_env;
  // `--strip-debug`: as the spec's "strip_debug": true (either one strips). The blobs lose
  // OpName, OpMemberName, OpSource, OpString, OpLine and OpModuleProcessed; the manifest and
  // the registry keep the names (reflection runs first). The cache keeps unstripped blobs.
  bool strip_debug = false;
  bool write_stats = false;  // also write <out>/stats.json (timings: not deterministic)
  bool verbose = false;      // one progress line per compiled source
  // A content cache shared over HTTP: GET/PUT <url>/<key[0:2]>/<key>, asked after a local miss,
  // given every entry compiled here unless read-only. Empty: none; unused without use_cache,
  // except by a shard or a merge, which then skip only the local cache.
  // Precondition: empty or an http:// or https:// URL (else build() fails naming it).
  // Credentials in it ("user:password@") are never printed; ~/.netrc can hold them instead.
  std::string remote_cache_url;
  bool remote_cache_read_only = false;
  // Not empty: every upload is signed with HMAC-SHA256 under this secret, and only entries so
  // signed are used (docs/cli.md, "trust model"). Never printed.
  std::string remote_cache_secret;
  // The waiting time the remote cache's requests may cost this build together; once spent, the
  // rest of the build does not use it. Each request also waits at most remote_cache_request_limit.
  std::chrono::milliseconds remote_cache_budget = kDefaultRemoteCacheBudget;
  std::chrono::milliseconds remote_cache_request_limit = kDefaultRemoteCacheRequestLimit;
  // The part this build plays (BuildRole): the whole domain (the default), a shard, or the
  // merge of the shards. validate() checks it against the remote-cache options.
  BuildRole role;
  // Receives progress lines (the CLI prints them on stderr). May be empty.
  std::function<void(const std::string&)> log;
  // Polled between jobs; when it returns true the build stops and fails, output untouched.
  std::function<bool()> cancelled;
};

// The rules between the options that need no file: the role against the remote cache (a shard
// needs one it may write, a merge one it may read), an output folder unless a shard, a remote
// cache URL it can use. The CLI turns a failure into exit 2; build() checks it first.
Status validate(const BuildOptions& options);

}  // namespace shadergen
