// remote_stats.h - what the remote cache did in one build: its counters, as RemoteCache::stats()
// reports them and shadergen::BuildSummary carries them.
#pragma once

#include <cstdint>

namespace shadergen {

struct RemoteCacheStats {
  std::uint32_t fetched = 0;   // verified entries taken from the server
  std::uint32_t missed = 0;    // GETs answered 404
  std::uint32_t uploaded = 0;  // PUTs answered 2xx
  std::uint32_t failed = 0;    // requests without a usable answer, and rejected entries
};

}  // namespace shadergen
