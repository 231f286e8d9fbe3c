#include "tilelight/render/tile_renderer.h"

#include "descriptors.h"
#include "floor_target.h"
#include "forward_pass.h"
#include "light_classes.h"
#include "lighting_interface.h"
#include "local_light_passes.h"
#include "local_light_shadows.h"
#include "picture_readback.h"
#include "render_targets.h"
#include "scene_passes.h"
#include "tile_classification.h"
#include "tile_light_pass.h"
#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/commands.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/submit.h"
#include "tilelight/vulkan/sync.h"
#include "tilelight/vulkan/timestamps.h"

#include <split_second_shaders.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

namespace tilelight {

namespace {

void check_size(const Context& context, const RendererOptions& options) {
  const DeviceLimits& limits = context.limits();
  auto check_one = [&](const char* what, std::uint32_t value, std::uint32_t limit) {
    if (value == 0) throw OptionError(what, std::string(what) + " 0: the frame must be at least 1 pixel");
    if (value > limit) {
      throw OptionError(what, std::string(what) + " " + std::to_string(value) + ": exceeds the maximum of " +
                                  std::to_string(limit) + " on " + context.device_name());
    }
  };
  check_one("width", options.width, std::min(limits.max_framebuffer_width, limits.max_image_dimension_2d));
  check_one("height", options.height, std::min(limits.max_framebuffer_height, limits.max_image_dimension_2d));
}

TileGrid checked_grid(const Context& context, const RendererOptions& options) {
  check_size(context, options);
  return TileGrid::make(options.width, options.height, options.tile_size);
}

// Points need large point sprites up to a whole block (4 tiles) and a viewport of whole tiles.
std::optional<std::string> points_unsupported(const Context& context, const TileGrid& grid) {
  const DeviceLimits& limits = context.limits();
  const float largest = static_cast<float>(kBlockTiles * grid.tile_size);
  if (!context.features().large_points) return "the device lacks the largePoints feature";
  if (limits.max_point_size < largest) {
    return "the device's largest point is " + std::to_string(limits.max_point_size) + " pixels, " +
           std::to_string(static_cast<int>(largest)) + " are needed";
  }
  if (grid.tiles_x * grid.tile_size > limits.max_viewport_width ||
      grid.tiles_y * grid.tile_size > limits.max_viewport_height) {
    return "a viewport of whole tiles exceeds the device's largest viewport";
  }
  return std::nullopt;
}

// The renderer's one choice of the sample count (--msaa): a count the device lacks is an error
// about that option.
VkSampleCountFlagBits checked_msaa(const Context& context, std::uint32_t requested) {
  try {
    return context.choose_msaa(requested);
  } catch (const Error& e) {
    throw OptionError("msaa", "msaa " + std::to_string(requested) + ": " + e.what());
  }
}

TilePrimitive choose_primitive(const Context& context, const TileGrid& grid, std::optional<TilePrimitive> asked) {
  const std::optional<std::string> why_not = points_unsupported(context, grid);
  if (!asked) return why_not ? TilePrimitive::triangles : TilePrimitive::points;
  if (*asked == TilePrimitive::points && why_not) {
    throw OptionError("primitive", "primitive points: not available on " + context.device_name() + ": " + *why_not);
  }
  return *asked;
}

// Every raw ID the registry has no permutation for: pruned, or (for a registry smaller than
// the domain, which the static_asserts of shader_registry.cpp rule out) missing.
std::array<bool, split_second::kRawCount> pruned_raw_ids(const shadergen::Registry& registry) {
  std::array<bool, split_second::kRawCount> pruned{};
  for (std::uint32_t raw = 0; raw < split_second::kRawCount; ++raw)
    pruned[raw] = registry.find_raw(shadergen::RawId(raw)) == nullptr;
  return pruned;
}

// Descriptor sets one renderer allocates from its pool, at most 13: the scene's, lighting set 0,
// the tile-ID output, the GPU index build, the GPU tile-list build, the compute light pass's
// four targets (classified, naive, dynamic, floor), the branch block's (branch_set.h), the local
// lights' sets 0, 1 and 3, and the forward pass's sets 0 and 1.
// The base colour textures have a pool of their own (scene_textures.cpp).
constexpr std::uint32_t kMaxDescriptorSets = 16;

// How long a failing frame waits, at least, for the GPU to finish what it was given before it
// releases the blocked tile pass (release_blocked_tile_pass()).
constexpr Seconds kReleaseGrace{10.0};

// Timestamps of submit B, by label (the baselines' depend on which ran).
constexpr std::string_view kTileStart = "start", kTiled = "tiled", kGBufferPlain = "gbuffer_plain";
constexpr std::string_view kNaive = "naive", kDynamic = "dynamic", kFloor = "floor";
// The local lights added after each light pass: into the classified, naive and dynamic targets.
constexpr std::string_view kLocal = "local", kNaiveLocal = "naive_local", kDynamicLocal = "dynamic_local";
// The blended materials' forward pass after the local lights, into the same targets.
constexpr std::string_view kForward = "forward", kNaiveForward = "naive_forward", kDynamicForward = "dynamic_forward";
// Submit A's stamp after the local lights' shadow maps, in the frames that render them.
constexpr std::string_view kLocalShadows = "local_shadows";
// Submit B writes at most: start, tiled, local, forward, gbuffer_plain, naive, naive_local,
// naive_forward, dynamic, dynamic_local, dynamic_forward, floor.
constexpr std::uint32_t kTileTimestamps = 12;

bool wrote(const std::vector<Timestamp>& stamps, std::string_view label) {
  for (const Timestamp& stamp : stamps) {
    if (stamp.label == label) return true;
  }
  return false;
}

std::size_t index_of(const std::vector<Timestamp>& stamps, std::string_view label) {
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    if (stamps[i].label == label) return i;
  }
  throw Error("no timestamp \"" + std::string(label) + "\" was written");
}

// A pass of submit B: from the stamp before its own (every pass there follows another).
double pass_ms(const std::vector<Timestamp>& stamps, std::string_view label) {
  const std::size_t end = index_of(stamps, label);
  return end == 0 ? 0.0 : stamps[end].ms - stamps[end - 1].ms;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

struct TileRenderer::Impl {
  const Context& context;
  RendererOptions options;
  TileGrid grid;
  TilePrimitive primitive;
  VkSampleCountFlagBits samples;
  CommandPool pool;
  UniqueDescriptorPool descriptor_pool;
  std::unique_ptr<RenderTargets> targets;
  std::unique_ptr<ScenePasses> scene_passes;
  std::unique_ptr<LightingInterface> lighting;
  std::unique_ptr<TileClassification> classification;
  std::unique_ptr<FloorTarget> floor_target;              // Baselines::floor and all
  LightClasses light_classes;                             // the tile pass's draw classes (light_kinds)
  std::unique_ptr<TileLightPass> light_pass;              // LightPass x IndexPath
  std::unique_ptr<LocalLightShadows> local_shadows;       // before the sun's map, first frame (or each)
  std::unique_ptr<LocalLightPasses> local_lights;         // after each light pass, into its target
  std::unique_ptr<ForwardPass> forward;                   // blended materials, after the local lights
  std::function<void(VkCommandBuffer)> gbuffer_override;  // replaces the scene's G-buffers when set

  UniqueCommandBuffer frame_commands;  // submit A, re-recorded each frame
  UniqueCommandBuffer tile_commands;   // submit B, recorded once
  TimestampQueries frame_queries, tile_queries;
  TimelineSemaphore timeline;
  Fence frame_done;
  std::uint64_t frame = 0;
  std::function<void()> before_host_signal;
  double scene_upload_ms = 0;

  Impl(const Context& ctx, const Scene& scene, const RendererOptions& opts)
      : context(ctx),
        options(opts),
        grid(checked_grid(ctx, opts)),
        primitive(choose_primitive(ctx, grid, opts.primitive)),
        samples(checked_msaa(ctx, opts.msaa)),
        pool(ctx, "tilelight frame") {
    const Camera& camera = opts.camera_pose ? *opts.camera_pose : scene.camera(opts.camera);
    descriptor_pool = create_descriptor_pool(ctx, kMaxDescriptorSets, "tilelight descriptors");
    targets = std::make_unique<RenderTargets>(ctx, VkExtent2D{opts.width, opts.height}, samples,
                                              scene.sun.shadow_map_size, opts.light_pass == LightPass::compute);
    const auto upload_start = std::chrono::steady_clock::now();
    scene_passes =
        std::make_unique<ScenePasses>(ctx, scene, camera, *targets, descriptor_pool.get(), pool, opts.cull_batches);
    scene_upload_ms = milliseconds_since(upload_start);
    lighting = std::make_unique<LightingInterface>(ctx, make_lighting_params(scene, camera, opts.width, opts.height),
                                                   *targets, descriptor_pool.get());
    classification = std::make_unique<TileClassification>(ctx, grid, *targets, *lighting, descriptor_pool.get());
    if (runs_floor()) floor_target = std::make_unique<FloorTarget>(ctx, *targets);
    light_pass = create_light_pass();
    local_shadows = std::make_unique<LocalLightShadows>(
        ctx, scene, *scene_passes, scene_passes->textures().set_layout(),
        LocalShadowOptions{opts.local_light_shadows, opts.local_light_shadow_cache, opts.local_light_shadow_face_size,
                           opts.local_light_shadow_cap_bytes});
    local_lights =
        std::make_unique<LocalLightPasses>(ctx, scene, *targets, lighting->params(), scene_passes->textures(),
                                           descriptor_pool.get(), opts.local_light_pass, *local_shadows);
    forward = std::make_unique<ForwardPass>(ctx, scene, camera, *targets, lighting->params(), *scene_passes,
                                            descriptor_pool.get(), *local_shadows);

    frame_queries = TimestampQueries(ctx, "frame timestamps", 8);
    tile_queries = TimestampQueries(ctx, "tile pass timestamps", kTileTimestamps);
    timeline = TimelineSemaphore(ctx, "classification/patch timeline", 0);
    frame_done = Fence(ctx, "frame done");
    frame_commands = pool.allocate("frame (submit A)");
    tile_commands = pool.allocate("tile pass (submit B, pre-recorded)");
    record_tile_pass();
  }

  PermutationSet permutation_set() const {
    return options.raw_permutations ? PermutationSet::raw : PermutationSet::optimised;
  }

  // The builders keep what they need of the class map and the pruned IDs: the IDs die here.
  // raw ID -> draw class comes from the classes of the build the tile pass draws (light_classes.h):
  // the optimised IDs, or (optimised ID, values) pairs, or the raw IDs. A pruned ID has no class
  // (0 there); pruned_raw_ids() marks it, and the index builds refuse a tile that holds one.
  std::unique_ptr<TileLightPass> create_light_pass() {
    light_classes = tilelight::light_classes(light_shaders_for(options.light_kinds, options.light_pass, samples),
                                             permutation_set());
    const std::array<bool, split_second::kRawCount> pruned = pruned_raw_ids(lighting->shaders());
    return make_tile_light_pass(
        options.light_pass,
        {context, grid, *targets, *lighting, light_classes, options.path, options.coalesce, primitive,
         light_classes.class_for_raw, pruned, classification->device_ids(), descriptor_pool.get(), floor_target.get()});
  }

  std::uint32_t class_count() const { return light_pass->class_count(); }

  bool runs_naive() const { return tilelight::runs_naive(options.baselines); }
  bool runs_dynamic() const { return tilelight::runs_dynamic(options.baselines); }
  bool runs_floor() const { return tilelight::runs_floor(options.baselines); }
  bool runs_any_baseline() const { return tilelight::runs_any_baseline(options.baselines); }

  // Recorded once, before any classification: the draws it holds are patched every frame.
  // Recorded again when the G-buffer override is set (the plain pass becomes the upload).
  void record_tile_pass() {
    VkCommandBuffer cmd = tile_commands.get();
    check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer", "tile pass (submit B)");
    begin_commands(cmd, "tile pass", 0);
    tile_queries.reset(cmd);
    light_pass->record_prepare(cmd, *targets);
    tile_queries.write(cmd, std::string(kTileStart));
    light_pass->record_tiled(cmd, *targets);
    tile_queries.write(cmd, std::string(kTiled));
    // Before the baselines' plain G-buffer replaces the classified one it reads.
    record_local_lights(cmd, LocalLightTarget::classified, true, kLocal);
    record_forward(cmd, LocalLightTarget::classified, kForward);
    if (runs_any_baseline()) record_baselines(cmd);
    end_commands(cmd, "tile pass");
  }

  bool has_local_lights() const { return local_lights->light_count() > 0; }

  // The local lights into one light target, then their stamp; nothing at all without lights.
  void record_local_lights(VkCommandBuffer cmd, LocalLightTarget target, bool tagged_gbuffer, std::string_view stamp) {
    if (!has_local_lights()) return;
    local_lights->record(cmd, *targets, target, tagged_gbuffer);
    tile_queries.write(cmd, std::string(stamp));
  }

  // The local lights' part of a frame whose light pass ended at a stamp: 0 without lights.
  double local_ms(const std::vector<Timestamp>& stamps, std::string_view stamp) const {
    return has_local_lights() ? pass_ms(stamps, stamp) : 0.0;
  }

  bool has_forward() const { return forward->instance_count() > 0; }

  // The blended materials into one light target, then their stamp; nothing without any.
  void record_forward(VkCommandBuffer cmd, LocalLightTarget target, std::string_view stamp) {
    if (!has_forward()) return;
    forward->record(cmd, *targets, target);
    tile_queries.write(cmd, std::string(stamp));
  }

  double forward_ms(const std::vector<Timestamp>& stamps, std::string_view stamp) const {
    return has_forward() ? pass_ms(stamps, stamp) : 0.0;
  }

  // The baselines' whole frame after the classified one: the plain G-buffer (what lighting
  // reads, no classification data) into the same targets, then each baseline that runs.
  void record_baselines(VkCommandBuffer cmd) {
    // The G-buffer render pass's external dependency orders its writes after the tile pass's
    // reads of the same images, as it does in submit A after the previous frame's.
    record_plain_gbuffer(cmd);
    tile_queries.write(cmd, std::string(kGBufferPlain));
    if (runs_naive()) {
      light_pass->record_baseline(cmd, *targets, BaselinePass::naive);
      tile_queries.write(cmd, std::string(kNaive));
      record_local_lights(cmd, LocalLightTarget::naive, false, kNaiveLocal);
      record_forward(cmd, LocalLightTarget::naive, kNaiveForward);
    }
    if (runs_dynamic()) {
      light_pass->record_baseline(cmd, *targets, BaselinePass::dynamic);
      tile_queries.write(cmd, std::string(kDynamic));
      record_local_lights(cmd, LocalLightTarget::dynamic, false, kDynamicLocal);
      record_forward(cmd, LocalLightTarget::dynamic, kDynamicForward);
    }
    if (runs_floor()) {
      light_pass->record_baseline(cmd, *targets, BaselinePass::floor);
      tile_queries.write(cmd, std::string(kFloor));
    }
  }

  // The baselines' G-buffer: the scene's plain one, or the test's override.
  void record_plain_gbuffer(VkCommandBuffer cmd) const {
    if (gbuffer_override) {
      gbuffer_override(cmd);  // the baselines must see the overridden G-buffer too
    } else {
      scene_passes->record_gbuffer_plain(cmd, *targets);
    }
  }

  // The G-buffer classification reads: the scene's classified one, or the test's override.
  void record_classified_gbuffer(VkCommandBuffer cmd) const {
    if (gbuffer_override) {
      gbuffer_override(cmd);
    } else {
      scene_passes->record_gbuffer(cmd, *targets);
    }
  }

  void record_frame() {
    VkCommandBuffer cmd = frame_commands.get();
    check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer", "frame (submit A)");
    begin_commands(cmd, "frame");
    frame_queries.reset(cmd);
    frame_queries.write(cmd, "start");
    if (local_shadows->renders_this_frame()) {
      local_shadows->record(cmd);
      frame_queries.write(cmd, std::string(kLocalShadows));
    }
    scene_passes->record_shadow_map(cmd, *targets);
    frame_queries.write(cmd, "shadow");
    record_classified_gbuffer(cmd);
    frame_queries.write(cmd, "gbuffer");
    classification->record(cmd);
    frame_queries.write(cmd, "classified");
    if (!light_pass->host_builds()) {
      light_pass->record_build(cmd);
      frame_queries.write(cmd, "built");
    }
    end_commands(cmd, "frame");
  }

  // The host's part of the CPU path: wait for classification, build, patch, signal.
  void build_and_patch(std::uint64_t classified_value, std::uint64_t patched_value, double& build_ms) {
    timeline.wait(classified_value, "classification", options.timeout);
    const auto start = std::chrono::steady_clock::now();
    light_pass->build_on_host(classification->host_ids());
    build_ms = milliseconds_since(start);
    if (before_host_signal) before_host_signal();
    timeline.signal(patched_value);
  }

  FrameResult render_frame() {
    ++frame;
    const std::uint64_t classified_value = 2 * frame - 1;
    const std::uint64_t patched_value = 2 * frame;
    record_frame();
    frame_done.reset();

    const VkCommandBuffer a = frame_commands.get();
    const SemaphoreSignal classified{timeline.handle(), classified_value};
    submit(context, {std::span(&a, 1), {}, std::span(&classified, 1), VK_NULL_HANDLE}, "frame (submit A)");

    const VkCommandBuffer b = tile_commands.get();
    FrameResult result;
    if (light_pass->host_builds()) {
      // Submitted before the host has built anything: the GPU holds it until the signal.
      const SemaphoreWait patched{timeline.handle(), patched_value, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT};
      submit(context, {std::span(&b, 1), std::span(&patched, 1), {}, frame_done.handle()}, "tile pass (submit B)");
      try {
        build_and_patch(classified_value, patched_value, result.timings.index_build_cpu);
      } catch (...) {
        release_blocked_tile_pass(classified_value, patched_value);
        throw;
      }
    } else {
      submit(context, {std::span(&b, 1), {}, {}, frame_done.handle()}, "tile pass (submit B)");
    }
    frame_done.wait("the tile and baseline light passes", options.timeout);
    result.stats = light_pass->stats();
    read_timings(result.timings);
    return result;
  }

  // The tile pass is waiting for a signal that will not come: empty every draw, signal, and
  // wait for the GPU, so nothing is left blocked when the error propagates. A host signal must
  // be below every pending signal of the semaphore (VUID-VkSemaphoreSignalInfo-value-03259), so
  // when the failure was the wait for classification itself (a GPU slower than `timeout`),
  // submit A's signal of `classified_value` may still be pending: wait for it first, for up to
  // kReleaseGrace more. A GPU that never gets there is hung; the tile pass then stays blocked
  // and the context's teardown reports it (and leaks the device rather than destroy it in use).
  void release_blocked_tile_pass(std::uint64_t classified_value, std::uint64_t patched_value) noexcept {
    try {
      light_pass->clear_draws();
      timeline.wait(classified_value, "classification, before releasing the tile pass",
                    std::max(options.timeout, kReleaseGrace));
      if (timeline.value() < patched_value) timeline.signal(patched_value);
      frame_done.wait("the tile pass after a failed index build", std::max(options.timeout, kReleaseGrace));
    } catch (...) {
      // Already failing: the original error is the one worth reporting.
    }
  }

  // One query-pool read per pool; stamps are in the order they were written.
  void read_timings(FrameTimings& t) const {
    // start [local_shadows] shadow gbuffer classified [built]
    const std::vector<Timestamp> frame_stamps = frame_queries.read();
    const std::vector<Timestamp> tile_stamps = tile_queries.read();  // start tiled [gbuffer_plain naive dynamic floor]
    t.local_light_shadows = wrote(frame_stamps, kLocalShadows) ? pass_ms(frame_stamps, kLocalShadows) : 0.0;
    t.shadow_map = pass_ms(frame_stamps, "shadow");
    t.gbuffer = pass_ms(frame_stamps, "gbuffer");
    t.classification = pass_ms(frame_stamps, "classified");
    if (!light_pass->host_builds()) t.index_build_gpu = pass_ms(frame_stamps, "built");
    t.tiled_light = pass_ms(tile_stamps, kTiled);
    t.local_lights = local_ms(tile_stamps, kLocal);
    t.forward = forward_ms(tile_stamps, kForward);
    // End to end across both submissions: the CPU path's wait for the host is part of it.
    const std::string_view last = has_forward() ? kForward : has_local_lights() ? kLocal : kTiled;
    t.frame_classified = tile_queries.span_ms(frame_stamps.front(), tile_stamps[index_of(tile_stamps, last)]);
    if (runs_any_baseline()) read_baseline_timings(tile_stamps, t);
  }

  // A baseline frame is the sum of its passes: the shadow maps (shared: the local lights' where
  // this frame rendered them, and the sun's), the plain G-buffer, its light pass.
  void read_baseline_timings(const std::vector<Timestamp>& stamps, FrameTimings& t) const {
    t.gbuffer_plain = pass_ms(stamps, kGBufferPlain);
    if (runs_naive()) {
      t.naive_light = pass_ms(stamps, kNaive);
      t.frame_naive = t.local_light_shadows + t.shadow_map + t.gbuffer_plain + t.naive_light +
                      local_ms(stamps, kNaiveLocal) + forward_ms(stamps, kNaiveForward);
    }
    if (runs_dynamic()) {
      t.dynamic_light = pass_ms(stamps, kDynamic);
      t.frame_dynamic = t.local_light_shadows + t.shadow_map + t.gbuffer_plain + t.dynamic_light +
                        local_ms(stamps, kDynamicLocal) + forward_ms(stamps, kDynamicForward);
    }
    if (runs_floor()) t.floor_light = pass_ms(stamps, kFloor);
  }
};

TileRenderer::TileRenderer(const Context& context, const Scene& scene, const RendererOptions& options)
    : impl_(std::make_unique<Impl>(context, scene, options)) {}

TileRenderer::~TileRenderer() {
  if (impl_) {
    try {
      // At least kReleaseGrace: a timeout shorter than the GPU's frame (a fault being tested)
      // must not leave the queue running while the renderer's objects are destroyed.
      impl_->context.wait_idle("renderer teardown", std::max(impl_->options.timeout, kReleaseGrace));
    } catch (...) {
      // Destructors must not throw; the context's own teardown waits (bounded) again.
    }
  }
}

FrameResult TileRenderer::render_frame() { return impl_->render_frame(); }
const TileGrid& TileRenderer::grid() const { return impl_->grid; }
std::uint32_t TileRenderer::msaa_samples() const { return static_cast<std::uint32_t>(impl_->samples); }
std::uint32_t TileRenderer::draw_class_count() const { return impl_->class_count(); }
TilePrimitive TileRenderer::tile_primitive() const { return impl_->primitive; }
std::uint32_t TileRenderer::pipeline_count() const { return impl_->light_pass->pipeline_count(); }
double TileRenderer::tile_pipelines_ms() const { return impl_->light_pass->tile_pipelines_ms(); }
LightPass TileRenderer::light_pass() const { return impl_->options.light_pass; }
LightKinds TileRenderer::light_kinds() const { return impl_->options.light_kinds; }
CulledBatches TileRenderer::culled_batches() const {
  return {impl_->scene_passes->culled_gbuffer_batches(), impl_->scene_passes->culled_shadow_batches()};
}
LocalLightShadowPool TileRenderer::local_light_shadow_pool() const {
  const LocalShadowPlan& plan = impl_->local_shadows->plan();
  return {impl_->options.local_light_shadows,
          impl_->options.local_light_shadow_cache,
          plan.maps,
          plan.faces,
          plan.face_size,
          plan.bytes,
          plan.cap_bytes,
          plan.unshadowed};
}
double TileRenderer::scene_upload_ms() const { return impl_->scene_upload_ms; }
std::size_t TileRenderer::forward_instances() const { return impl_->forward->instance_count(); }
const LightingParamsBlock& TileRenderer::lighting_params() const { return impl_->lighting->params(); }

std::vector<std::uint8_t> TileRenderer::raw_tile_ids() const {
  return to_row_major(impl_->grid, impl_->classification->host_ids());
}

RgbaImage TileRenderer::read_classified() const {
  return read_image_rgba(impl_->context, impl_->pool, impl_->targets->classified(),
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, impl_->options.timeout);
}

RgbaImage TileRenderer::read_naive() const {
  if (!impl_->runs_naive()) throw Error("read_naive: this renderer does not run the naive pass (baselines dynamic)");
  return read_image_rgba(impl_->context, impl_->pool, impl_->targets->naive(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         impl_->options.timeout);
}

RgbaImage TileRenderer::read_floor() const {
  if (!impl_->floor_target) throw Error("read_floor: this renderer does not run the floor pass (baselines)");
  return read_image_rgba(impl_->context, impl_->pool, impl_->floor_target->image(),
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, impl_->options.timeout);
}

RgbaImage TileRenderer::read_dynamic() const {
  if (!impl_->runs_dynamic())
    throw Error("read_dynamic: this renderer does not run the dynamic pass (baselines naive)");
  return read_image_rgba(impl_->context, impl_->pool, impl_->targets->dynamic(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         impl_->options.timeout);
}

const Context& TileRenderer::context() const { return impl_->context; }
const RenderTargets& TileRenderer::render_targets() const { return *impl_->targets; }
const LightingInterface& TileRenderer::lighting_interface() const { return *impl_->lighting; }

void TileRenderer::submit_after_gbuffer(GBufferKind kind, const std::function<void(VkCommandBuffer)>& record) {
  Impl& impl = *impl_;
  // Where a baseline ran, the targets hold its plain G-buffer, without the classification data
  // the CPU reference needs: draw the classified one again first (the frame's, bit for bit).
  submit_and_wait(
      impl.context, impl.pool,
      [&](VkCommandBuffer cmd) {
        if (kind == GBufferKind::plain) {
          impl.record_plain_gbuffer(cmd);
        } else if (impl.runs_any_baseline()) {
          impl.record_classified_gbuffer(cmd);
        }
        record(cmd);
      },
      "a test pass after the G-buffer", impl.options.timeout);
}

std::vector<float> TileRenderer::read_shadow_map() const {
  const std::vector<std::byte> bytes =
      read_image_bytes(impl_->context, impl_->pool, impl_->targets->shadow_map(),
                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, impl_->options.timeout);
  std::vector<float> depths(bytes.size() / sizeof(float));
  std::memcpy(depths.data(), bytes.data(), depths.size() * sizeof(float));
  return depths;
}

void TileRenderer::set_gbuffer_recorder(std::function<void(VkCommandBuffer)> gbuffer) {
  impl_->gbuffer_override = std::move(gbuffer);
  // Submit B draws the baselines' G-buffer: it must be the override as well. No frame is in
  // flight here (render_frame() returns after its fence).
  if (impl_->runs_any_baseline()) impl_->record_tile_pass();
}

void TileRenderer::set_before_host_signal(std::function<void()> hook) { impl_->before_host_signal = std::move(hook); }

}  // namespace tilelight
