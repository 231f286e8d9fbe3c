#pragma once
// The frame report: the figures report.json holds and the Table-4.2-style summary on stdout.

#include "tilelight/app/frame_ratios.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/local_light.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tilelight::app {

// Where the camera stood, in the coordinates --eye takes (a --scene file's own): enough to
// place it again with --eye, --target, --up and --fov.
struct CameraPose {
  std::array<double, 3> eye{}, target{}, up{};
  double fov_deg = 0;
};

struct RunDescription {
  std::string device;
  std::uint32_t width = 0, height = 0, msaa_samples = 0, tile_size = 0, frames = 0;
  IndexPath path = IndexPath::cpu;
  bool raw_permutations = false;  // "raw" | "optimised" in the report
  std::string camera;             // a procedural camera's name, "gltf:N" or "eye"
  bool coalesce = true;
  std::string lavapipe_threads;               // LP_NUM_THREADS as set, or "" (driver default)
  std::string primitive;                      // "points" | "triangles": what the tile pass drew; "workgroups" (compute)
  Baselines baselines = Baselines::both;      // the full-frame passes that ran (--baseline)
  LightPass light_pass = LightPass::compute;  // how every light pass ran
  LightKinds light_kinds = LightKinds::variant;  // the build of the light domain the tile pass drew
  std::uint32_t tile_pipelines = 0;              // the tile pass's pipelines (TileRenderer::pipeline_count())
  double tile_pipelines_ms = 0;                  // their creation, host milliseconds
  // The scene: the --scene file's name (empty: the procedural scene), its triangles per G-buffer pass.
  std::string scene;
  std::uint64_t scene_triangles = 0;
  CameraPose camera_pose;
  // What the --scene file holds that is not drawn, as printed on stderr (load_gltf.h's GltfScene::warnings).
  std::vector<std::string> scene_warnings;
  LocalLightCounts local_lights;  // the scene's point, spot and box lights (--lights, or the file's)
  bool cull = true;               // RendererOptions::cull_batches (--no-cull: false)
  LocalLightPass local_light_pass = LocalLightPass::volumes;  // --local-light-pass
  std::uint64_t forward_instances = 0;                        // blended instances (TileRenderer::forward_instances())
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
  // Host milliseconds from the scene file (or the procedural scene's generation) to the scene on
  // the GPU: parse and decode (load_gltf), then TileRenderer::scene_upload_ms().
  double load_ms = 0;
  CulledBatches culled;                      // mesh batches the scene passes skipped (--no-cull: 0)
  LocalLightShadowPool local_light_shadows;  // the local lights' shadow-map pool
  std::uint32_t tiles = 0;
  // Per raw feature, named by its shader define (the generated registry's), in the spec's order.
  std::vector<std::pair<std::string, std::uint32_t>> raw_property_tiles;
  std::vector<std::uint32_t> optimised_tiles;  // 32 counts
  // Raster: one primitive per tile uncoalesced, the primitives drawn after coalescing, and the
  // rectangles they draw (a non-square one is drawn as one point per tile). Compute: the tiles
  // dispatched, the workgroups that shade them, and 0.
  std::uint32_t primitives_uncoalesced = 0, primitives_coalesced = 0;
  std::uint32_t rectangles = 0;
  MedianTimings timings;
  std::vector<FrameTimings> frame_timings;  // every timed frame, in order (timings: their medians)
  FrameRatios ratios;                       // frame_ratios(frame_timings)
  std::optional<Equivalences> equivalence;  // empty when neither naive nor dynamic ran
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

// The chapter's Table 4.2 layout, led by the whole frame: per-stage milliseconds of each
// baseline that ran and of the classified frame, then the per-frame speed-ups.
std::string timing_table(const FrameReport& report);

}  // namespace tilelight::app
