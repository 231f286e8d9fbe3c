#include "driver/shard_check.h"

#include <vector>

#include "base/thread_pool.h"
#include "cache/shard_record.h"
#include "compile/toolchain.h"

namespace shadergen {
namespace {

// The messages of one kind name at most this many shards each, then say how many more.
constexpr std::size_t kNamedShards = 8;

std::string with_place(std::string repair, const std::string& place) {
  std::size_t at = repair.find("I/N");
  if (at != std::string::npos) repair.replace(at, 3, place);
  return repair;
}

}  // namespace

Status record_shard(RemoteCache& remote, const std::string& build_key, std::uint32_t index, std::uint32_t count) {
  ShardRecord record{index, count, recorded_tools(current_cache_key_parts())};
  if (remote.store_text(shard_record_path(build_key, index, count), encode_shard_record(record))) return Ok{};
  return make_error("shard " + std::to_string(index) + "/" + std::to_string(count) +
                    ": every source is on the remote cache " + remote.shown_url() +
                    ", but the shard's record (which the merge checks first) could not be stored; the warnings "
                    "above say why");
}

Status check_shard_records(RemoteCache& remote, const std::string& build_key, std::uint32_t shards, unsigned jobs,
                           const std::string& repair) {
  const CacheKeyParts mine = recorded_tools(current_cache_key_parts());
  // Per shard: empty when its record is there and made by this shadergen, else what is wrong.
  std::vector<std::string> problems(shards);
  parallel_for(shards, jobs, [&](std::size_t i) {
    const auto index = static_cast<std::uint32_t>(i);
    RemoteCache::Found found = RemoteCache::Found::no_answer;
    auto text = remote.load_text(shard_record_path(build_key, index, shards), &found);
    if (!text) {
      problems[i] = found == RemoteCache::Found::rejected ? "its record is not signed with this merge's secret"
                    : found == RemoteCache::Found::none
                        ? "no record of it on the server: it has not finished, or ran with another spec, "
                          "working folder or build options"
                        : "its record could not be fetched (the warning above says why)";
      return;
    }
    auto record = decode_shard_record(*text);
    if (!record || record->index != index || record->count != shards) {
      problems[i] = "its record on the server is not a shard record of this build (corrupt)";
      return;
    }
    if (std::string differs = tools_difference(record->tools, mine); !differs.empty())
      problems[i] = "it ran " + tools_text(record->tools) + " and this merge runs " + tools_text(mine) + " (" +
                    differs + " differs), so their cache keys differ: every machine must run the same shadergen";
  });
  Diagnostics errors;
  std::size_t failing = 0;
  for (std::uint32_t i = 0; i < shards; ++i) {
    if (problems[i].empty()) continue;
    if (++failing > kNamedShards) continue;
    const std::string place = std::to_string(i) + "/" + std::to_string(shards);
    errors.push_back(make_error("shard " + place + ": " + problems[i] + "; rerun it: " + with_place(repair, place)));
  }
  if (failing == 0) return Ok{};
  if (failing > kNamedShards)
    errors.push_back(make_error("... and " + std::to_string(failing - kNamedShards) + " more shards"));
  errors.insert(errors.begin(), make_error(std::to_string(failing) + " of " + std::to_string(shards) +
                                           " shards are not ready on the remote cache " + remote.shown_url() +
                                           "; the merge fetched no entry and wrote nothing"));
  return errors;
}

}  // namespace shadergen
