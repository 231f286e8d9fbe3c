// shadergen/build_summary.h - no longer the summary's home: shadergen::BuildSummary is declared
// with build() in shadergen/build.h (driver), its counters by the areas that count them
// (cache/remote_stats.h), its `--stats` text in the CLI (cli/build_stats.h), and PhaseTime with
// the clock that measures it (base/phase_clock.h). This header only forwards PhaseTime for
// compile/compiled_domain.h; once that includes base/phase_clock.h, delete this one.
#pragma once

#include "base/phase_clock.h"
