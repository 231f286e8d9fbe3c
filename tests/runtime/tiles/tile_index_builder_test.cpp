#include "tilelight/tiles/tile_index_builder.h"
#include "tilelight/base/error.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/tiles/tile_primitive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <ostream>
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace tilelight {
namespace {

// The tests' own LUTs (not the generated one). With 32 draw classes: optimised = raw & 31, so raw
// IDs 32 apart share an optimised ID; with 128: the identity, as when the raw permutations are
// drawn. Raw IDs with bits 0 and 1 both set are pruned.
std::uint8_t class_of(std::uint8_t raw, std::uint32_t class_count) {
  return class_count == kOptimisedClassCount ? static_cast<std::uint8_t>(raw & 31u) : raw;
}

std::vector<std::uint8_t> lut_for(std::uint32_t class_count) {
  std::vector<std::uint8_t> lut(kRawClassCount);
  for (std::uint32_t r = 0; r < kRawClassCount; ++r) lut[r] = class_of(static_cast<std::uint8_t>(r), class_count);
  return lut;
}

std::vector<std::uint8_t> test_lut() { return lut_for(kOptimisedClassCount); }

bool is_pruned(std::uint32_t raw) { return (raw & 3u) == 3u; }

// std::vector<bool> has no contiguous storage, so keep a plain bool array.
const std::array<bool, kRawClassCount>& test_pruned() {
  static const std::array<bool, kRawClassCount> pruned = [] {
    std::array<bool, kRawClassCount> p{};
    for (std::uint32_t r = 0; r < kRawClassCount; ++r) p[r] = is_pruned(r);
    return p;
  }();
  return pruned;
}

std::vector<std::uint8_t> valid_raw_ids() {
  std::vector<std::uint8_t> ids;
  for (std::uint32_t r = 0; r < kRawClassCount; ++r) {
    if (!is_pruned(r)) ids.push_back(static_cast<std::uint8_t>(r));
  }
  return ids;
}

constexpr std::uint32_t kUnwritten = 0xDEADBEEFu;  // what build_row_major() fills the index buffer with

struct Built {
  IndexBuildStats stats;
  std::vector<std::uint32_t> indices;
  std::vector<DrawRecord> draws = std::vector<DrawRecord>(kOptimisedClassCount);
};

Built build_row_major(const TileGrid& grid, const std::vector<std::uint8_t>& row_major, bool coalesce,
                      std::uint32_t class_count = kOptimisedClassCount,
                      TilePrimitive primitive = TilePrimitive::triangles) {
  const std::vector<std::uint8_t> lut = lut_for(class_count);
  TileIndexBuilder builder(grid, lut, test_pruned(), class_count, primitive);
  Built out;
  out.indices.assign(grid.max_index_count(), kUnwritten);
  out.draws.resize(class_count);
  out.stats = builder.build(to_blocked(grid, row_major), coalesce, out.indices, out.draws);
  return out;
}

struct Rectangle {
  std::uint32_t x0, y0, x1, y1;
};

// Decodes one rectangle from its 6 indices, checking the documented triangle order.
Rectangle decode(const TileGrid& grid, const std::uint32_t* idx) {
  const std::uint32_t stride = grid.tiles_x + 1;
  const Rectangle r{idx[0] % stride, idx[0] / stride, idx[4] % stride, idx[4] / stride};
  EXPECT_EQ(idx[1], grid.vertex_index(r.x1, r.y0));
  EXPECT_EQ(idx[2], grid.vertex_index(r.x0, r.y1));
  EXPECT_EQ(idx[3], idx[1]);
  EXPECT_EQ(idx[5], idx[2]);
  return r;
}

// Rectangles and points per draw class by the coalescing rule, worked out independently on the
// row-major IDs. A point is a square rectangle, or one tile of any other: a run inside a block row
// is one tile high, so it is drawn as one point per tile whatever its length.
struct Expected {
  std::array<std::uint32_t, kMaxDrawClasses> rects{}, points{};
};

Expected expected_counts(const TileGrid& grid, const std::vector<std::uint8_t>& rm, bool coalesce,
                         std::uint32_t class_count = kOptimisedClassCount) {
  Expected counts;
  auto id_at = [&](std::uint32_t x, std::uint32_t y) {
    return class_of(rm[std::size_t{y} * grid.tiles_x + x], class_count);
  };
  for (std::uint32_t by = 0; by < grid.blocks_y; ++by) {
    for (std::uint32_t bx = 0; bx < grid.blocks_x; ++bx) {
      const std::uint32_t x_end = std::min(grid.tiles_x, bx * 4 + 4);
      const std::uint32_t y_end = std::min(grid.tiles_y, by * 4 + 4);
      bool uniform = true;
      for (std::uint32_t y = by * 4; y < y_end; ++y) {
        for (std::uint32_t x = bx * 4; x < x_end; ++x) uniform = uniform && id_at(x, y) == id_at(bx * 4, by * 4);
      }
      if (coalesce && uniform) {
        const std::uint32_t w = x_end - bx * 4, h = y_end - by * 4;
        ++counts.rects[id_at(bx * 4, by * 4)];
        counts.points[id_at(bx * 4, by * 4)] += w == h ? 1 : w * h;
        continue;
      }
      for (std::uint32_t y = by * 4; y < y_end; ++y) {
        for (std::uint32_t x = bx * 4; x < x_end; ++x) {
          if (!coalesce || x == bx * 4 || id_at(x, y) != id_at(x - 1, y)) ++counts.rects[id_at(x, y)];
          ++counts.points[id_at(x, y)];
        }
      }
    }
  }
  return counts;
}

// Decodes one point into the square of tiles it covers (tile_primitive.h).
Rectangle decode_point(const TileGrid& grid, std::uint32_t index) {
  const std::uint32_t stride = grid.tiles_x + 1;
  const std::uint32_t corner = point_corner_vertex(index);
  const std::uint32_t side = point_side_tiles(index);
  return {corner % stride, corner / stride, corner % stride + side, corner / stride + side};
}

// Checks every structural promise of build() for either primitive: the draws are contiguous, at
// the prefix sums of stats.primitives; each primitive covers a rectangle inside the grid and
// inside one block (a point wider than a tile: its whole uniform block); each tile is covered
// exactly once, by a primitive of its own class; a class's primitives keep block order; the
// counts follow the coalescing rule (expected_counts); nothing is written past index_count.
void verify_build(const TileGrid& grid, const std::vector<std::uint8_t>& rm, const Built& b, bool coalesce,
                  std::uint32_t class_count, TilePrimitive primitive) {
  ASSERT_EQ(b.draws.size(), class_count);
  const std::uint32_t per_primitive = indices_per_primitive(primitive);
  std::uint32_t next_first = 0;
  std::vector<int> coverage(grid.tile_count(), 0);
  std::array<std::uint32_t, kMaxDrawClasses> tiles_per_class{};
  for (std::uint32_t id = 0; id < class_count; ++id) {
    const DrawRecord& d = b.draws[id];
    EXPECT_EQ(d.instanceCount, 1u);
    EXPECT_EQ(d.vertexOffset, 0);
    EXPECT_EQ(d.firstInstance, 0u);
    ASSERT_EQ(d.firstIndex, next_first) << "draw " << id << " does not start at the prefix sum";
    ASSERT_EQ(d.indexCount, b.stats.primitives[id] * per_primitive) << "draw " << id;
    next_first += d.indexCount;
    std::uint64_t last_key = 0;
    for (std::uint32_t k = d.firstIndex; k < d.firstIndex + d.indexCount; k += per_primitive) {
      const Rectangle r =
          primitive == TilePrimitive::points ? decode_point(grid, b.indices[k]) : decode(grid, &b.indices[k]);
      ASSERT_LT(r.x0, r.x1);
      ASSERT_LT(r.y0, r.y1);
      ASSERT_LE(r.x1, grid.tiles_x) << "primitive at index " << k << " leaves the grid";
      ASSERT_LE(r.y1, grid.tiles_y) << "primitive at index " << k << " leaves the grid";
      ASSERT_EQ(r.x0 / 4, (r.x1 - 1) / 4) << "primitive at index " << k << " crosses a block edge";
      ASSERT_EQ(r.y0 / 4, (r.y1 - 1) / 4) << "primitive at index " << k << " crosses a block edge";
      const bool one_tile = r.x1 - r.x0 == 1 && r.y1 - r.y0 == 1;
      if (!coalesce) {
        ASSERT_TRUE(one_tile) << "a primitive wider than a tile without coalescing";
      }
      if (primitive == TilePrimitive::points && !one_tile) {
        ASSERT_EQ(r.x1, std::min(r.x0 + 4, grid.tiles_x)) << "point at index " << k << " is not its whole block";
        ASSERT_EQ(r.y1, std::min(r.y0 + 4, grid.tiles_y)) << "point at index " << k << " is not its whole block";
      }
      const std::uint64_t block = std::uint64_t{r.y0 / 4} * grid.blocks_x + r.x0 / 4;
      const std::uint64_t key = ((block * 4 + r.y0 % 4) * 4 + r.x0 % 4) + 1;
      ASSERT_GT(key, last_key) << "primitives of class " << id << " are not in block order";
      last_key = key;
      for (std::uint32_t y = r.y0; y < r.y1; ++y) {
        for (std::uint32_t x = r.x0; x < r.x1; ++x) {
          const std::size_t t = std::size_t{y} * grid.tiles_x + x;
          ++coverage[t];
          ASSERT_EQ(class_of(rm[t], class_count), id) << "tile (" << x << ", " << y << ") drawn by the wrong class";
          ++tiles_per_class[id];
        }
      }
    }
  }
  for (std::size_t t = 0; t < coverage.size(); ++t) ASSERT_EQ(coverage[t], 1) << "tile " << t;
  EXPECT_EQ(next_first, b.stats.index_count);
  EXPECT_EQ(b.stats.index_count, b.stats.primitives_coalesced * per_primitive);
  for (std::size_t i = b.stats.index_count; i < b.indices.size(); ++i) {
    ASSERT_EQ(b.indices[i], kUnwritten) << "wrote past index_count at " << i;
  }
  EXPECT_EQ(b.stats.class_tiles, tiles_per_class);
  const Expected expected = expected_counts(grid, rm, coalesce, class_count);
  EXPECT_EQ(b.stats.rectangles, expected.rects);
  EXPECT_EQ(b.stats.primitives, primitive == TilePrimitive::points ? expected.points : expected.rects);
  std::uint32_t rectangles = 0;
  for (std::uint32_t n : expected.rects) rectangles += n;
  EXPECT_EQ(b.stats.rectangles_coalesced, rectangles);
  EXPECT_EQ(b.stats.tiles, grid.tile_count());
  EXPECT_EQ(b.stats.primitives_uncoalesced, grid.tile_count());
  if (!coalesce) {
    EXPECT_EQ(b.stats.primitives_coalesced, grid.tile_count());
  }
}

void verify(const TileGrid& grid, const std::vector<std::uint8_t>& rm, const Built& b, bool coalesce) {
  verify_build(grid, rm, b, coalesce, kOptimisedClassCount, TilePrimitive::triangles);
}

void verify_points(const TileGrid& grid, const std::vector<std::uint8_t>& rm, const Built& b, bool coalesce,
                   std::uint32_t class_count) {
  verify_build(grid, rm, b, coalesce, class_count, TilePrimitive::points);
}

std::vector<std::uint8_t> random_ids(const TileGrid& grid, std::uint32_t seed, std::size_t palette) {
  const std::vector<std::uint8_t> valid = valid_raw_ids();
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, std::min(palette, valid.size()) - 1);
  std::vector<std::uint8_t> ids(grid.tile_count());
  for (auto& id : ids) id = valid[pick(rng)];
  return ids;
}

// ---- structural checks on many grids and patterns ----

struct Size {
  std::uint32_t width, height, tile_size;
};

// Readable, stable test names (gtest would otherwise print the raw bytes of the structs).
void PrintTo(const Size& s, std::ostream* os) { *os << s.width << "x" << s.height << "_ts" << s.tile_size; }

class RandomIds : public ::testing::TestWithParam<std::tuple<Size, bool, std::size_t>> {};

TEST_P(RandomIds, CoverEveryTileOnceWithItsOptimisedId) {
  const auto [size, coalesce, palette] = GetParam();
  const TileGrid grid = TileGrid::make(size.width, size.height, size.tile_size);
  const std::vector<std::uint8_t> ids = random_ids(grid, size.width * 31u + size.height, palette);
  const Built b = build_row_major(grid, ids, coalesce);
  verify(grid, ids, b, coalesce);
}

INSTANTIATE_TEST_SUITE_P(
    Grids, RandomIds,
    ::testing::Combine(::testing::Values(Size{1280, 720, 4}, Size{1283, 719, 4}, Size{1, 1, 4}, Size{5, 3, 4},
                                         Size{37, 23, 8}, Size{1920, 1080, 16}, Size{61, 45, 4}),
                       ::testing::Bool(),
                       // A palette of 2 raw IDs makes uniform blocks and runs likely; 96 makes them rare.
                       ::testing::Values(std::size_t{2}, std::size_t{5}, std::size_t{96})));

TEST(TileIndexBuilder, UniformFrameIsOneRectanglePerBlock) {
  const TileGrid grid = TileGrid::make(1280, 720);
  const std::vector<std::uint8_t> ids(grid.tile_count(), 37);  // optimised ID 5
  const Built b = build_row_major(grid, ids, true);
  verify(grid, ids, b, true);
  EXPECT_EQ(b.stats.primitives_coalesced, 3600u);
  EXPECT_EQ(b.stats.rectangles[5], 3600u);
  EXPECT_EQ(b.stats.class_tiles[5], 57600u);
  EXPECT_EQ(b.draws[5].indexCount, 21600u);
  EXPECT_EQ(b.draws[5].firstIndex, 0u);
  for (std::uint32_t id = 0; id < kOptimisedClassCount; ++id) {
    if (id == 5) continue;
    EXPECT_EQ(b.draws[id].indexCount, 0u);
    EXPECT_EQ(b.draws[id].instanceCount, 1u);
    EXPECT_EQ(b.draws[id].firstIndex, id < 5 ? 0u : 21600u);
  }
}

TEST(TileIndexBuilder, UniformFrameWithoutCoalescingIsOneRectanglePerTile) {
  const TileGrid grid = TileGrid::make(1280, 720);
  const std::vector<std::uint8_t> ids(grid.tile_count(), 37);
  const Built b = build_row_major(grid, ids, false);
  verify(grid, ids, b, false);
  EXPECT_EQ(b.stats.primitives_coalesced, 57600u);
  EXPECT_EQ(b.draws[5].indexCount, 57600u * 6u);
}

TEST(TileIndexBuilder, UniformOddFrameCoalescesPartialBlocks) {
  const TileGrid grid = TileGrid::make(1283, 719);  // 81x45 blocks, the last column partial
  const std::vector<std::uint8_t> ids(grid.tile_count(), 0);
  const Built b = build_row_major(grid, ids, true);
  verify(grid, ids, b, true);
  EXPECT_EQ(b.stats.primitives_coalesced, 81u * 45u);
}

TEST(TileIndexBuilder, DifferentRawIdsWithOneOptimisedIdCoalesce) {
  const TileGrid grid = TileGrid::make(64, 64);  // 16x16 tiles, 4x4 blocks
  std::vector<std::uint8_t> ids(grid.tile_count());
  const std::uint8_t same[] = {1, 33, 65, 97};  // all map to optimised ID 1
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = same[i % 4];
  const Built b = build_row_major(grid, ids, true);
  verify(grid, ids, b, true);
  EXPECT_EQ(b.stats.primitives_coalesced, 16u);
  EXPECT_EQ(b.stats.rectangles[1], 16u);
}

struct Pattern {
  const char* name;
  std::uint8_t (*raw)(std::uint32_t x, std::uint32_t y);
  std::uint32_t rects_per_block;
};

void PrintTo(const Pattern& p, std::ostream* os) { *os << p.name; }

class RowPatterns : public ::testing::TestWithParam<Pattern> {};

TEST_P(RowPatterns, RectangleCountPerBlock) {
  const Pattern& p = GetParam();
  const TileGrid grid = TileGrid::make(320, 192);  // 80x48 tiles, 20x12 full blocks
  std::vector<std::uint8_t> ids(grid.tile_count());
  for (std::uint32_t y = 0; y < grid.tiles_y; ++y) {
    for (std::uint32_t x = 0; x < grid.tiles_x; ++x) ids[std::size_t{y} * grid.tiles_x + x] = p.raw(x, y);
  }
  const Built b = build_row_major(grid, ids, true);
  verify(grid, ids, b, true);
  EXPECT_EQ(b.stats.primitives_coalesced, grid.block_count() * p.rects_per_block) << p.name;
}

INSTANTIATE_TEST_SUITE_P(
    Patterns, RowPatterns,
    ::testing::Values(
        Pattern{"halves", [](std::uint32_t x, std::uint32_t) { return std::uint8_t(x % 4 < 2 ? 4 : 8); }, 8},
        Pattern{"stripes", [](std::uint32_t x, std::uint32_t) { return std::uint8_t(x % 2 ? 1 : 2); }, 16},
        Pattern{"bands", [](std::uint32_t, std::uint32_t y) { return std::uint8_t(y % 4 * 4); }, 4},
        Pattern{"aab_a", [](std::uint32_t x, std::uint32_t) { return std::uint8_t(x % 4 == 2 ? 9 : 0); }, 12},
        Pattern{"one_odd_tile",
                [](std::uint32_t x, std::uint32_t y) { return std::uint8_t(x % 4 == 1 && y % 4 == 2 ? 6 : 5); }, 6},
        Pattern{"same_opt_rows",
                [](std::uint32_t x, std::uint32_t y) { return std::uint8_t(y % 2 ? 40 + x % 2 * 32 : 8); }, 1}));

TEST(TileIndexBuilder, ExactIndicesForATwoTileFrame) {
  const TileGrid grid = TileGrid::make(8, 4);  // 2x1 tiles; corners 3 per row
  const Built same = build_row_major(grid, {2, 34}, true);
  EXPECT_EQ(same.stats.primitives_coalesced, 1u);
  EXPECT_EQ(std::vector<std::uint32_t>(same.indices.begin(), same.indices.begin() + 6),
            (std::vector<std::uint32_t>{0, 2, 3, 2, 5, 3}));
  for (std::size_t i = 6; i < same.indices.size(); ++i) {
    EXPECT_EQ(same.indices[i], 0xDEADBEEFu) << "wrote past index_count at " << i;
  }

  const Built split = build_row_major(grid, {2, 1}, true);
  EXPECT_EQ(split.stats.primitives_coalesced, 2u);
  // ID 1 (tile 1) comes first in the buffer, then ID 2 (tile 0).
  EXPECT_EQ(std::vector<std::uint32_t>(split.indices.begin(), split.indices.begin() + 12),
            (std::vector<std::uint32_t>{1, 2, 4, 2, 5, 4, 0, 1, 3, 1, 4, 3}));
  EXPECT_EQ(split.draws[1].firstIndex, 0u);
  EXPECT_EQ(split.draws[2].firstIndex, 6u);
}

TEST(TileIndexBuilder, PartialBlockBecomesOneRectangle) {
  const TileGrid grid = TileGrid::make(20, 12);  // 5x3 tiles: a 4x3 block and a 1x3 block
  const std::vector<std::uint8_t> ids(grid.tile_count(), 0);
  const Built b = build_row_major(grid, ids, true);
  verify(grid, ids, b, true);
  ASSERT_EQ(b.stats.primitives_coalesced, 2u);
  const Rectangle first = decode(grid, &b.indices[0]);
  const Rectangle second = decode(grid, &b.indices[6]);
  EXPECT_EQ(std::tie(first.x0, first.y0, first.x1, first.y1), std::make_tuple(0u, 0u, 4u, 3u));
  EXPECT_EQ(std::tie(second.x0, second.y0, second.x1, second.y1), std::make_tuple(4u, 0u, 5u, 3u));
}

TEST(TileIndexBuilder, PaddingSlotsAreNotRead) {
  const TileGrid grid = TileGrid::make(23, 9);  // 6x3 tiles: partial blocks
  const std::vector<std::uint8_t> ids = random_ids(grid, 7, 3);
  std::vector<std::uint8_t> blocked = to_blocked(grid, ids);
  for (auto& v : blocked) {
    if (v == kNoTile) v = 3;  // a pruned raw ID: would throw if the builder read it
  }
  const std::vector<std::uint8_t> lut = test_lut();
  TileIndexBuilder builder(grid, lut, test_pruned());
  std::vector<std::uint32_t> indices(grid.max_index_count());
  std::array<DrawRecord, kOptimisedClassCount> draws{};
  const IndexBuildStats stats = builder.build(blocked, true, indices, draws);
  EXPECT_EQ(stats.rectangles, expected_counts(grid, ids, true).rects);
}

TEST(TileIndexBuilder, RebuildingReusesTheScratchCorrectly) {
  const TileGrid grid = TileGrid::make(61, 45);
  const std::vector<std::uint8_t> lut = test_lut();
  TileIndexBuilder builder(grid, lut, test_pruned());
  for (std::uint32_t round = 0; round < 3; ++round) {
    const std::vector<std::uint8_t> ids = random_ids(grid, round, round == 1 ? 96 : 2);
    Built b;
    b.indices.assign(grid.max_index_count(), kUnwritten);
    b.stats = builder.build(to_blocked(grid, ids), round != 2, b.indices, b.draws);
    verify(grid, ids, b, round != 2);
  }
}

TEST(TileIndexBuilder, EmptyPrunedSetAllowsEveryRawId) {
  const TileGrid grid = TileGrid::make(8, 8);
  const std::vector<std::uint8_t> lut = test_lut();
  TileIndexBuilder builder(grid, lut, {});
  const std::vector<std::uint8_t> ids(grid.tile_count(), 3);
  std::vector<std::uint32_t> indices(grid.max_index_count());
  std::array<DrawRecord, kOptimisedClassCount> draws{};
  EXPECT_EQ(builder.build(to_blocked(grid, ids), true, indices, draws).rectangles[3], 1u);
}

// ---- points (TilePrimitive::points) ----

class RandomIdsAsPoints : public ::testing::TestWithParam<std::tuple<Size, bool>> {};

TEST_P(RandomIdsAsPoints, CoverEveryTileOnceWithAPointOfItsClass) {
  const auto [size, coalesce] = GetParam();
  const TileGrid grid = TileGrid::make(size.width, size.height, size.tile_size);
  // Palettes and class counts in one process: each build takes microseconds, a test process far longer.
  for (const std::size_t palette : {std::size_t{2}, std::size_t{5}, std::size_t{96}}) {
    for (const std::uint32_t class_count : {kOptimisedClassCount, kRawClassCount}) {
      SCOPED_TRACE(testing::Message() << "palette " << palette << ", " << class_count << " classes");
      const std::vector<std::uint8_t> ids = random_ids(grid, size.width * 31u + size.height, palette);
      const Built points = build_row_major(grid, ids, coalesce, class_count, TilePrimitive::points);
      verify_points(grid, ids, points, coalesce, class_count);

      // Triangles find the same rectangles; only how they are drawn differs.
      const Built triangles = build_row_major(grid, ids, coalesce, class_count, TilePrimitive::triangles);
      verify_build(grid, ids, triangles, coalesce, class_count, TilePrimitive::triangles);
      EXPECT_EQ(triangles.stats.rectangles, points.stats.rectangles);
      EXPECT_EQ(triangles.stats.class_tiles, points.stats.class_tiles);
      EXPECT_EQ(triangles.stats.rectangles_coalesced, points.stats.rectangles_coalesced);
      EXPECT_EQ(triangles.stats.primitives_coalesced, triangles.stats.rectangles_coalesced);
    }
  }
}

// The grids of RandomIds, and partial blocks of 2x2 and 3x3 tiles (square, so one point each);
// palettes of 2 raw IDs make uniform blocks and runs likely, 96 rare; 32 classes merge raw IDs
// 32 apart, 128 keep every raw ID its own class.
INSTANTIATE_TEST_SUITE_P(Grids, RandomIdsAsPoints,
                         ::testing::Combine(::testing::Values(Size{1280, 720, 4}, Size{1283, 719, 4}, Size{1, 1, 4},
                                                              Size{5, 3, 4}, Size{37, 23, 8}, Size{1920, 1080, 16},
                                                              Size{61, 45, 4}, Size{24, 24, 4}, Size{12, 12, 4}),
                                            ::testing::Bool()));

// Exact index buffers for small frames (tile size 4, coalescing on, the 32-class LUT).
struct PointLayout {
  const char* name;
  std::uint32_t width, height;
  std::uint8_t (*raw)(std::uint32_t x, std::uint32_t y);
  std::vector<std::uint32_t> indices;           // the whole written index buffer
  std::vector<std::uint32_t> points_per_class;  // draws[0..n).indexCount; later classes draw nothing
  std::uint32_t rectangles;
};

void PrintTo(const PointLayout& c, std::ostream* os) { *os << c.name; }

class PointLayouts : public ::testing::TestWithParam<PointLayout> {};

TEST_P(PointLayouts, ExactIndicesAndDraws) {
  const PointLayout& c = GetParam();
  const TileGrid grid = TileGrid::make(c.width, c.height);
  std::vector<std::uint8_t> ids(grid.tile_count());
  for (std::uint32_t y = 0; y < grid.tiles_y; ++y) {
    for (std::uint32_t x = 0; x < grid.tiles_x; ++x) ids[std::size_t{y} * grid.tiles_x + x] = c.raw(x, y);
  }
  const Built b = build_row_major(grid, ids, true, kOptimisedClassCount, TilePrimitive::points);
  verify_points(grid, ids, b, true, kOptimisedClassCount);
  ASSERT_EQ(b.stats.index_count, c.indices.size());
  EXPECT_EQ(std::vector<std::uint32_t>(b.indices.begin(), b.indices.begin() + b.stats.index_count), c.indices);
  std::uint32_t first = 0;
  for (std::uint32_t id = 0; id < kOptimisedClassCount; ++id) {
    const std::uint32_t count = id < c.points_per_class.size() ? c.points_per_class[id] : 0;
    EXPECT_EQ(b.draws[id].indexCount, count) << "class " << id;
    EXPECT_EQ(b.draws[id].firstIndex, first) << "class " << id;
    first += count;
  }
  EXPECT_EQ(b.stats.rectangles_coalesced, c.rectangles);
}

std::uint8_t all_zero(std::uint32_t, std::uint32_t) { return 0; }

INSTANTIATE_TEST_SUITE_P(
    Frames, PointLayouts,
    ::testing::Values(
        // 4x4 tiles: one uniform block is one point of side 4.
        PointLayout{"full_block", 16, 16, all_zero, {point_index(0, 4)}, {1}, 1},
        // Raw IDs 0 and 32 share class 0: the block is uniform after the LUT.
        PointLayout{"full_block_two_raw_ids",
                    16,
                    16,
                    [](std::uint32_t x, std::uint32_t) { return std::uint8_t(x % 2 * 32); },
                    {point_index(0, 4)},
                    {1},
                    1},
        PointLayout{"two_blocks", 32, 16, all_zero, {point_index(0, 4), point_index(4, 4)}, {2}, 2},
        // 3x3 tiles: a partial block that is square is still one point.
        PointLayout{"partial_3x3", 12, 12, all_zero, {point_index(0, 3)}, {1}, 1},
        PointLayout{"one_tile", 1, 1, all_zero, {point_index(0, 1)}, {1}, 1},
        // 6x6 tiles, corner stride 7: a 4x4 block, a 2x4 and a 4x2 one (a point per tile, row-major),
        // then the 2x2 corner block, at corner (4, 4) = 32, as one point of side 2.
        PointLayout{
            "partial_2x2_corner",
            24,
            24,
            all_zero,
            {point_index(0, 4), 4, 5, 11, 12, 18, 19, 25, 26, 28, 29, 30, 31, 35, 36, 37, 38, point_index(32, 2)},
            {18},
            4},
        // 5x3 tiles, stride 6: a 4x3 block and a 1x3 block, neither square.
        PointLayout{
            "partial_4x3_and_1x3", 20, 12, all_zero, {0, 1, 2, 3, 6, 7, 8, 9, 12, 13, 14, 15, 4, 10, 16}, {15}, 2},
        // 4x4 tiles, stride 5: tile (3, 0) is class 1, so row 0 is a run of three class-0 tiles (three
        // points of side 1) and rows 1-3 are runs of four (four points each).
        PointLayout{"row_run_of_three",
                    16,
                    16,
                    [](std::uint32_t x, std::uint32_t y) { return std::uint8_t(x == 3 && y == 0 ? 1 : 0); },
                    {0, 1, 2, 5, 6, 7, 8, 10, 11, 12, 13, 15, 16, 17, 18, point_index(3, 1)},
                    {15, 1},
                    5}),
    [](const ::testing::TestParamInfo<PointLayout>& param_info) { return std::string(param_info.param.name); });

TEST(TileIndexBuilder, UniformFrameIsOnePointPerBlock) {
  const TileGrid grid = TileGrid::make(1280, 720);
  const std::vector<std::uint8_t> ids(grid.tile_count(), 37);  // class 5
  const Built b = build_row_major(grid, ids, true, kOptimisedClassCount, TilePrimitive::points);
  verify_points(grid, ids, b, true, kOptimisedClassCount);
  EXPECT_EQ(b.stats.primitives_coalesced, 3600u);
  EXPECT_EQ(b.stats.rectangles_coalesced, 3600u);
  EXPECT_EQ(b.stats.primitives[5], 3600u);
  EXPECT_EQ(b.draws[5].indexCount, 3600u);
  for (std::uint32_t k = 0; k < b.stats.index_count; ++k) ASSERT_EQ(point_side_tiles(b.indices[k]), 4u) << k;
}

TEST(TileIndexBuilder, UniformFrameWithoutCoalescingIsOnePointPerTile) {
  const TileGrid grid = TileGrid::make(1280, 720);
  const std::vector<std::uint8_t> ids(grid.tile_count(), 37);
  const Built b = build_row_major(grid, ids, false, kOptimisedClassCount, TilePrimitive::points);
  verify_points(grid, ids, b, false, kOptimisedClassCount);
  EXPECT_EQ(b.stats.primitives_coalesced, 57600u);
  EXPECT_EQ(b.stats.rectangles_coalesced, 57600u);
  EXPECT_EQ(b.draws[5].indexCount, 57600u);
}

TEST(TileIndexBuilder, RebuildingPointsReusesTheScratchCorrectly) {
  const TileGrid grid = TileGrid::make(61, 45);
  const std::vector<std::uint8_t> lut = test_lut();
  TileIndexBuilder builder(grid, lut, test_pruned(), kOptimisedClassCount, TilePrimitive::points);
  EXPECT_EQ(builder.primitive(), TilePrimitive::points);
  for (std::uint32_t round = 0; round < 3; ++round) {
    const std::vector<std::uint8_t> ids = random_ids(grid, round, round == 1 ? 96 : 2);
    Built b;
    b.indices.assign(grid.max_index_count(), kUnwritten);
    b.stats = builder.build(to_blocked(grid, ids), round != 2, b.indices, b.draws);
    verify_points(grid, ids, b, round != 2, kOptimisedClassCount);
  }
}

// ---- errors ----

std::string build_error(const TileGrid& grid, std::vector<std::uint8_t> blocked, std::size_t index_count,
                        std::size_t draw_count) {
  const std::vector<std::uint8_t> lut = test_lut();
  TileIndexBuilder builder(grid, lut, test_pruned());
  std::vector<std::uint32_t> indices(index_count, 0x12345678u);
  std::vector<DrawRecord> draws(draw_count, DrawRecord{7, 7, 7, 7, 7});
  try {
    (void)builder.build(blocked, true, indices, draws);
  } catch (const Error& e) {
    // Nothing is written before the input is known to be valid.
    for (std::uint32_t v : indices) EXPECT_EQ(v, 0x12345678u);
    for (const auto& d : draws) EXPECT_EQ(d.indexCount, 7u);
    return e.what();
  }
  return "no error";
}

struct BadTile {
  std::uint32_t width, height, tile_x, tile_y;
  std::uint8_t value;
  bool coalesce_uniform;  // fill the frame with one ID so the raw-uniform fast path is hit
  const char* message;
};

void PrintTo(const BadTile& c, std::ostream* os) {
  *os << c.width << "x" << c.height << "_tile_" << c.tile_x << "_" << c.tile_y << "_id_" << int{c.value}
      << (c.coalesce_uniform ? "_uniform" : "_random");
}

class BadTiles : public ::testing::TestWithParam<BadTile> {};

TEST_P(BadTiles, NameTheTileAndValue) {
  const BadTile& c = GetParam();
  const TileGrid grid = TileGrid::make(c.width, c.height);
  std::vector<std::uint8_t> ids =
      c.coalesce_uniform ? std::vector<std::uint8_t>(grid.tile_count(), 4) : random_ids(grid, 11, 96);
  ids[std::size_t{c.tile_y} * grid.tiles_x + c.tile_x] = c.value;
  EXPECT_EQ(build_error(grid, to_blocked(grid, ids), grid.max_index_count(), kOptimisedClassCount), c.message);
}

INSTANTIATE_TEST_SUITE_P(
    Errors, BadTiles,
    ::testing::Values(
        BadTile{1280, 720, 12, 7, 3, false, "tile (12, 7): raw ID 3 is impossible (a pruned class)"},
        BadTile{1280, 720, 12, 7, 200, false, "tile (12, 7): raw ID 200 is out of range (0..127)"},
        BadTile{1280, 720, 12, 7, 128, true, "tile (12, 7): raw ID 128 is out of range (0..127)"},
        BadTile{1280, 720, 319, 179, kNoTile, false, "tile (319, 179): raw ID 255 is out of range (0..127)"},
        BadTile{1283, 719, 320, 5, 127, false, "tile (320, 5): raw ID 127 is impossible (a pruned class)"},
        BadTile{1283, 719, 320, 179, kNoTile, true, "tile (320, 179): raw ID 255 is out of range (0..127)"}));

TEST(TileIndexBuilder, UniformPrunedBlockIsRejected) {
  const TileGrid grid = TileGrid::make(64, 64);
  const std::vector<std::uint8_t> ids(grid.tile_count(), 7);
  EXPECT_EQ(build_error(grid, to_blocked(grid, ids), grid.max_index_count(), kOptimisedClassCount),
            "tile (0, 0): raw ID 7 is impossible (a pruned class)");
}

TEST(TileIndexBuilder, RejectsWrongBufferSizes) {
  const TileGrid grid = TileGrid::make(20, 12);  // 5x3 tiles, 2 blocks, 90 indices
  const std::vector<std::uint8_t> ok = to_blocked(grid, std::vector<std::uint8_t>(grid.tile_count(), 0));
  EXPECT_EQ(build_error(grid, std::vector<std::uint8_t>(31, 0), 90, 32),
            "TileIndexBuilder::build: expected 32 blocked raw ID bytes, got 31");
  EXPECT_EQ(build_error(grid, ok, 89, 32), "TileIndexBuilder::build: the index buffer holds 89 indices, needs 90");
  EXPECT_EQ(build_error(grid, ok, 90, 31), "TileIndexBuilder::build: expected 32 draw records, got 31");
  EXPECT_EQ(build_error(grid, ok, 91, 32), "no error");
}

TEST(TileIndexBuilder, ConstructorRejectsBadTables) {
  const TileGrid grid = TileGrid::make(8, 8);
  const std::array<bool, kRawClassCount> none{};
  const std::array<bool, 5> short_pruned{};
  std::vector<std::uint8_t> lut = test_lut();
  auto message = [&](std::span<const std::uint8_t> l, std::span<const bool> p) -> std::string {
    try {
      TileIndexBuilder builder(grid, l, p);
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message(std::span(lut).first(127), none), "TileIndexBuilder: the LUT must have 128 entries (got 127)");
  EXPECT_EQ(message(lut, short_pruned), "TileIndexBuilder: the pruned set must have 128 entries or none (got 5)");
  lut[77] = 32;
  EXPECT_EQ(message(lut, none), "TileIndexBuilder: LUT entry 77 is 32, out of range (0..31)");
}

}  // namespace
}  // namespace tilelight
