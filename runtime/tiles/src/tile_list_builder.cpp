#include "tilelight/tiles/tile_list_builder.h"

#include "raw_class_map.h"
#include "tilelight/base/error.h"
#include "tilelight/tiles/tile_index_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace tilelight {
namespace {

static_assert(kTileListMaxClasses <= kNoClass, "a draw class must never read as kNoClass");

constexpr std::uint32_t kMaxTileCoordinate = 0xFFFF;  // 16 bits each in pack_tile()

// Bit i of `v` to bit 2i: one coordinate's half of a Morton code.
std::uint64_t spread_bits(std::uint32_t v) {
  std::uint64_t x = v;
  x = (x | (x << 16)) & 0x0000FFFF0000FFFFull;
  x = (x | (x << 8)) & 0x00FF00FF00FF00FFull;
  x = (x | (x << 4)) & 0x0F0F0F0F0F0F0F0Full;
  x = (x | (x << 2)) & 0x3333333333333333ull;
  x = (x | (x << 1)) & 0x5555555555555555ull;
  return x;
}

// Every tile of the grid, packed, in Morton (Z) order: the order each class's list is filled in,
// so that the few tiles one light workgroup shades (4 at tile size 4) are, where the class
// covers the region, one 2x2 square of tiles (8x8 pixels), and a run of workgroups one larger
// square, rather than a strip of a row.
std::vector<std::uint32_t> morton_order(const TileGrid& grid) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(grid.tile_count());
  for (std::uint32_t y = 0; y < grid.tiles_y; ++y) {
    for (std::uint32_t x = 0; x < grid.tiles_x; ++x)
      keyed.emplace_back(spread_bits(x) | (spread_bits(y) << 1), pack_tile(x, y));
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order;
  order.reserve(keyed.size());
  for (const auto& [key, tile] : keyed) order.push_back(tile);
  return order;
}

}  // namespace

void check_tile_list_grid(const TileGrid& grid) {
  if (grid.tiles_x > kMaxTileCoordinate + 1 || grid.tiles_y > kMaxTileCoordinate + 1) {
    throw Error(fmt::format("tile lists: a grid of {}x{} tiles: a tile list stores coordinates up to {}", grid.tiles_x,
                            grid.tiles_y, kMaxTileCoordinate));
  }
}

TileListBuilder::TileListBuilder(const TileGrid& grid, std::span<const std::uint8_t> lut, std::span<const bool> pruned,
                                 std::uint32_t class_count, std::uint32_t tiles_per_group)
    : grid_(grid),
      class_count_(class_count),
      tiles_per_group_(tiles_per_group),
      map_(make_raw_class_map("TileListBuilder", lut, pruned, class_count, kTileListMaxClasses)) {
  check_tile_list_grid(grid);
  if (tiles_per_group == 0) throw Error("TileListBuilder: tiles per workgroup must be >= 1 (got 0)");
  order_ = morton_order(grid);
}

std::uint8_t TileListBuilder::class_of(std::uint8_t raw, std::uint32_t tile_x, std::uint32_t tile_y) const {
  const std::uint8_t c = map_[raw];
  if (c == kNoClass) throw_no_class(tile_x, tile_y, raw);
  return c;
}

TileListStats TileListBuilder::build(std::span<const std::uint8_t> blocked_raw_ids, std::span<std::uint32_t> lists,
                                     std::span<DispatchRecord> dispatches) const {
  if (blocked_raw_ids.size() != grid_.id_bytes()) {
    throw Error(fmt::format("TileListBuilder: {} raw ID bytes for a grid of {} (blocked)", blocked_raw_ids.size(),
                            grid_.id_bytes()));
  }
  if (lists.size() < kTileListHeaderWords + std::size_t{grid_.tile_count()}) {
    throw Error(fmt::format("TileListBuilder: the list buffer holds {} words, {} are needed", lists.size(),
                            kTileListHeaderWords + std::size_t{grid_.tile_count()}));
  }
  if (dispatches.size() != class_count_) {
    throw Error(fmt::format("TileListBuilder: {} dispatch records for {} classes", dispatches.size(), class_count_));
  }
  // Pass 1: count (and validate every tile before anything is written).
  TileListStats stats;
  for (std::uint32_t y = 0; y < grid_.tiles_y; ++y) {
    for (std::uint32_t x = 0; x < grid_.tiles_x; ++x) {
      ++stats.class_tiles[class_of(blocked_raw_ids[grid_.blocked_offset(x, y)], x, y)];
    }
  }
  // Prefix sum: each class's range, its header words and its dispatch.
  std::array<std::uint32_t, kTileListMaxClasses> cursor{};
  std::uint32_t first = 0;
  for (std::uint32_t c = 0; c < kTileListMaxClasses; ++c) {
    const std::uint32_t count = c < class_count_ ? stats.class_tiles[c] : 0;
    lists[c] = first;
    lists[kTileListMaxClasses + c] = count;
    cursor[c] = kTileListHeaderWords + first;
    if (c < class_count_) {
      const std::uint32_t groups = (count + tiles_per_group_ - 1) / tiles_per_group_;
      dispatches[c] = DispatchRecord{groups, 1, 1};
      stats.workgroups += groups;
    }
    first += count;
  }
  stats.tiles = first;
  // Pass 2: fill, in Morton order (morton_order()).
  for (const std::uint32_t tile : order_) {
    const std::uint32_t x = tile & kMaxTileCoordinate, y = tile >> 16;
    lists[cursor[map_[blocked_raw_ids[grid_.blocked_offset(x, y)]]]++] = tile;
  }
  return stats;
}

}  // namespace tilelight
