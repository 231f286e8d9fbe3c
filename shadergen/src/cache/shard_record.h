// shard_record.h - what a shard leaves on the remote cache beside its entries: that it finished,
// and which shadergen made them. The merge reads every shard's record before it fetches an
// entry, so a shard that never finished, or that ran another shadergen (whose cache keys the
// merge never asks for), is named up front instead of showing as "sources missing".
//
// A record lives at <url>/shards/<build key>-<I>-of-<N>, signed like every upload when a team
// shares a secret. The build key names the spec (path and bytes), the working folder and the
// settings that decide the content keys, but no tool version: the record of a shard that ran
// another version is found, and its versions are compared.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "cache/cache.h"

namespace shadergen {

struct ShardRecord {
  std::uint32_t index = 0, count = 0;
  CacheKeyParts tools;  // the shadergen that ran the shard, as recorded_tools() gives it
};

// `tools` as a record holds them: the optimiser recipe (long) by its SHA-256.
CacheKeyParts recorded_tools(CacheKeyParts tools);

// The build's key, like input_set_key() (input_cache.h) without the tools.
std::string shard_build_key(const std::filesystem::path& spec_path, std::string_view spec_digest,
                            std::string_view settings);
// Where shard `index` of `count` keeps its record, relative to the server's URL.
std::string shard_record_path(std::string_view build_key, std::uint32_t index, std::uint32_t count);

std::string encode_shard_record(const ShardRecord& record);
// nullopt when `text` is not a record (another format, truncated, garbage).
std::optional<ShardRecord> decode_shard_record(std::string_view text);

// "shadergen 0.9.0 (glslang 12.0.0, SPIRV-Tools v2022.4)": for messages.
std::string tools_text(const CacheKeyParts& tools);
// Empty when `a` and `b` make the same content keys, else which part differs ("the optimiser recipe").
std::string tools_difference(const CacheKeyParts& a, const CacheKeyParts& b);

}  // namespace shadergen
