// The report's per-class tile counts and the tile-class picture's IDs map raw tile IDs through
// the generated checked lookup: a raw ID that is out of range or pruned is an error naming the
// tile, never a read past the table or a silent class 0. CPU only.
#include "tilelight/app/report.h"
#include "tilelight/base/error.h"

#include <gtest/gtest.h>

#include <split_second_shaders.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tilelight::test {
namespace {

constexpr std::uint8_t kSun = split_second::raw_bit::SUN_LIGHT.value();
constexpr std::uint8_t kSolidAndSoft =
    (split_second::raw_bit::SHADOW_SOLID | split_second::raw_bit::SHADOW_SOFT).value();

TEST(TileIdsReport, ValidRawIdsMapToTheirOptimisedIds) {
  const std::vector<std::uint8_t> raw = {0, kSun, 69, 126};
  EXPECT_EQ(app::optimised_tile_ids(raw), (std::vector<std::uint8_t>{0, 16, 8, 31}));
  app::FrameReport report;
  app::count_tiles(report, raw);
  EXPECT_EQ(report.tiles, 4u);
  ASSERT_EQ(report.optimised_tiles.size(), split_second::kOptimisedCount);
  EXPECT_EQ(report.optimised_tiles[0], 1u);
  EXPECT_EQ(report.optimised_tiles[16], 1u);
  EXPECT_EQ(report.optimised_tiles[8], 1u);
  EXPECT_EQ(report.optimised_tiles[31], 1u);
}

std::string error_of(const std::vector<std::uint8_t>& raw) {
  try {
    app::optimised_tile_ids(raw);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(TileIdsReport, APrunedOrOutOfRangeRawIdIsAnErrorNamingTheTile) {
  static_assert(split_second::kRawPruned[kSolidAndSoft]);
  EXPECT_EQ(error_of({kSun, kSolidAndSoft}), "tile 1: raw ID 3 is impossible (a pruned class)");
  EXPECT_EQ(error_of({128}), "tile 0: raw ID 128 is out of range (0..127)");
  EXPECT_EQ(error_of({0, 0, 0xff}), "tile 2: raw ID 255 is out of range (0..127)");
  app::FrameReport report;
  EXPECT_THROW(app::count_tiles(report, {kSun, 200}), Error);
}

}  // namespace
}  // namespace tilelight::test
