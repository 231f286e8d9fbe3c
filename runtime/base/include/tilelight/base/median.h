#pragma once
// The median every timing table of the runtime and its benchmarks reports: robust against the
// odd slow frame or run that a mean would smear into the figure.

#include <vector>

namespace tilelight {

// The middle value of `values`; the mean of the two middle ones for an even count; 0 for none.
double median(std::vector<double> values);

}  // namespace tilelight
