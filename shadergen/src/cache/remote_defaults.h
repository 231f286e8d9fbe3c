// remote_defaults.h - the remote cache's time limits when nobody sets them: their one
// definition. RemoteCacheSettings (remote_cache.h), shadergen::BuildOptions, and
// `build --remote-cache-budget` with its help text all take them from here.
#pragma once

#include <chrono>

namespace shadergen {

// The waiting time all requests of one build may cost together (--remote-cache-budget)...
inline constexpr std::chrono::milliseconds kDefaultRemoteCacheBudget{10000};
// ...and each one at most.
inline constexpr std::chrono::milliseconds kDefaultRemoteCacheRequestLimit{5000};

}  // namespace shadergen
