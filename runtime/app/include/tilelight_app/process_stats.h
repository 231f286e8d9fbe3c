#pragma once
// Figures about the tilelight process itself, for the report (the soak test reads them).

namespace tilelight::app {

// The largest resident set size the process has had so far, in MiB (getrusage ru_maxrss).
// Never decreases; 0 if the system does not say.
double peak_rss_mib();

}  // namespace tilelight::app
