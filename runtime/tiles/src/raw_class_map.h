#pragma once
// The table both CPU builders (TileIndexBuilder, TileListBuilder) look every tile's raw ID up in:
// one lookup maps a byte to its draw class and says whether the byte names a tile at all. The
// checks of what they are given to make it, and the error for a tile without a class, are the
// builders' shared contract ("the same messages as TileIndexBuilder").

#include "tilelight/tiles/tile_index_builder.h"

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace tilelight {

// A raw ID byte -> draw class; kNoClass for a byte >= kRawClassCount and for a pruned raw ID.
using RawClassMap = std::array<std::uint8_t, 256>;

// No class: draw classes are < 128, so a class never has this bit, and OR-ing the classes of
// several tiles and testing it validates them all at once.
inline constexpr std::uint8_t kNoClass = 0x80;

// The map of `lut` (raw ID -> draw class) with `pruned` (raw IDs that never occur) left out.
// Throws tilelight::Error, its message prefixed by `builder`, unless 1 <= class_count <=
// max_classes, lut has kRawClassCount entries, each < class_count, and pruned has kRawClassCount
// entries or none. Precondition: max_classes <= 128.
RawClassMap make_raw_class_map(std::string_view builder, std::span<const std::uint8_t> lut,
                               std::span<const bool> pruned, std::uint32_t class_count, std::uint32_t max_classes);

// Throws the tilelight::Error for tile (tile_x, tile_y), whose raw ID `raw` has no class: out of
// range or pruned.
[[noreturn]] void throw_no_class(std::uint32_t tile_x, std::uint32_t tile_y, std::uint8_t raw);

}  // namespace tilelight
