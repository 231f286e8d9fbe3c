#include "sweep_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace tilelight::sweep {
namespace {

class PlanBuilder {
 public:
  PlanBuilder(RendererOptions base, std::vector<std::string> only) : base_(std::move(base)), only_(std::move(only)) {}

  // Adds a comparison whose rows are the base configuration changed by each of `variants`.
  template <typename Variant>
  void compare(Facet facet, std::string id, std::string title, const std::vector<Variant>& variants,
               void (*apply)(RendererOptions&, const Variant&)) {
    if (!only_.empty() && std::find(only_.begin(), only_.end(), id) == only_.end()) return;
    Comparison c{facet, std::move(id), std::move(title), {}};
    for (const Variant& v : variants) {
      RendererOptions o = base_;
      apply(o, v);
      c.keys.push_back(add(o));
    }
    plan_.comparisons.push_back(std::move(c));
  }

  SweepPlan take() { return std::move(plan_); }

 private:
  std::string add(const RendererOptions& options) {
    std::string key = configuration_key(options);  // not const: returned by move
    const bool known = std::any_of(plan_.configurations.begin(), plan_.configurations.end(),
                                   [&](const RendererOptions& o) { return configuration_key(o) == key; });
    if (!known) plan_.configurations.push_back(options);
    return key;
  }

  RendererOptions base_;
  std::vector<std::string> only_;
  SweepPlan plan_;
};

}  // namespace

SweepPlan make_sweep_plan(const SweepOptions& options) {
  RendererOptions base;
  // The design choices a) to g) are the raster tile pass's (primitives and coalescing mean
  // nothing to the compute one); the baselines comparison names its light-pass kinds itself.
  base.light_pass = LightPass::raster;
  base.width = options.sizes.front().width;
  base.height = options.sizes.front().height;
  // The design choices are measured from the first camera of the baseline comparison: the
  // procedural scene's "default", a file's, or a placed --eye view (then the only one).
  if (!options.cameras.empty()) base.camera = options.cameras.front();
  const std::string at = fmt::format(" ({}x{})", base.width, base.height);
  PlanBuilder b(base, options.only);
  b.compare<bool>(Facet::permutations, "permutations", "Optimised vs raw permutations" + at, {false, true},
                  [](RendererOptions& o, const bool& raw) { o.raw_permutations = raw; });
  b.compare<std::uint32_t>(Facet::tile_size, "tile_size", "Tile size 4 vs 8 vs 16" + at, {4, 8, 16},
                           [](RendererOptions& o, const std::uint32_t& t) { o.tile_size = t; });
  b.compare<IndexPath>(Facet::index_path, "index_path", "CPU patching vs GPU-driven index build" + at,
                       {IndexPath::cpu, IndexPath::gpu}, [](RendererOptions& o, const IndexPath& p) { o.path = p; });
  b.compare<bool>(Facet::coalescing, "coalescing", "Coalesced vs uncoalesced tiles" + at, {true, false},
                  [](RendererOptions& o, const bool& c) { o.coalesce = c; });
  // Auto is points wherever the device draws them; triangles is the chapter's two per rectangle.
  b.compare<std::optional<TilePrimitive>>(
      Facet::primitive, "primitive", "Point sprites vs triangle pairs" + at, {std::nullopt, TilePrimitive::triangles},
      [](RendererOptions& o, const std::optional<TilePrimitive>& p) { o.primitive = p; });
  b.compare<FrameSize>(Facet::resolution, "resolution", "Resolution scaling, naive vs classified", options.sizes,
                       [](RendererOptions& o, const FrameSize& s) {
                         o.width = s.width;
                         o.height = s.height;
                       });
  b.compare<bool>(Facet::stages, "stages", "Per-stage cost, naive vs classified" + at, {true},
                  [](RendererOptions&, const bool&) {});
  // SKY and LIGHT_SCATTERING as variants, specialization constants and run-time branches
  // (--light-kinds), in both light passes: the same frame, other pipelines and blobs.
  std::vector<std::pair<LightPass, LightKinds>> kinds;
  for (const std::string& pass : options.light_passes) {
    for (const LightKinds k : {LightKinds::variant, LightKinds::specialization, LightKinds::branch}) {
      kinds.emplace_back(pass == "compute" ? LightPass::compute : LightPass::raster, k);
    }
  }
  b.compare<std::pair<LightPass, LightKinds>>(
      Facet::kinds, "kinds",
      "Feature kinds: SKY and LIGHT_SCATTERING as variants, specialization constants, branches" + at, kinds,
      [](RendererOptions& o, const std::pair<LightPass, LightKinds>& k) {
        o.light_pass = k.first;
        o.light_kinds = k.second;
      });
  // Every light-pass kind, MSAA mode, size, index build and camera: rows grouped in that order.
  struct View {
    std::uint32_t msaa;
    FrameSize size;
    std::string camera;
    IndexPath path;
    LightPass light_pass;
    Baselines baselines;
    bool cull;
  };
  std::vector<View> views;
  for (const std::string& pass : options.light_passes) {
    for (std::uint32_t msaa : options.msaa) {
      for (const FrameSize& size : options.sizes) {
        for (IndexPath path : options.paths) {
          for (const std::string& camera : options.cameras) {
            for (const bool cull : options.culls) {
              views.push_back({msaa, size, camera, path, pass == "compute" ? LightPass::compute : LightPass::raster,
                               options.baselines, cull});
            }
          }
        }
      }
    }
  }
  b.compare<View>(Facet::baselines, "baselines", "Classified vs per-pixel branching (dynamic) vs naive", views,
                  [](RendererOptions& o, const View& v) {
                    o.msaa = v.msaa;
                    o.width = v.size.width;
                    o.height = v.size.height;
                    o.camera = v.camera;
                    o.path = v.path;
                    o.light_pass = v.light_pass;
                    o.baselines = v.baselines;
                    o.cull_batches = v.cull;
                  });
  return b.take();
}

std::string row_label(Facet facet, const Measurement& m) {
  const RendererOptions& o = m.options;
  switch (facet) {
    case Facet::permutations: return fmt::format("{} ({})", o.raw_permutations ? "raw" : "optimised", m.pipelines);
    case Facet::tile_size: return fmt::format("tile {}", o.tile_size);
    case Facet::index_path: return o.path == IndexPath::gpu ? "GPU-driven" : "CPU patching";
    case Facet::coalescing: return o.coalesce ? "coalesced" : "uncoalesced";
    case Facet::primitive: return fmt::format("{} ({})", to_string(m.primitive), o.primitive ? "asked for" : "auto");
    case Facet::resolution:
    case Facet::stages: return fmt::format("{}x{}", o.width, o.height);
    case Facet::kinds: return fmt::format("{} {}", to_string(o.light_pass), to_string(o.light_kinds));
    case Facet::baselines:
      // The index build only where it is not the default, so a CPU-only run keeps its labels.
      return fmt::format("{} {}x {}x{} {}{}{}", to_string(o.light_pass), m.msaa_samples, o.width, o.height, o.camera,
                         o.path == IndexPath::gpu ? " (GPU build)" : "", o.cull_batches ? "" : " (no cull)");
  }
  return m.key;
}

}  // namespace tilelight::sweep
