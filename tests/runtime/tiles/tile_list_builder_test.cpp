// The CPU build of the compute light pass's work: per-class tile lists and dispatch records.
#include "tilelight/tiles/tile_list_builder.h"
#include "tilelight/base/error.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/tiles/tile_index_builder.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace tilelight {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace tile_list_builder_test {
namespace {

// The tests' own LUT: optimised = raw & 31; raw IDs with bits 0 and 1 both set are pruned.
std::vector<std::uint8_t> test_lut() {
  std::vector<std::uint8_t> lut(kRawClassCount);
  for (std::uint32_t r = 0; r < kRawClassCount; ++r) lut[r] = static_cast<std::uint8_t>(r & 31u);
  return lut;
}

const std::array<bool, kRawClassCount>& test_pruned() {
  static const std::array<bool, kRawClassCount> pruned = [] {
    std::array<bool, kRawClassCount> p{};
    for (std::uint32_t r = 0; r < kRawClassCount; ++r) p[r] = (r & 3u) == 3u;
    return p;
  }();
  return pruned;
}

// Row-major raw IDs of a random frame, every one possible.
std::vector<std::uint8_t> random_frame(const TileGrid& grid, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::vector<std::uint8_t> ids(grid.tile_count());
  for (std::uint8_t& id : ids) {
    do {
      id = static_cast<std::uint8_t>(random() % kRawClassCount);
    } while (test_pruned()[id]);
  }
  return ids;
}

struct Built {
  TileListStats stats;
  std::vector<std::uint32_t> lists;
  std::vector<DispatchRecord> dispatches;
};

Built build(const TileGrid& grid, const std::vector<std::uint8_t>& row_major, std::uint32_t per_group) {
  const TileListBuilder builder(grid, test_lut(), test_pruned(), kOptimisedClassCount, per_group);
  Built b;
  b.lists.assign(kTileListHeaderWords + grid.tile_count(), 0xDEADBEEFu);
  b.dispatches.assign(kOptimisedClassCount, DispatchRecord{7, 7, 7});
  b.stats = builder.build(to_blocked(grid, row_major), b.lists, b.dispatches);
  return b;
}

TEST(TileListBuilder, EveryTileOnceInItsClassListWithItsDispatch) {
  for (const auto& [width, height, tile_size, per_group] :
       std::vector<std::array<std::uint32_t, 4>>{{320, 180, 4, 4}, {333, 197, 8, 1}, {50, 30, 16, 1}, {4, 4, 4, 4}}) {
    const TileGrid grid = TileGrid::make(width, height, tile_size);
    const std::vector<std::uint8_t> ids = random_frame(grid, width * 31 + height);
    const Built b = build(grid, ids, per_group);
    std::set<std::uint32_t> seen;
    std::uint32_t next_first = 0, groups = 0;
    for (std::uint32_t c = 0; c < kTileListMaxClasses; ++c) {
      const std::uint32_t first = b.lists[c], count = b.lists[kTileListMaxClasses + c];
      EXPECT_EQ(first, next_first) << "class " << c << ": lists are back to back, in class order";
      next_first += count;
      if (c >= kOptimisedClassCount) {
        EXPECT_EQ(count, 0u) << "class " << c;
        continue;
      }
      EXPECT_EQ(count, b.stats.class_tiles[c]);
      EXPECT_EQ(b.dispatches[c].x, (count + per_group - 1) / per_group) << "class " << c;
      EXPECT_EQ(b.dispatches[c].y, 1u);
      EXPECT_EQ(b.dispatches[c].z, 1u);
      groups += b.dispatches[c].x;
      for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t packed = b.lists[kTileListHeaderWords + first + i];
        const std::uint32_t x = packed & 0xFFFFu, y = packed >> 16;
        ASSERT_LT(x, grid.tiles_x);
        ASSERT_LT(y, grid.tiles_y);
        EXPECT_EQ(ids[y * grid.tiles_x + x] & 31u, c) << "tile (" << x << ", " << y << ")";
        EXPECT_TRUE(seen.insert(packed).second) << "tile (" << x << ", " << y << ") listed twice";
      }
    }
    EXPECT_EQ(seen.size(), grid.tile_count());
    EXPECT_EQ(b.stats.tiles, grid.tile_count());
    EXPECT_EQ(b.stats.workgroups, groups);
  }
}

// Morton order: each light workgroup's 4 tiles are a 2x2 square (8x8 pixels), 4 workgroups a
// 4x4 one, and so on; a grid that is not square keeps the order of its tiles' Morton codes.
TEST(TileListBuilder, WithinAClassTilesAreInMortonOrder) {
  const TileGrid grid = TileGrid::make(64, 64, 4);
  const Built b = build(grid, std::vector<std::uint8_t>(grid.tile_count(), 5), 4);
  ASSERT_EQ(b.lists[kTileListMaxClasses + 5], 256u);
  const std::uint32_t* list = b.lists.data() + kTileListHeaderWords;
  const std::vector<std::uint32_t> first_eight(list, list + 8);
  EXPECT_EQ(first_eight,
            (std::vector<std::uint32_t>{pack_tile(0, 0), pack_tile(1, 0), pack_tile(0, 1), pack_tile(1, 1),
                                        pack_tile(2, 0), pack_tile(3, 0), pack_tile(2, 1), pack_tile(3, 1)}));
  EXPECT_EQ(list[16], pack_tile(4, 0));
  EXPECT_EQ(list[255], pack_tile(15, 15));
  const TileGrid wide = TileGrid::make(24, 8, 4);  // 6x2 tiles
  const Built w = build(wide, std::vector<std::uint8_t>(wide.tile_count(), 5), 4);
  const std::uint32_t* wide_list = w.lists.data() + kTileListHeaderWords;
  EXPECT_EQ(std::vector<std::uint32_t>(wide_list, wide_list + 12),
            (std::vector<std::uint32_t>{pack_tile(0, 0), pack_tile(1, 0), pack_tile(0, 1), pack_tile(1, 1),
                                        pack_tile(2, 0), pack_tile(3, 0), pack_tile(2, 1), pack_tile(3, 1),
                                        pack_tile(4, 0), pack_tile(5, 0), pack_tile(4, 1), pack_tile(5, 1)}));
  EXPECT_EQ(b.dispatches[5].x, 64u);
  EXPECT_EQ(b.dispatches[4].x, 0u) << "a class without tiles dispatches nothing";
}

std::string error_of(const TileGrid& grid, const std::vector<std::uint8_t>& row_major) {
  try {
    build(grid, row_major, 4);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(TileListBuilder, BadRawIdsAreNamedAndNothingIsWritten) {
  const TileGrid grid = TileGrid::make(32, 32, 4);
  std::vector<std::uint8_t> ids(grid.tile_count(), 0);
  ids[7 * 8 + 5] = 3;
  EXPECT_EQ(error_of(grid, ids), "tile (5, 7): raw ID 3 is impossible (a pruned class)");
  ids[7 * 8 + 5] = 200;
  EXPECT_EQ(error_of(grid, ids), "tile (5, 7): raw ID 200 is out of range (0..127)");

  const TileListBuilder builder(grid, test_lut(), test_pruned(), kOptimisedClassCount, 4);
  std::vector<std::uint32_t> lists(kTileListHeaderWords + grid.tile_count(), 0xDEADBEEFu);
  std::vector<DispatchRecord> dispatches(kOptimisedClassCount, DispatchRecord{7, 7, 7});
  EXPECT_THROW(builder.build(to_blocked(grid, ids), lists, dispatches), Error);
  for (const std::uint32_t w : lists) ASSERT_EQ(w, 0xDEADBEEFu);
  for (const DispatchRecord& d : dispatches) ASSERT_EQ(d.x, 7u);
}

TEST(TileListBuilder, PreconditionsAreChecked) {
  const TileGrid grid = TileGrid::make(32, 32, 4);
  auto construct_error = [&](std::uint32_t classes, std::uint32_t per_group, std::size_t lut_size) -> std::string {
    try {
      const std::vector<std::uint8_t> lut(lut_size, 0);
      TileListBuilder(grid, lut, {}, classes, per_group);
    } catch (const Error& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_EQ(construct_error(0, 4, 128), "TileListBuilder: the class count must be 1..128 (got 0)");
  EXPECT_EQ(construct_error(32, 0, 128), "TileListBuilder: tiles per workgroup must be >= 1 (got 0)");
  EXPECT_EQ(construct_error(32, 4, 64), "TileListBuilder: the LUT must have 128 entries (got 64)");
  const TileListBuilder builder(grid, test_lut(), test_pruned(), kOptimisedClassCount, 4);
  std::vector<std::uint32_t> short_lists(kTileListHeaderWords + grid.tile_count() - 1);
  std::vector<DispatchRecord> dispatches(kOptimisedClassCount);
  try {
    builder.build(std::vector<std::uint8_t>(grid.id_bytes(), 0), short_lists, dispatches);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "TileListBuilder: the list buffer holds 319 words, 320 are needed");
  }
}

}  // namespace
}  // namespace tile_list_builder_test
}  // namespace tilelight
