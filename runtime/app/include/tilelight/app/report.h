#pragma once
// The frame report: the figures report.json holds and the Table-4.2-style summary on stdout.

#include "tilelight/render/tile_renderer.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tilelight::app {

struct RunDescription {
  std::string device;
  std::uint32_t width = 0, height = 0, msaa_samples = 0, tile_size = 0, frames = 0;
  std::string path;          // "cpu" | "gpu"
  std::string permutations;  // "optimised" | "raw"
  std::string camera;
  bool coalesce = true;
  std::string lavapipe_threads;  // LP_NUM_THREADS as set, or "" (driver default)
  std::string primitive;         // "points" | "triangles": what the tile pass drew; "workgroups" (compute)
  std::string baselines;         // "naive" | "dynamic" | "both": the full-screen passes that ran
  std::string light_pass;        // "raster" | "compute": how every light pass ran
  // The scene: the --scene file's name (empty: the procedural scene), its triangles per G-buffer pass.
  std::string scene;
  std::uint64_t scene_triangles = 0;
};

// Milliseconds per stage, each the median over the frames (FrameTimings' stages, of one frame).
using MedianTimings = FrameTimings;

struct Equivalence {
  double max_abs_difference = 0;       // over every channel of every pixel
  std::uint64_t pixels_different = 0;  // pixels with any channel differing
};

// What the classified frame was compared with: the naive pass where it ran, else the dynamic
// one; and the dynamic pass against the naive one, where both ran.
struct Equivalences {
  std::string reference;  // "naive" | "dynamic"
  Equivalence classified;
  std::optional<Equivalence> dynamic;  // dynamic vs naive
};

struct ProcessFigures {
  double peak_rss_mib = 0;          // the process's largest resident set size, at the end of the run
  double rss_after_frames_mib = 0;  // the resident set size right after the last frame
};

struct FrameReport {
  RunDescription run;
  std::uint32_t tiles = 0;
  std::vector<std::pair<std::string, std::uint32_t>> raw_property_tiles;  // in the order
  std::vector<std::uint32_t> optimised_tiles;                             // 32 counts
  // Raster: one primitive per tile uncoalesced, the primitives drawn after coalescing, and the
  // rectangles they draw (a non-square one is drawn as one point per tile). Compute: the tiles
  // dispatched, the workgroups that shade them, and 0.
  std::uint32_t primitives_uncoalesced = 0, primitives_coalesced = 0;
  std::uint32_t rectangles = 0;
  MedianTimings timings;
  std::vector<FrameTimings> frame_timings;  // every timed frame, in order (timings: their medians)
  Equivalences equivalence;
  ProcessFigures process;
};

// The optimised ID of each row-major raw tile ID, through the generated checked lookup
// (split_second::optimised_id). Throws tilelight::Error naming the first tile whose raw ID is
// out of range or pruned: the index build refuses such a frame before it gets here.
std::vector<std::uint8_t> optimised_tile_ids(const std::vector<std::uint8_t>& raw_ids);

// Counts per raw property and per optimised ID from the row-major raw tile IDs (through
// optimised_tile_ids(), so it throws as that does), whatever path or permutation set drew the
// frame.
void count_tiles(FrameReport& report, const std::vector<std::uint8_t>& raw_ids);

MedianTimings median_timings(const std::vector<FrameTimings>& frames);

Equivalence compare_frames(const RgbaImage& classified, const RgbaImage& naive);

// The classified frame against the naive one where it ran, else the dynamic one; the dynamic
// frame against the naive one where both ran. Precondition: at least one baseline image.
Equivalences compare_with_baselines(const RgbaImage& classified, const std::optional<RgbaImage>& naive,
                                    const std::optional<RgbaImage>& dynamic);

std::string report_json(const FrameReport& report);

// The chapter's Table 4.2 layout: per-stage milliseconds, naive vs classified.
std::string timing_table(const FrameReport& report);

}  // namespace tilelight::app
