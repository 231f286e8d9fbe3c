#pragma once
// Figures about the tilelight process itself, for the report (the soak test reads them).

namespace tilelight::app {

// The largest resident set size the process has had so far, in MiB (getrusage ru_maxrss).
// Never decreases; 0 if the system does not say.
double peak_rss_mib();

// The resident set size now, in MiB (/proc/self/statm); 0 if it cannot be read. Unlike the
// peak, it is not dominated by start-up (shader compilation), so a slow leak shows in it first.
double current_rss_mib();

}  // namespace tilelight::app
