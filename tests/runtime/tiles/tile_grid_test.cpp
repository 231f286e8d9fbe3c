#include "tilelight/tiles/tile_grid.h"
#include "tilelight/base/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace tilelight {
namespace {

struct GridCase {
  std::uint32_t width, height, tile_size;
  std::uint32_t tiles_x, tiles_y, blocks_x, blocks_y;
};

// Readable, stable test names (gtest would otherwise print the raw bytes of the struct).
void PrintTo(const GridCase& c, std::ostream* os) { *os << c.width << "x" << c.height << "_ts" << c.tile_size; }

class TileGridSizes : public ::testing::TestWithParam<GridCase> {};

TEST_P(TileGridSizes, DerivedCounts) {
  const GridCase& c = GetParam();
  const TileGrid grid = TileGrid::make(c.width, c.height, c.tile_size);
  EXPECT_EQ(grid.width, c.width);
  EXPECT_EQ(grid.height, c.height);
  EXPECT_EQ(grid.tile_size, c.tile_size);
  EXPECT_EQ(grid.tiles_x, c.tiles_x);
  EXPECT_EQ(grid.tiles_y, c.tiles_y);
  EXPECT_EQ(grid.blocks_x, c.blocks_x);
  EXPECT_EQ(grid.blocks_y, c.blocks_y);
  EXPECT_EQ(grid.tile_count(), c.tiles_x * c.tiles_y);
  EXPECT_EQ(grid.block_count(), c.blocks_x * c.blocks_y);
  EXPECT_EQ(grid.id_bytes(), std::size_t{c.blocks_x} * c.blocks_y * 16);
  EXPECT_EQ(grid.vertex_count(), (c.tiles_x + 1) * (c.tiles_y + 1));
  EXPECT_EQ(grid.max_index_count(), c.tiles_x * c.tiles_y * 6);
}

INSTANTIATE_TEST_SUITE_P(Sizes, TileGridSizes,
                         ::testing::Values(GridCase{1280, 720, 4, 320, 180, 80, 45},
                                           GridCase{1920, 1080, 4, 480, 270, 120, 68},
                                           GridCase{1283, 719, 4, 321, 180, 81, 45}, GridCase{1, 1, 4, 1, 1, 1, 1},
                                           GridCase{5, 3, 4, 2, 1, 1, 1}, GridCase{1280, 720, 8, 160, 90, 40, 23},
                                           GridCase{1280, 720, 16, 80, 45, 20, 12}, GridCase{17, 33, 16, 2, 3, 1, 1},
                                           GridCase{80, 16, 4, 20, 4, 5, 1},
                                           // The widest one-tile-high frame whose corner vertices (2 * 536870911) stay
                                           // below 2^30, as point indices need (tile_primitive.h).
                                           GridCase{2147483640u, 4, 4, 536870910u, 1, 134217728u, 1}));

TEST(TileGrid, ExactCountsAt720p) {
  const TileGrid grid = TileGrid::make(1280, 720);
  EXPECT_EQ(grid.tile_size, 4u);
  EXPECT_EQ(grid.tile_count(), 57600u);
  EXPECT_EQ(grid.block_count(), 3600u);
}

struct BadGrid {
  std::uint32_t width, height, tile_size;
  const char* message;
};

void PrintTo(const BadGrid& c, std::ostream* os) { *os << c.width << "x" << c.height << "_ts" << c.tile_size; }

class TileGridErrors : public ::testing::TestWithParam<BadGrid> {};

TEST_P(TileGridErrors, NamesTheValue) {
  const BadGrid& c = GetParam();
  try {
    (void)TileGrid::make(c.width, c.height, c.tile_size);
    FAIL() << "no error for " << c.width << "x" << c.height << " tile size " << c.tile_size;
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), c.message);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Bad, TileGridErrors,
    ::testing::Values(BadGrid{0, 720, 4, "TileGrid: width must be > 0 (got 0)"},
                      BadGrid{1280, 0, 4, "TileGrid: height must be > 0 (got 0)"},
                      BadGrid{1280, 720, 5, "TileGrid: tile_size must be 4, 8 or 16 (got 5)"},
                      BadGrid{1280, 720, 0, "TileGrid: tile_size must be 4, 8 or 16 (got 0)"},
                      BadGrid{1280, 720, 32, "TileGrid: tile_size must be 4, 8 or 16 (got 32)"},
                      BadGrid{4294967295u, 4294967295u, 4,
                              "TileGrid: frame 4294967295x4294967295 at tile size 4 has too many "
                              "tiles (1152921504606846976)"},
                      // 536870911 tiles pass the index-count and block-storage limits, but their
                      // 2 * 536870912 corner vertices do not fit in a point index's 30 bits.
                      BadGrid{
                          2147483641u, 4, 4,
                          "TileGrid: frame 2147483641x4 at tile size 4 has too many tile corners (1073741824, at most "
                          "1073741823)"}));

TEST(TileGrid, BlockedOffsetFollowsTheDocumentedLayout) {
  const TileGrid grid = TileGrid::make(1283, 719);  // 321x180 tiles, 81x45 blocks
  EXPECT_EQ(grid.blocked_offset(0, 0), 0u);
  EXPECT_EQ(grid.blocked_offset(3, 0), 3u);
  EXPECT_EQ(grid.blocked_offset(0, 1), 4u);
  EXPECT_EQ(grid.blocked_offset(3, 3), 15u);
  EXPECT_EQ(grid.blocked_offset(4, 0), 16u);
  EXPECT_EQ(grid.blocked_offset(0, 4), 81u * 16u);
  EXPECT_EQ(grid.blocked_offset(13, 6), (1u * 81u + 3u) * 16u + 2u * 4u + 1u);
  EXPECT_EQ(grid.blocked_offset(320, 179), (44u * 81u + 80u) * 16u + 3u * 4u + 0u);
}

TEST(TileGrid, BlockedOffsetIsABijectionOntoTheInsideSlots) {
  const TileGrid grid = TileGrid::make(37, 23);  // 10x6 tiles: partial blocks both ways
  std::vector<int> hits(grid.id_bytes(), 0);
  for (std::uint32_t ty = 0; ty < grid.tiles_y; ++ty) {
    for (std::uint32_t tx = 0; tx < grid.tiles_x; ++tx) ++hits[grid.blocked_offset(tx, ty)];
  }
  int inside = 0;
  for (int h : hits) {
    EXPECT_LE(h, 1);
    inside += h;
  }
  EXPECT_EQ(inside, static_cast<int>(grid.tile_count()));
}

class TileGridRoundTrip : public ::testing::TestWithParam<GridCase> {};

TEST_P(TileGridRoundTrip, RowMajorToBlockedAndBack) {
  const GridCase& c = GetParam();
  const TileGrid grid = TileGrid::make(c.width, c.height, c.tile_size);
  std::vector<std::uint8_t> row_major(grid.tile_count());
  for (std::size_t i = 0; i < row_major.size(); ++i) row_major[i] = static_cast<std::uint8_t>(i % 127);
  const std::vector<std::uint8_t> blocked = to_blocked(grid, row_major);
  ASSERT_EQ(blocked.size(), grid.id_bytes());
  for (std::uint32_t ty = 0; ty < grid.tiles_y; ++ty) {
    for (std::uint32_t tx = 0; tx < grid.tiles_x; ++tx) {
      ASSERT_EQ(blocked[grid.blocked_offset(tx, ty)], row_major[std::size_t{ty} * grid.tiles_x + tx]);
    }
  }
  const auto padding = static_cast<std::size_t>(std::count(blocked.begin(), blocked.end(), kNoTile));
  EXPECT_EQ(padding, grid.id_bytes() - grid.tile_count());
  EXPECT_EQ(to_row_major(grid, blocked), row_major);
}

INSTANTIATE_TEST_SUITE_P(Sizes, TileGridRoundTrip,
                         ::testing::Values(GridCase{1280, 720, 4, 0, 0, 0, 0}, GridCase{1283, 719, 4, 0, 0, 0, 0},
                                           GridCase{1, 1, 4, 0, 0, 0, 0}, GridCase{5, 3, 4, 0, 0, 0, 0},
                                           GridCase{100, 70, 8, 0, 0, 0, 0}, GridCase{200, 90, 16, 0, 0, 0, 0}));

TEST(TileGrid, ConversionsRejectWrongSizes) {
  const TileGrid grid = TileGrid::make(5, 3);  // 2x1 tiles, one block
  const std::vector<std::uint8_t> three(3, 0);
  EXPECT_THROW((void)to_blocked(grid, three), Error);
  EXPECT_THROW((void)to_row_major(grid, three), Error);
  try {
    (void)to_blocked(grid, three);
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "to_blocked: expected 2 IDs for the grid, got 3");
  }
}

TEST(TileGrid, VertexIndexIsRowMajorOverCorners) {
  const TileGrid grid = TileGrid::make(10, 6);  // 3x2 tiles, 4x3 corners
  EXPECT_EQ(grid.vertex_index(0, 0), 0u);
  EXPECT_EQ(grid.vertex_index(3, 0), 3u);
  EXPECT_EQ(grid.vertex_index(0, 1), 4u);
  EXPECT_EQ(grid.vertex_index(3, 2), 11u);
  EXPECT_EQ(grid.vertex_count(), 12u);
}

TEST(TileGrid, CornerVerticesClampAtTheFrameEdge) {
  const TileGrid grid = TileGrid::make(10, 6);  // 3x2 tiles; the last column/row is partial
  const std::vector<float> v = grid.corner_vertices();
  ASSERT_EQ(v.size(), std::size_t{grid.vertex_count()} * 2);
  const float xs[] = {0.0f, 4.0f, 8.0f, 10.0f};
  const float ys[] = {0.0f, 4.0f, 6.0f};
  for (std::uint32_t cy = 0; cy <= grid.tiles_y; ++cy) {
    for (std::uint32_t cx = 0; cx <= grid.tiles_x; ++cx) {
      const std::size_t i = std::size_t{grid.vertex_index(cx, cy)} * 2;
      EXPECT_EQ(v[i], xs[cx]) << cx << "," << cy;
      EXPECT_EQ(v[i + 1], ys[cy]) << cx << "," << cy;
    }
  }
}

TEST(TileGrid, CornerVerticesOfAnExactFrame) {
  const TileGrid grid = TileGrid::make(1280, 720, 16);
  const std::vector<float> v = grid.corner_vertices();
  const std::size_t last = std::size_t{grid.vertex_index(grid.tiles_x, grid.tiles_y)} * 2;
  EXPECT_EQ(v[last], 1280.0f);
  EXPECT_EQ(v[last + 1], 720.0f);
  const std::size_t mid = std::size_t{grid.vertex_index(7, 3)} * 2;
  EXPECT_EQ(v[mid], 112.0f);
  EXPECT_EQ(v[mid + 1], 48.0f);
}

TEST(TileGrid, OnePixelFrame) {
  const TileGrid grid = TileGrid::make(1, 1);
  EXPECT_EQ(grid.corner_vertices(), (std::vector<float>{0, 0, 1, 0, 0, 1, 1, 1}));
}

}  // namespace
}  // namespace tilelight
