#include "tilelight_app/process_stats.h"

#include <sys/resource.h>

namespace tilelight::app {

double peak_rss_mib() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

}  // namespace tilelight::app
