#pragma once
// tilelight_local_light_bench (docs/results.md, section n): the local lights of the procedural
// scene (tilelight --lights N) drawn as light volumes against the full-screen reference, at
// several light counts, measured side by side in one process. This file holds its command line,
// the configurations it measures and the table it prints, so the tests can reach them.

#include "tilelight/render/tile_renderer.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace tilelight::local_light_bench {

// The local lights' shadows in a configuration: none (tilelight --local-light-shadows off), the
// static maps rendered once and kept (the default), or rendered again every frame
// (--local-light-shadow-cache off).
enum class ShadowMode { off, cached, rebuilt };
const char* to_string(ShadowMode mode);

struct BenchOptions {
  std::vector<std::uint32_t> lights{16, 64, 256};
  std::vector<ShadowMode> shadows{ShadowMode::off, ShadowMode::cached, ShadowMode::rebuilt};
  std::vector<LocalLightPass> passes{LocalLightPass::volumes, LocalLightPass::fullscreen};
  std::uint32_t width = 1280, height = 720;
  std::string camera = "street";
  std::uint32_t msaa = 0;                     // 0 = auto, as tilelight --msaa auto
  LightPass light_pass = LightPass::compute;  // tilelight's default
  std::uint32_t frames = 5;
  std::string device;  // as tilelight --device
  std::string out = "tilelight-local-lights";
};

// Parses argv. On --help or a usage error it prints to `out` / `err` and sets `exit_code` (0 for
// help, 2 for a usage error), returning false; true means go on and measure. --quick sets small
// inputs (2 and 4 lights at 96x54, one frame) unless they are given too.
bool parse_bench_options(int argc, const char* const* argv, BenchOptions& options, int& exit_code, std::ostream& out,
                         std::ostream& err);

// One measured configuration: a light count, its shadows and the renderer's options.
struct BenchConfiguration {
  std::uint32_t lights = 0;
  ShadowMode shadows = ShadowMode::off;
  RendererOptions renderer;
};

// Every light count with every shadow mode and every pass, in that order (the passes of one count
// and mode side by side). The
// renderer runs no baseline: the classified frame is the whole frame measured, and the volume
// image is compared with the full-screen one.
std::vector<BenchConfiguration> bench_configurations(const BenchOptions& options);

// What one configuration measured: medians over the timed frames, and the classified image's
// difference from the first pass's image at the same light count and shadow mode (0 for that
// pass itself).
struct BenchRow {
  BenchConfiguration configuration;
  double local_lights_ms = 0;  // FrameTimings::local_lights
  double shadow_maps_ms = 0;   // FrameTimings::local_light_shadows: 0 in frames that render none
  double frame_ms = 0;         // FrameTimings::frame_classified: the whole frame
  LocalLightShadowPool pool;   // the maps the lights got
  std::uint64_t pixels_different = 0;
  double max_abs_difference = 0;
};

// The markdown table: one row per light count and shadow mode, with the maps the lights got, the
// shadow maps' time in a frame, each pass's local-light pass and whole frame side by side, the
// ratios of the second pass over the first (with two passes) and the pixels that differ between
// them.
std::string markdown_table(const BenchOptions& options, const std::vector<BenchRow>& rows);

}  // namespace tilelight::local_light_bench
