#pragma once
// The sweep's bar charts, one per comparison.

#include "measurement.h"
#include "sweep_plan.h"

#include "plot/bar_chart.h"

#include <vector>

namespace tilelight::sweep {

// Design choices: one group per configuration (labelled with its speed-up), one bar per light
// stage plus the classified total and the naive pass. Resolution: classified total vs naive
// per size. Stages: the Table 4.2 tasks, naive vs classification.
plot::BarChart comparison_chart(const Comparison& comparison, const std::vector<const Measurement*>& rows);

}  // namespace tilelight::sweep
