#pragma once
// One renderer = one camera, one frame size, one configuration: the whole tile-classified
// deferred frame of Split/Second on Vulkan.
//
// Per frame (docs/architecture.md has the diagram):
//   submit A  shadow map -> G-buffer -> classification -> copy IDs to host memory
//             [--path gpu: + LUT, counts, prefix sum, index fill, indirect records in compute]
//             signals timeline value 2k-1
//   submit B  the tile pass, then (where any baseline runs) the plain G-buffer pass into the same
//             targets and the baseline passes (naive, dynamic, floor), recorded ONCE at start-up
//             (again when a test overrides the G-buffer), before any classification ran;
//             --path cpu: waits for timeline value 2k, which the host signals after it built the
//             index buffer and patched the indirect records (submitted before that signal:
//             wait-before-signal)
//   host      waits for 2k-1, maps IDs through the generated LUT, builds the index buffer
//             (3 passes + coalescing), writes the indirect records, signals 2k
// With LightPass::compute the tile pass is one indirect dispatch per class instead of one draw,
// and what the host (or the GPU build) writes is per-class tile lists and dispatch records.
// Every wait is bounded (`timeout`); a failure between submit B and the host signal still
// signals (with empty draws) so the queue is never left blocked.

#include "tilelight/picture/rgba_image.h"
#include "tilelight/scene/scene.h"
#include "tilelight/scene/uniform_blocks.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/tiles/tile_primitive.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/timeout.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tilelight {

class LightingInterface;
class RenderTargets;

enum class IndexPath { cpu, gpu };

// How the light passes run: as draws (the tile pass draws each class's tiles with the fragment
// permutation; the baselines draw two full-frame triangles) or as compute dispatches (the tile
// pass dispatches each class over its tile list; the baselines are one full-frame dispatch).
// Every pass of a frame is of the one kind, so ratios compare like with like.
enum class LightPass { raster, compute };

// "raster" | "compute", as tilelight's --light-pass spells it.
constexpr const char* to_string(LightPass pass) { return pass == LightPass::compute ? "compute" : "raster"; }

// How the light domain's SKY and LIGHT_SCATTERING features reach the tile pass's shaders
// (docs/spec-format.md, "Kinds"; docs/runtime.md, "Feature kinds"): compiled into the
// permutations (variant: permutations/split_second.json, 32 optimised IDs), fixed at pipeline
// creation (specialization: split_second_specialization.json, one pipeline per optimised ID and
// values pair) or read per draw class from a uniform block (branch: split_second_branch.json,
// one pipeline per optimised ID, the values at a dynamic offset). The shader text is the same
// and so is every pixel; the baselines always draw the variant build (the reference).
enum class LightKinds { variant, specialization, branch };

// "variant" | "specialization" | "branch", as tilelight's --light-kinds spells it.
constexpr const char* to_string(LightKinds kinds) {
  switch (kinds) {
    case LightKinds::variant: return "variant";
    case LightKinds::specialization: return "specialization";
    case LightKinds::branch: return "branch";
  }
  return "?";
}

// How each local light is added into the light targets (docs/local-lights.md): drawn as its
// light volume (a sphere, cone or box, tested against the scene's depth and stencil: the
// Tabula Rasa chapter's §19.7.1), or as a full-screen pass (the chapter's baseline, and the
// per-pixel reference the volumes must equal).
enum class LocalLightPass { volumes, fullscreen };

// "volumes" | "fullscreen", as tilelight's --local-light-pass spells it.
constexpr const char* to_string(LocalLightPass pass) {
  return pass == LocalLightPass::fullscreen ? "fullscreen" : "volumes";
}

// The full-screen passes the classified frame is measured against: naive (the uber-shader with
// every feature, on every sample of every pixel), dynamic (every feature compiled in, each taken
// only where the pixel needs it: per-pixel branching) and floor (reads the G-buffer and writes
// the output with no lighting, in the naive pass's shape: what any full-frame light pass costs
// at least). `both` is naive and dynamic, `all` the three, `none` no baseline at all. The
// baselines run on the plain G-buffer (no classification data), drawn only when one runs.
enum class Baselines { none, naive, dynamic, both, floor, all };

constexpr bool runs_naive(Baselines b) { return b == Baselines::naive || b == Baselines::both || b == Baselines::all; }
constexpr bool runs_dynamic(Baselines b) {
  return b == Baselines::dynamic || b == Baselines::both || b == Baselines::all;
}
constexpr bool runs_floor(Baselines b) { return b == Baselines::floor || b == Baselines::all; }
constexpr bool runs_any_baseline(Baselines b) { return b != Baselines::none; }

// "none" | "naive" | "dynamic" | "both" | "floor" | "all", as tilelight's --baseline spells it.
constexpr const char* to_string(Baselines b) {
  switch (b) {
    case Baselines::none: return "none";
    case Baselines::naive: return "naive";
    case Baselines::dynamic: return "dynamic";
    case Baselines::both: return "both";
    case Baselines::floor: return "floor";
    case Baselines::all: return "all";
  }
  return "?";
}

// The most local lights the forward pass lights one blended instance with: the K most important
// (Tabula Rasa §19.3.3; docs/local-lights.md, "Forward pass for blended materials").
inline constexpr std::uint32_t kForwardMaxLights = 8;

struct RendererOptions {
  std::uint32_t width = 1280;
  std::uint32_t height = 720;
  std::uint32_t msaa = 0;       // 0: automatic (2x where offered, else 4x); else 1, 2, 4, 8, 16
  std::uint32_t tile_size = 4;  // pixels: 4, 8 or 16
  IndexPath path = IndexPath::cpu;
  LightPass light_pass = LightPass::compute;     // tilelight's default (docs/results.md g4)
  LightKinds light_kinds = LightKinds::variant;  // which build of the light domain the tile pass draws
  bool raw_permutations = false;                 // draw the 96 raw permutations instead of the 32 optimised ones
  bool coalesce = true;
  LocalLightPass local_light_pass = LocalLightPass::volumes;  // the scene's local lights, if any
  // Local lights' shadow maps (docs/local-lights.md, "Shadows"): whether lights that cast shadows
  // get maps; whether the maps are kept once rendered (static maps: the first frame renders
  // them) or rendered every frame; each face's size in texels (> 6, square) and the pool's cap
  // on the atlas's bytes (4 per texel). Lights beyond the cap are drawn unshadowed.
  bool local_light_shadows = true;
  bool local_light_shadow_cache = true;
  std::uint32_t local_light_shadow_face_size = 512;
  std::uint64_t local_light_shadow_cap_bytes = 256ull << 20;
  // The scene passes skip mesh batches wholly outside their clip volume (the camera's for the
  // G-buffer, the sun's for the shadow map); no pixel changes. Off: every batch is drawn.
  bool cull_batches = true;
  // How the tile pass draws its rectangles (tile_primitive.h); empty: points where the device
  // draws them (largePoints, a whole block's width), else triangles.
  std::optional<TilePrimitive> primitive;
  std::string camera = "default";
  // A camera placed by the caller (--eye, a fitted file camera): drawn instead of `camera`.
  std::optional<Camera> camera_pose;
  Baselines baselines = Baselines::both;  // which full-screen passes run (and are timed) each frame
  Seconds timeout = kDefaultGpuTimeout;
};

struct FrameTimings {  // milliseconds
  double shadow_map = 0;
  double gbuffer = 0;        // the classified path's G-buffer (with its classification data)
  double gbuffer_plain = 0;  // the baselines' plain G-buffer; 0 when no baseline ran
  double classification = 0;
  double index_build_cpu = 0;  // host clock, CPU path only
  double index_build_gpu = 0;  // GPU timestamps, GPU path only
  double tiled_light = 0, naive_light = 0;
  double dynamic_light = 0;  // the per-pixel-branching pass; 0 when it did not run (RendererOptions::baselines)
  double floor_light = 0;    // the floor pass; 0 when it did not run
  // The local lights added into the classified light target after its global pass (each
  // baseline adds them into its own target too, and its frame below includes that); 0 without
  // local lights.
  double local_lights = 0;
  // The forward pass of the blended materials into the classified light target, after its local
  // lights (each baseline's frame includes its own); 0 without blended materials.
  double forward = 0;
  // Rendering the local lights' shadow maps in this frame (submit A, before the sun's map); 0 in
  // a frame that rendered none: every frame after the first with the cache on, or without maps.
  double local_light_shadows = 0;
  // Whole frames: shadow map + G-buffer + [classification + index build] + light pass + local
  // lights + forward pass. The
  // classified frame is end to end (first to last GPU timestamp), so the CPU path's wait for the
  // host's index build is in it; a baseline frame is the sum of its passes. 0 where it did not run.
  double frame_classified = 0, frame_naive = 0, frame_dynamic = 0;
};

// The raster tile pass draws primitives (coalesced rectangles, as triangle pairs or points); the
// compute tile pass dispatches workgroups over tile lists: there `primitives` count workgroups
// and `rectangles` stay 0.
struct FrameStats {
  std::vector<std::uint32_t> class_tiles;       // per draw class (32 optimised or 128 raw)
  std::vector<std::uint32_t> class_rectangles;  // per draw class
  std::vector<std::uint32_t> class_primitives;  // per draw class: primitives drawn, or workgroups dispatched
  std::uint32_t primitives_uncoalesced = 0;     // one primitive per tile
  std::uint32_t primitives_coalesced = 0;       // primitives drawn (points, or rectangles as triangle pairs)
  std::uint32_t rectangles = 0;                 // rectangles after coalescing
};

struct FrameResult {
  FrameTimings timings;
  FrameStats stats;
};

struct CulledBatches {
  std::uint32_t gbuffer = 0;  // outside the camera's frustum
  std::uint32_t shadow = 0;   // outside the sun's shadow-map volume
};

// The local lights' shadow-map pool (report.json's local_light_shadows).
struct LocalLightShadowPool {
  bool enabled = false;          // RendererOptions::local_light_shadows
  bool cached = true;            // RendererOptions::local_light_shadow_cache
  std::uint32_t maps = 0;        // lights with a map
  std::uint32_t faces = 0;       // their faces (6 per point light, 1 per spot or box)
  std::uint32_t face_size = 0;   // texels per side
  std::uint64_t bytes = 0;       // the atlas's memory (its depth texels)
  std::uint64_t cap_bytes = 0;   // the pool's cap
  std::uint32_t unshadowed = 0;  // lights that cast shadows but got no map (over the cap)
};

// Which of the frame's two G-buffers: the classified path's (with its coverage flags) or the
// baselines' plain one.
enum class GBufferKind { classified, plain };

class TileRenderer {
 public:
  // Throws tilelight::Error naming the value for a size of 0 or beyond the device's limits,
  // an MSAA count the device lacks, an unknown camera or tile size (OptionError, naming the
  // option, for the size, the MSAA count and the primitive).
  TileRenderer(const Context& context, const Scene& scene, const RendererOptions& options);
  ~TileRenderer();
  TileRenderer(const TileRenderer&) = delete;
  TileRenderer& operator=(const TileRenderer&) = delete;

  FrameResult render_frame();

  const TileGrid& grid() const;
  std::uint32_t msaa_samples() const;
  // 32 or 128: with LightKinds other than variant, the (optimised ID, specialization and branch
  // values) pairs that some raw ID reaches (32 as well for the light domain).
  std::uint32_t draw_class_count() const;
  TilePrimitive tile_primitive() const;  // the one chosen (RendererOptions::primitive)
  // The tile pass's pipelines: 32 or 96 (variant), 32 or 96 (specialization: one per optimised ID
  // and specialization values), 8 or 96 (branch: one per optimised ID or raw blob).
  std::uint32_t pipeline_count() const;
  // Host milliseconds the tile pass's pipelines took to create, when this renderer was made.
  double tile_pipelines_ms() const;
  LightPass light_pass() const;
  LightKinds light_kinds() const;
  // Mesh batches the scene passes skip (RendererOptions::cull_batches; 0 without it).
  CulledBatches culled_batches() const;
  // The local lights' shadow maps: how many, how large, and the lights left without.
  LocalLightShadowPool local_light_shadow_pool() const;
  // Host milliseconds to put the scene on the GPU: meshes, instances, textures (with their
  // mip chains) and the scene passes' pipelines, once, when this renderer was made.
  double scene_upload_ms() const;
  // Blended instances the forward pass draws into each light target (0: no forward pass); each
  // is lit by at most kForwardMaxLights local lights.
  std::size_t forward_instances() const;

  // Results of the last frame.
  std::vector<std::uint8_t> raw_tile_ids() const;  // row-major, tiles_x * tiles_y
  RgbaImage read_classified() const;
  RgbaImage read_naive() const;    // precondition: the naive pass runs (RendererOptions::baselines)
  RgbaImage read_dynamic() const;  // precondition: the dynamic pass runs
  RgbaImage read_floor() const;    // precondition: the floor pass runs

 private:
  // The tests' seam (tests/support/tilelight_testing/renderer_test_seam.h) and the only caller
  // of the test-only members below; production code has no way to reach them.
  friend class TileRendererTestSeam;

  // The seam's way to run a test's own passes (tests/support/tilelight_testing: the G-buffer
  // dump and upload, whose shaders are a test domain) against this renderer's targets and
  // lighting set, which are internal types.
  const Context& context() const;
  const RenderTargets& render_targets() const;
  const LightingInterface& lighting_interface() const;
  // The lighting parameters the shaders read (the CPU reference classifier's input).
  const LightingParamsBlock& lighting_params() const;
  // Submits and waits for: the G-buffer of `kind` drawn again into the targets (the classified
  // one only where a baseline's plain one replaced it), from the same scene, camera and
  // override, then `record` (which reads it). Precondition: a frame was rendered.
  void submit_after_gbuffer(GBufferKind kind, const std::function<void(VkCommandBuffer)>& record);
  std::vector<float> read_shadow_map() const;  // shadow_map_size^2 depths, row-major

  // Later frames record `gbuffer` instead of both scene G-buffer passes (the shadow map still
  // comes from the scene). `gbuffer` must begin and end the G-buffer render pass itself, and
  // keep what it records alive as long as this renderer.
  void set_gbuffer_recorder(std::function<void(VkCommandBuffer)> gbuffer);

  // Called on the host after the tile pass was submitted and before the host signals it; an
  // exception thrown here must still leave the GPU unblocked (the failure path).
  void set_before_host_signal(std::function<void()> hook);

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tilelight
