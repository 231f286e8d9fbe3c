// shard_check.h - the shard records (cache/shard_record.h) from the driver's side: a shard
// stores its record once every source of its slice is on the server; a merge that knows how
// many shards there were reads them all before it fetches any entry, and fails up front,
// naming the shards, when one never finished or ran another shadergen.
#pragma once

#include <cstdint>
#include <string>

#include "cache/remote_cache.h"
#include "shadergen/diagnostic.h"

namespace shadergen {

// Preconditions: `remote` may be written; index < count.
Status record_shard(RemoteCache& remote, const std::string& build_key, std::uint32_t index, std::uint32_t count);

// Every record of shards 0..shards-1 of this build. `repair` is the command that reruns a shard,
// with "I/N" where the shard goes ("shadergen build SPEC --shard I/N --remote-cache URL").
// Precondition: shards >= 1.
Status check_shard_records(RemoteCache& remote, const std::string& build_key, std::uint32_t shards, unsigned jobs,
                           const std::string& repair);

}  // namespace shadergen
