// build_stats.h - the lines `shadergen build --stats` prints about a build.
#pragma once

#include <string>

#include "shadergen/build.h"

namespace shadergen {

// Two lines (three for a shard: its sources first): permutations recompiled vs reused, whether
// preprocessing was skipped, and the phase timings. Ends with a newline.
std::string format_build_stats(const BuildSummary& summary);

}  // namespace shadergen
