#include "tilelight/tiles/tile_list_builder.h"

#include "raw_class_map.h"
#include "tilelight/base/error.h"
#include "tilelight/tiles/tile_index_builder.h"

#include <fmt/format.h>

#include <algorithm>

namespace tilelight {
namespace {

static_assert(kTileListMaxClasses <= kNoClass, "a draw class must never read as kNoClass");

constexpr std::uint32_t kMaxTileCoordinate = 0xFFFF;  // 16 bits each in pack_tile()

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
  // Pass 2: fill, row-major.
  for (std::uint32_t y = 0; y < grid_.tiles_y; ++y) {
    for (std::uint32_t x = 0; x < grid_.tiles_x; ++x) {
      lists[cursor[map_[blocked_raw_ids[grid_.blocked_offset(x, y)]]]++] = pack_tile(x, y);
    }
  }
  return stats;
}

}  // namespace tilelight
