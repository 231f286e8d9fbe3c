#include "tilelight/app/frame_ratios.h"

#include <median/median.h>

#include <algorithm>

namespace tilelight::app {
namespace {

// baseline / classified per frame, over the frames where both are above 0.
std::optional<RatioStats> summarise(const std::vector<FrameTimings>& frames, double FrameTimings::*baseline,
                                    double (*classified)(const FrameTimings&)) {
  std::vector<double> ratios;
  for (const FrameTimings& f : frames) {
    const double c = classified(f);
    if (f.*baseline > 0 && c > 0) ratios.push_back(f.*baseline / c);
  }
  if (ratios.empty()) return std::nullopt;
  const auto [low, high] = std::minmax_element(ratios.begin(), ratios.end());
  return RatioStats{median::of(ratios), *low, *high};
}

double classified_frame_ms(const FrameTimings& t) { return t.frame_classified; }

}  // namespace

double classified_light_ms(const FrameTimings& t) {
  return t.classification + t.index_build_cpu + t.index_build_gpu + t.tiled_light;
}

FrameRatios frame_ratios(const std::vector<FrameTimings>& frames) {
  FrameRatios r;
  r.whole_frame_vs_dynamic = summarise(frames, &FrameTimings::frame_dynamic, classified_frame_ms);
  r.whole_frame_vs_naive = summarise(frames, &FrameTimings::frame_naive, classified_frame_ms);
  r.light_vs_dynamic = summarise(frames, &FrameTimings::dynamic_light, classified_light_ms);
  r.light_vs_naive = summarise(frames, &FrameTimings::naive_light, classified_light_ms);
  return r;
}

}  // namespace tilelight::app
