#include "measurement.h"

#include <fmt/format.h>

#include <chrono>
#include <vector>

namespace tilelight::sweep {

double Measurement::speedup() const {
  const double classified = classified_light();
  return classified > 0 ? timings.naive_light / classified : 0.0;
}

std::string configuration_key(const RendererOptions& o) {
  return fmt::format("{}x{} tile {} {} {} {}", o.width, o.height, o.tile_size,
                     o.path == IndexPath::gpu ? "gpu" : "cpu", o.raw_permutations ? "raw" : "optimised",
                     o.coalesce ? "coalesced" : "uncoalesced");
}

Measurement measure(const Context& context, const Scene& scene, const RendererOptions& options,
                    std::uint32_t frames, std::ostream& progress) {
  const auto start = std::chrono::steady_clock::now();
  Measurement m;
  m.key = configuration_key(options);
  m.options = options;
  m.frames = frames;
  TileRenderer renderer(context, scene, options);
  // The warm-up frame takes the drivers' lazy pipeline compilation out of the timings.
  progress << "  warm-up" << std::flush;
  renderer.render_frame();
  progress << ", frames" << std::flush;
  std::vector<FrameTimings> timings;
  FrameResult last;
  for (std::uint32_t f = 0; f < frames; ++f) {
    last = renderer.render_frame();
    timings.push_back(last.timings);
    progress << ' ' << f + 1 << std::flush;
  }
  m.timings = app::median_timings(timings);
  m.msaa_samples = renderer.msaa_samples();
  m.pipelines = renderer.pipeline_count();
  m.tiles = renderer.grid().tile_count();
  m.primitives_uncoalesced = last.stats.primitives_uncoalesced;
  m.primitives_coalesced = last.stats.primitives_coalesced;
  m.equivalence = app::compare_frames(renderer.read_classified(), renderer.read_naive());
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  progress << fmt::format(": done in {:.1f} s: speed-up {:.2f}x, {} pixels differ\n", took.count(), m.speedup(),
                          m.equivalence.pixels_different);
  return m;
}

}  // namespace tilelight::sweep
