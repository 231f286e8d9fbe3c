// median.h - the median every timing table of the runtime and the benchmarks reports (the
// tilelight report, the sweep's tables, the shadergen benchmarks): robust against the odd slow
// frame or run that a mean would smear into the figure.
#pragma once

#include <vector>

namespace median {

// The middle value of `values`; the mean of the two middle ones for an even count; 0 for none.
double of(std::vector<double> values);

}  // namespace median
