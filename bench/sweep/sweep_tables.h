#pragma once
// The sweep's markdown tables (printed on stdout, pasted into docs/results.md).

#include "measurement.h"
#include "sweep_plan.h"

#include <string>
#include <string_view>
#include <vector>

namespace tilelight::sweep {

// One row per configuration: tiles, rectangles drawn, each light stage, the classified total,
// naive light, the speed-up and the pixel-difference count; milliseconds, medians. For
// Facet::stages, the chapter's Table 4.2 layout instead (tasks down, naive | classification
// across), with the stages both frames share under it. For Facet::baselines with Baselines::all,
// light path and whole frame against naive, dynamic and floor with the per-frame ratios, and the
// G-buffer-read limit at `device_name`'s memory bandwidth (gbuffer_bound.h; "unknown" if none).
std::string markdown_table(const Comparison& comparison, const std::vector<const Measurement*>& rows,
                           std::string_view device_name = {});

}  // namespace tilelight::sweep
