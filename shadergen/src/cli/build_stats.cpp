#include "cli/build_stats.h"

#include <cstdio>

namespace shadergen {

std::string format_build_stats(const BuildSummary& s) {
  std::string out = "shadergen: permutations: " + std::to_string(s.permutations) + " (" + std::to_string(s.recompiled) +
                    " recompiled, " + std::to_string(s.reused) + " reused); inputs " +
                    (s.inputs_reused ? "unchanged, preprocessing skipped" : "preprocessed") +
                    "\nshadergen: phases (ms):";
  if (s.sharded)
    out = "shadergen: shard " + std::to_string(s.shard_index) + "/" + std::to_string(s.shard_count) + ": " +
          std::to_string(s.shard_sources) + " sources owned, " + std::to_string(s.shard_uploaded) + " uploaded, " +
          std::to_string(s.shard_on_server) + " already on the server\n" + out;
  for (std::size_t i = 0; i < s.phases.size(); ++i) {
    char ms[32];
    std::snprintf(ms, sizeof ms, " %.1f", s.phases[i].ms);
    out += (i ? ", " : " ") + s.phases[i].name + ms;
  }
  return out + "\n";
}

}  // namespace shadergen
