#pragma once
// Builds, on the CPU, the work of the compute light pass: per draw class the list of its tiles,
// and the indirect dispatch that shades them (uber/include/tile_lists.glsl has the buffer layout;
// uber/classify/tile_lists.comp is the GPU path's twin). Where the raster pass needs one index
// buffer and one draw per class (tile_index_builder.h), the compute pass needs one tile list and
// one VkDispatchIndirectCommand per class.

#include "tilelight/tiles/dispatch_record.h"
#include "tilelight/tiles/tile_grid.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tilelight {

// Draw classes a list buffer has room for: the 32 optimised IDs, or all 128 raw IDs.
inline constexpr std::uint32_t kTileListMaxClasses = 128;
// The list buffer's header, in uint32 words: first[128], then count[128]; the tiles follow.
inline constexpr std::uint32_t kTileListHeaderWords = 2 * kTileListMaxClasses;

// A tile's coordinates as the lists store them: x | y << 16 (TileListBuilder checks both < 2^16).
constexpr std::uint32_t pack_tile(std::uint32_t x, std::uint32_t y) { return x | (y << 16); }

// Throws tilelight::Error when a tile coordinate of `grid` would not fit pack_tile()'s 16 bits
// (more than 65536 tiles across or down). Both list builds, CPU and GPU, check it.
void check_tile_list_grid(const TileGrid& grid);

struct TileListStats {
  std::array<std::uint32_t, kTileListMaxClasses> class_tiles{};  // per draw class
  std::uint32_t tiles = 0;
  std::uint32_t workgroups = 0;  // dispatched, over every class
};

class TileListBuilder {
 public:
  // lut: raw ID -> draw class (128 entries, each < class_count); pruned: raw IDs that can never
  // occur (128 entries, or empty for none); tiles_per_group: how many tiles one workgroup of the
  // light pass shades (>= 1). Throws tilelight::Error on a wrong size or an out-of-range entry,
  // with the same messages as TileIndexBuilder, and for a grid of more than 65536 tiles across or
  // down (a tile coordinate must fit 16 bits).
  TileListBuilder(const TileGrid& grid, std::span<const std::uint8_t> lut, std::span<const bool> pruned,
                  std::uint32_t class_count, std::uint32_t tiles_per_group);

  // Two passes over the blocked raw IDs (a counting sort): count the tiles of each class, then
  // write each class's tiles, in row-major tile order, after an exclusive prefix sum of the
  // counts. `lists` receives first[c] and count[c] for every class (0 beyond class_count) and
  // then the packed tiles; dispatches[c] = {ceil(count[c] / tiles_per_group), 1, 1}.
  // Preconditions (checked, tilelight::Error): blocked_raw_ids.size() == grid.id_bytes();
  // lists.size() >= kTileListHeaderWords + grid.tile_count(); dispatches.size() == class_count.
  // A raw ID >= 128, a pruned one, or kNoTile inside the grid throws an Error naming the tile and
  // value before anything is written.
  TileListStats build(std::span<const std::uint8_t> blocked_raw_ids, std::span<std::uint32_t> lists,
                      std::span<DispatchRecord> dispatches) const;

  const TileGrid& grid() const { return grid_; }
  std::uint32_t class_count() const { return class_count_; }
  std::uint32_t tiles_per_group() const { return tiles_per_group_; }

 private:
  std::uint8_t class_of(std::uint8_t raw, std::uint32_t tile_x, std::uint32_t tile_y) const;

  TileGrid grid_;
  std::uint32_t class_count_;
  std::uint32_t tiles_per_group_;
  std::array<std::uint8_t, 256> map_{};  // raw byte -> class, or no class (src/raw_class_map.h)
  std::vector<std::uint32_t> order_;     // every tile, packed, in the order lists are filled (Morton)
};

}  // namespace tilelight
