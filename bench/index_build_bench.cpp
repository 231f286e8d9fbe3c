// Benchmark of TileIndexBuilder::build(): the CPU side that turns classified tile IDs into one
// index buffer plus 32 indirect draws. The target is 57,600 tiles (1280x720, tile size 4) in
// <= 50 microseconds median on one core.
//
// The LUT here is synthetic (optimised = raw & 31, raw IDs with bits 0 and 1 both set pruned), a
// stand-in for the generated one so the benchmark does not depend on generated code; what the
// builder costs depends on how often neighbouring tiles share an optimised ID, not on the mapping.

#include "tilelight/tiles/tile_grid.h"
#include "tilelight/tiles/tile_index_builder.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using tilelight::kOptimisedClassCount;
using tilelight::kRawClassCount;

enum Pattern : int { kUniform = 0, kRandom = 1, kSceneLike = 2 };
constexpr const char* kPatternNames[] = {"uniform", "random", "scene"};

bool pruned_raw(std::uint32_t raw) { return (raw & 3u) == 3u; }

std::vector<std::uint8_t> synthetic_lut() {
  std::vector<std::uint8_t> lut(kRawClassCount);
  for (std::uint32_t r = 0; r < kRawClassCount; ++r) lut[r] = static_cast<std::uint8_t>(r & 31u);
  return lut;
}

std::array<bool, kRawClassCount> synthetic_pruned() {
  std::array<bool, kRawClassCount> p{};
  for (std::uint32_t r = 0; r < kRawClassCount; ++r) p[r] = pruned_raw(r);
  return p;
}

// Any valid raw ID, uniformly: the worst case for coalescing.
std::vector<std::uint8_t> random_ids(const tilelight::TileGrid& grid) {
  std::vector<std::uint8_t> valid;
  for (std::uint32_t r = 0; r < kRawClassCount; ++r) {
    if (!pruned_raw(r)) valid.push_back(static_cast<std::uint8_t>(r));
  }
  std::mt19937 rng(1234);
  std::uniform_int_distribution<std::size_t> pick(0, valid.size() - 1);
  std::vector<std::uint8_t> ids(grid.tile_count());
  for (auto& id : ids) id = valid[pick(rng)];
  return ids;
}

// Roughly what a frame looks like: horizontal bands (sky, far, near ground) whose edges do not
// fall on block edges, plus a dozen boxes (objects under other light sets).
std::vector<std::uint8_t> scene_ids(const tilelight::TileGrid& grid) {
  std::vector<std::uint8_t> ids(grid.tile_count());
  for (std::uint32_t y = 0; y < grid.tiles_y; ++y) {
    const std::uint8_t band = y < grid.tiles_y * 3 / 10 ? 0 : y < grid.tiles_y * 6 / 10 ? 5 : 9;
    for (std::uint32_t x = 0; x < grid.tiles_x; ++x) ids[std::size_t{y} * grid.tiles_x + x] = band;
  }
  std::mt19937 rng(99);
  const std::uint8_t box_ids[] = {16, 20, 33, 40, 70, 98};
  for (std::uint32_t box = 0; box < 12; ++box) {
    const std::uint32_t w = 5 + static_cast<std::uint32_t>(rng() % (grid.tiles_x / 6));
    const std::uint32_t h = 5 + static_cast<std::uint32_t>(rng() % (grid.tiles_y / 4));
    const std::uint32_t x0 = static_cast<std::uint32_t>(rng() % (grid.tiles_x - w));
    const std::uint32_t y0 = static_cast<std::uint32_t>(rng() % (grid.tiles_y - h));
    const std::uint8_t id = box_ids[box % std::size(box_ids)];
    for (std::uint32_t y = y0; y < y0 + h; ++y) {
      for (std::uint32_t x = x0; x < x0 + w; ++x) ids[std::size_t{y} * grid.tiles_x + x] = id;
    }
  }
  return ids;
}

std::vector<std::uint8_t> make_ids(const tilelight::TileGrid& grid, int pattern) {
  switch (pattern) {
    case kRandom: return random_ids(grid);
    case kSceneLike: return scene_ids(grid);
    default: return std::vector<std::uint8_t>(grid.tile_count(), 4);
  }
}

// Args: width, height, pattern, coalesce, primitive (0: triangle pairs, 1: points; tile_primitive.h).
void BM_IndexBuild(benchmark::State& state) {
  const auto grid =
      tilelight::TileGrid::make(static_cast<std::uint32_t>(state.range(0)), static_cast<std::uint32_t>(state.range(1)));
  const int pattern = static_cast<int>(state.range(2));
  const bool coalesce = state.range(3) != 0;
  const auto primitive = state.range(4) != 0 ? tilelight::TilePrimitive::points : tilelight::TilePrimitive::triangles;
  const std::vector<std::uint8_t> blocked = tilelight::to_blocked(grid, make_ids(grid, pattern));
  const std::vector<std::uint8_t> lut = synthetic_lut();
  const std::array<bool, kRawClassCount> pruned = synthetic_pruned();
  tilelight::TileIndexBuilder builder(grid, lut, pruned, kOptimisedClassCount, primitive);
  std::vector<std::uint32_t> indices(grid.max_index_count());
  std::array<tilelight::DrawRecord, kOptimisedClassCount> draws{};

  tilelight::IndexBuildStats stats;
  for (auto _ : state) {
    stats = builder.build(blocked, coalesce, indices, draws);
    benchmark::DoNotOptimize(stats);
    benchmark::DoNotOptimize(indices.data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(kPatternNames[pattern]);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * grid.tile_count());
  state.counters["tiles_per_rect"] = static_cast<double>(stats.tiles) / static_cast<double>(stats.rectangles_coalesced);
  state.counters["rects"] = static_cast<double>(stats.rectangles_coalesced);
  state.counters["prims"] = static_cast<double>(stats.primitives_coalesced);
}

void index_build_args(benchmark::internal::Benchmark* b) {
  b->ArgNames({"w", "h", "pattern", "coalesce", "points"});
  for (const auto& [w, h] : {std::array<std::int64_t, 2>{1280, 720}, std::array<std::int64_t, 2>{1920, 1080}}) {
    for (std::int64_t pattern : {kUniform, kRandom, kSceneLike}) {
      for (std::int64_t coalesce : {1, 0}) {
        for (std::int64_t points : {0, 1}) b->Args({w, h, pattern, coalesce, points});
      }
    }
  }
  b->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_IndexBuild)->Apply(index_build_args);

}  // namespace

BENCHMARK_MAIN();
