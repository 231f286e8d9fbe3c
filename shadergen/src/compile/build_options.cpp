#include "shadergen/build_options.h"

#include "base/untrusted_text.h"
#include "cache/remote_cache.h"

namespace shadergen {
namespace {

std::string shard_range_error(const std::string& text) {
  return "--shard " + text + ": expected I/N with 0 <= I < N <= " + std::to_string(kMaxShards);
}

}  // namespace

Result<BuildRole> BuildRole::shard(std::uint32_t index, std::uint32_t count) {
  if (count == 0 || count > kMaxShards || index >= count)
    return make_error(shard_range_error(std::to_string(index) + "/" + std::to_string(count)));
  BuildRole role;
  role.kind_ = Kind::shard;
  role.place_ = Shard{index, count};
  return role;
}

Result<BuildRole> BuildRole::shard(std::string_view text) {
  const std::string shown = printable(std::string(text));
  std::size_t slash = text.find('/');
  if (slash == std::string_view::npos || slash == 0 || slash + 1 == text.size() || text.size() > 16)
    return make_error(shard_range_error(shown));
  std::uint64_t parts[2] = {0, 0};
  for (int p = 0; p < 2; ++p) {
    std::string_view digits = p == 0 ? text.substr(0, slash) : text.substr(slash + 1);
    for (char c : digits) {
      if (c < '0' || c > '9') return make_error(shard_range_error(shown));
      parts[p] = parts[p] * 10 + static_cast<std::uint64_t>(c - '0');
    }
  }
  if (parts[1] == 0 || parts[1] > kMaxShards || parts[0] >= parts[1]) return make_error(shard_range_error(shown));
  return shard(static_cast<std::uint32_t>(parts[0]), static_cast<std::uint32_t>(parts[1]));
}

Result<BuildRole> BuildRole::merge(std::uint32_t shards) {
  if (shards > kMaxShards)
    return make_error("--shards " + std::to_string(shards) + ": at most " + std::to_string(kMaxShards));
  BuildRole role;
  role.kind_ = Kind::merge;
  role.shards_ = shards;
  return role;
}

Status validate(const BuildOptions& options) {
  const BuildRole& role = options.role;
  if (role.is_shard()) {
    if (options.remote_cache_url.empty())
      return make_error(
          "--shard needs --remote-cache (or SHADERGEN_REMOTE_CACHE): a shard's results reach the merge only "
          "through it");
    if (options.remote_cache_read_only)
      return make_error("--shard cannot use --remote-cache-readonly: a shard uploads what it compiles");
  } else if (options.out_dir.empty()) {
    return make_error("--out is required (except with --shard)");
  }
  if (role.is_merge() && options.remote_cache_url.empty())
    return make_error(
        "--require-remote-hits needs --remote-cache (or SHADERGEN_REMOTE_CACHE): it takes every source from there");
  if (!options.remote_cache_url.empty())
    if (std::string problem = remote_cache_url_problem(options.remote_cache_url); !problem.empty())
      return make_error("--remote-cache: \"" + printable(redacted_url(options.remote_cache_url)) + "\" " + problem +
                        " (set by the option or SHADERGEN_REMOTE_CACHE)");
  return Ok{};
}

}  // namespace shadergen
