#pragma once
// The renderer's light passes behind one interface: the tile (classified) pass and the baselines,
// run as draws (raster_tile_light_pass.h) or as dispatches (compute_tile_light_pass.h), together
// with where the tile pass's per-frame work comes from (IndexPath). On the CPU path the host
// builds it after submit A's classification and before it signals submit B; on the GPU path
// submit A builds it in compute. TileRenderer holds one and records and submits around it, so
// "which light pass" and "which index path" are decided once, here, instead of at every use.

#include "floor_target.h"
#include "light_classes.h"
#include "lighting_interface.h"
#include "lighting_passes.h"
#include "render_targets.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/tiles/tile_primitive.h"
#include "tilelight/vulkan/buffer.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

namespace tilelight {

class Context;

// What either light pass is built from. What it references must outlive the pass, except the
// two spans: the builds copy them into their own maps at construction.
struct TileLightPassSetup {
  const Context& context;
  const TileGrid& grid;
  const RenderTargets& targets;
  const LightingInterface& lighting;
  // The draw classes and the build of the light domain they are drawn with (the raw ID ->
  // class map below is theirs).
  const LightClasses& classes;
  IndexPath path;
  bool coalesce;            // the raster index build's coalescing (the compute lists do not coalesce)
  TilePrimitive primitive;  // the raster tile pass's primitive
  // raw ID -> draw class, and the raw IDs no permutation exists for (both kRawCount entries).
  std::span<const std::uint8_t> class_for_raw;
  std::span<const bool> pruned;
  const Buffer& tile_ids;  // the classification's blocked raw IDs on the device (the GPU build reads them)
  VkDescriptorPool pool;
  const FloorTarget* floor;  // the floor pass's target; null where the floor pass does not run
};

// The full-frame baseline light passes, each run on the plain G-buffer.
enum class BaselinePass { naive, dynamic, floor };

class TileLightPass {
 public:
  virtual ~TileLightPass() = default;

  // Draw classes: 32 (optimised) or 128 (raw, pruned IDs included), and the tile pass's pipelines.
  virtual std::uint32_t class_count() const = 0;
  virtual std::uint32_t pipeline_count() const = 0;
  // Host milliseconds the tile pass's pipelines took to create.
  virtual double tile_pipelines_ms() const = 0;

  // True on the CPU path: each frame the host must build_on_host() between classification and
  // the signal that releases submit B. False on the GPU path: record_build() goes into submit A.
  bool host_builds() const { return host_builds_; }

  // GPU path (precondition: !host_builds()): the build, after classification in submit A; it
  // ends with the barrier that makes its output visible to the tile pass.
  virtual void record_build(VkCommandBuffer cmd) const = 0;
  // What the tile pass needs before its start timestamp (untimed); nothing by default.
  virtual void record_prepare(VkCommandBuffer cmd, const RenderTargets& targets) const;
  // The tile pass, recorded once: it reads what the build writes later, each frame.
  virtual void record_tiled(VkCommandBuffer cmd, const RenderTargets& targets) const = 0;
  // A baseline, into its own target. Precondition for BaselinePass::floor: the setup had a
  // `floor` target (checked: tilelight::Error).
  virtual void record_baseline(VkCommandBuffer cmd, const RenderTargets& targets, BaselinePass pass) const = 0;

  // CPU path (precondition: host_builds()): builds the frame's work from the classification's
  // blocked raw IDs into the host-visible buffers the tile pass reads. Throws tilelight::Error
  // on an impossible ID, before anything is written.
  virtual void build_on_host(std::span<const std::uint8_t> blocked_raw_ids) = 0;
  // CPU path: every draw or dispatch of the tile pass does nothing (the state before the first
  // build, and what a failed frame releases the blocked tile pass with). No-op on the GPU path.
  virtual void clear_draws() = 0;

  // The last frame's figures, one entry per draw class: on the CPU path those of the last
  // build_on_host(); on the GPU path read back from the build (precondition: the frame's fence
  // was waited for), throwing tilelight::Error where a tile had an impossible raw ID.
  virtual FrameStats stats() const = 0;

 protected:
  // `setup`: that of the implementation, whose path and floor target this keeps.
  explicit TileLightPass(const TileLightPassSetup& setup);
  // The setup's floor target; throws tilelight::Error where the floor pass does not run.
  const FloorTarget& floor() const;

 private:
  bool host_builds_;
  const FloorTarget* floor_;
};

// Precondition: setup.floor is non-null iff the renderer runs the floor pass.
std::unique_ptr<TileLightPass> make_tile_light_pass(LightPass kind, const TileLightPassSetup& setup);

// The GPU builds count the tiles whose raw ID was impossible instead of failing: reports them.
// Throws tilelight::Error naming `build` when `invalid_tiles` is not 0.
void check_no_invalid_tiles(std::uint32_t invalid_tiles, std::string_view build);

}  // namespace tilelight
