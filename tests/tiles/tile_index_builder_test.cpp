#include "tilelight/error.h"
#include "tilelight/tile_grid.h"
#include "tilelight/tile_index_builder.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <ostream>
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace tilelight {
namespace {

// The tests' own LUT (not the generated one): optimised = raw & 31, so raw IDs 32 apart share an
// optimised ID; raw IDs with bits 0 and 1 both set are pruned.
std::vector<std::uint8_t> test_lut() {
  std::vector<std::uint8_t> lut(kRawClassCount);
  for (std::uint32_t r = 0; r < kRawClassCount; ++r) lut[r] = static_cast<std::uint8_t>(r & 31u);
  return lut;
}

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

struct Built {
  IndexBuildStats stats;
  std::vector<std::uint32_t> indices;
  std::array<VkDrawIndexedIndirectCommand, kOptimisedClassCount> draws{};
};

Built build_row_major(const TileGrid& grid, const std::vector<std::uint8_t>& row_major, bool coalesce) {
  const std::vector<std::uint8_t> lut = test_lut();
  TileIndexBuilder builder(grid, lut, test_pruned());
  Built out;
  out.indices.assign(grid.max_index_count(), 0xDEADBEEFu);
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

std::uint8_t optimised(std::uint8_t raw) { return static_cast<std::uint8_t>(raw & 31u); }

// Rectangle counts per optimised ID by the coalescing rule, worked out independently on the
// row-major IDs.
std::array<std::uint32_t, kMaxDrawClasses> expected_rects(const TileGrid& grid,
                                                              const std::vector<std::uint8_t>& rm,
                                                              bool coalesce) {
  std::array<std::uint32_t, kMaxDrawClasses> counts{};
  auto id_at = [&](std::uint32_t x, std::uint32_t y) { return optimised(rm[std::size_t{y} * grid.tiles_x + x]); };
  for (std::uint32_t by = 0; by < grid.blocks_y; ++by) {
    for (std::uint32_t bx = 0; bx < grid.blocks_x; ++bx) {
      const std::uint32_t x_end = std::min(grid.tiles_x, bx * 4 + 4);
      const std::uint32_t y_end = std::min(grid.tiles_y, by * 4 + 4);
      bool uniform = true;
      for (std::uint32_t y = by * 4; y < y_end; ++y) {
        for (std::uint32_t x = bx * 4; x < x_end; ++x) uniform = uniform && id_at(x, y) == id_at(bx * 4, by * 4);
      }
      if (coalesce && uniform) {
        ++counts[id_at(bx * 4, by * 4)];
        continue;
      }
      for (std::uint32_t y = by * 4; y < y_end; ++y) {
        for (std::uint32_t x = bx * 4; x < x_end; ++x) {
          if (!coalesce || x == bx * 4 || id_at(x, y) != id_at(x - 1, y)) ++counts[id_at(x, y)];
        }
      }
    }
  }
  return counts;
}

// Checks every structural promise of build(): contiguous draws, each tile covered exactly once by
// a rectangle of its optimised ID, rectangles inside one block, block order within an ID, stats.
void verify(const TileGrid& grid, const std::vector<std::uint8_t>& rm, const Built& b, bool coalesce) {
  std::uint32_t next_first = 0;
  std::vector<int> coverage(grid.tile_count(), 0);
  std::array<std::uint32_t, kMaxDrawClasses> tiles_per_id{};
  for (std::uint32_t id = 0; id < kOptimisedClassCount; ++id) {
    const VkDrawIndexedIndirectCommand& d = b.draws[id];
    EXPECT_EQ(d.instanceCount, 1u);
    EXPECT_EQ(d.vertexOffset, 0);
    EXPECT_EQ(d.firstInstance, 0u);
    ASSERT_EQ(d.firstIndex, next_first) << "draw " << id << " is not contiguous";
    ASSERT_EQ(d.indexCount % 6, 0u);
    ASSERT_EQ(d.indexCount, b.stats.rectangles[id] * 6);
    next_first += d.indexCount;
    std::uint64_t last_key = 0;
    for (std::uint32_t k = d.firstIndex; k < d.firstIndex + d.indexCount; k += 6) {
      const Rectangle r = decode(grid, &b.indices[k]);
      ASSERT_LT(r.x0, r.x1);
      ASSERT_LT(r.y0, r.y1);
      ASSERT_LE(r.x1, grid.tiles_x);
      ASSERT_LE(r.y1, grid.tiles_y);
      ASSERT_EQ(r.x0 / 4, (r.x1 - 1) / 4) << "rectangle crosses a block edge";
      ASSERT_EQ(r.y0 / 4, (r.y1 - 1) / 4) << "rectangle crosses a block edge";
      if (!coalesce) {
        ASSERT_EQ((r.x1 - r.x0) * (r.y1 - r.y0), 1u);
      }
      const std::uint64_t block = std::uint64_t{r.y0 / 4} * grid.blocks_x + r.x0 / 4;
      const std::uint64_t key = ((block * 4 + r.y0 % 4) * 4 + r.x0 % 4) + 1;
      ASSERT_GT(key, last_key) << "rectangles of ID " << id << " are not in block order";
      last_key = key;
      for (std::uint32_t y = r.y0; y < r.y1; ++y) {
        for (std::uint32_t x = r.x0; x < r.x1; ++x) {
          const std::size_t t = std::size_t{y} * grid.tiles_x + x;
          ++coverage[t];
          ASSERT_EQ(optimised(rm[t]), id) << "tile (" << x << ", " << y << ") drawn by the wrong ID";
          ++tiles_per_id[id];
        }
      }
    }
  }
  EXPECT_EQ(next_first, b.stats.index_count);
  for (std::size_t t = 0; t < coverage.size(); ++t) ASSERT_EQ(coverage[t], 1) << "tile " << t;
  EXPECT_EQ(b.stats.class_tiles, tiles_per_id);
  EXPECT_EQ(b.stats.rectangles, expected_rects(grid, rm, coalesce));
  EXPECT_EQ(b.stats.tiles, grid.tile_count());
  EXPECT_EQ(b.stats.primitives_uncoalesced, grid.tile_count());
  EXPECT_EQ(b.stats.index_count, b.stats.primitives_coalesced * 6);
  if (!coalesce) {
    EXPECT_EQ(b.stats.primitives_coalesced, grid.tile_count());
  }
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
    ::testing::Combine(::testing::Values(Size{1280, 720, 4}, Size{1283, 719, 4}, Size{1, 1, 4},
                                         Size{5, 3, 4}, Size{37, 23, 8}, Size{1920, 1080, 16},
                                         Size{61, 45, 4}),
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
        Pattern{"same_opt_rows", [](std::uint32_t x, std::uint32_t y) { return std::uint8_t(y % 2 ? 40 + x % 2 * 32 : 8); }, 1}));

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
  std::array<VkDrawIndexedIndirectCommand, kOptimisedClassCount> draws{};
  const IndexBuildStats stats = builder.build(blocked, true, indices, draws);
  EXPECT_EQ(stats.rectangles, expected_rects(grid, ids, true));
}

TEST(TileIndexBuilder, RebuildingReusesTheScratchCorrectly) {
  const TileGrid grid = TileGrid::make(61, 45);
  const std::vector<std::uint8_t> lut = test_lut();
  TileIndexBuilder builder(grid, lut, test_pruned());
  for (std::uint32_t round = 0; round < 3; ++round) {
    const std::vector<std::uint8_t> ids = random_ids(grid, round, round == 1 ? 96 : 2);
    Built b;
    b.indices.assign(grid.max_index_count(), 0);
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
  std::array<VkDrawIndexedIndirectCommand, kOptimisedClassCount> draws{};
  EXPECT_EQ(builder.build(to_blocked(grid, ids), true, indices, draws).rectangles[3], 1u);
}

// ---- errors ----

std::string build_error(const TileGrid& grid, std::vector<std::uint8_t> blocked, std::size_t index_count,
                        std::size_t draw_count) {
  const std::vector<std::uint8_t> lut = test_lut();
  TileIndexBuilder builder(grid, lut, test_pruned());
  std::vector<std::uint32_t> indices(index_count, 0x12345678u);
  std::vector<VkDrawIndexedIndirectCommand> draws(draw_count, VkDrawIndexedIndirectCommand{7, 7, 7, 7, 7});
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
  std::vector<std::uint8_t> ids = c.coalesce_uniform ? std::vector<std::uint8_t>(grid.tile_count(), 4)
                                                     : random_ids(grid, 11, 96);
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
  EXPECT_EQ(message(std::span(lut).first(127), none),
            "TileIndexBuilder: the LUT must have 128 entries (got 127)");
  EXPECT_EQ(message(lut, short_pruned),
            "TileIndexBuilder: the pruned set must have 128 entries or none (got 5)");
  lut[77] = 32;
  EXPECT_EQ(message(lut, none), "TileIndexBuilder: LUT entry 77 is 32, out of range (0..31)");
}

}  // namespace
}  // namespace tilelight
