#pragma once
// Speed-ups of the classified frame over the baselines, taken frame by frame: each frame's
// baseline time divided by the same frame's classified time, then summarised. A ratio within
// one frame cancels what drifts between frames (a shared machine, a CPU governor); the ratio
// of two medians would not, and could pair a fast frame of one path with a slow one of the other.

#include "tilelight/render/tile_renderer.h"

#include <optional>
#include <vector>

namespace tilelight::app {

struct RatioStats {
  double median = 0, min = 0, max = 0;
};

// Each summary is empty where its baseline did not run (its times are 0 in every frame) or no
// frame has a classified time above 0.
struct FrameRatios {
  std::optional<RatioStats> whole_frame_vs_dynamic, whole_frame_vs_naive;
  std::optional<RatioStats> light_vs_dynamic, light_vs_naive;
};

// The classified light path of one frame: classification + index build (either path) + the tile
// pass. The baselines' light path is their light pass alone.
double classified_light_ms(const FrameTimings& t);

// Ratios over `frames` (every timed frame of one configuration, in any order).
FrameRatios frame_ratios(const std::vector<FrameTimings>& frames);

}  // namespace tilelight::app
