#include "tilelight/tiles/tile_grid.h"

#include "tilelight/base/error.h"
#include "tilelight/tiles/tile_primitive.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace tilelight {
namespace {

std::uint32_t ceil_div(std::uint32_t value, std::uint32_t divisor) {
  // 64-bit so that width = UINT32_MAX does not wrap.
  return static_cast<std::uint32_t>((std::uint64_t{value} + divisor - 1) / divisor);
}

void check_size(std::size_t got, std::size_t expected, const char* what) {
  if (got != expected) {
    throw Error(fmt::format("{}: expected {} IDs for the grid, got {}", what, expected, got));
  }
}

}  // namespace

TileGrid TileGrid::make(std::uint32_t width, std::uint32_t height, std::uint32_t tile_size) {
  if (width == 0) throw Error(fmt::format("TileGrid: width must be > 0 (got {})", width));
  if (height == 0) throw Error(fmt::format("TileGrid: height must be > 0 (got {})", height));
  if (tile_size != 4 && tile_size != 8 && tile_size != 16) {
    throw Error(fmt::format("TileGrid: tile_size must be 4, 8 or 16 (got {})", tile_size));
  }
  TileGrid grid;
  grid.width = width;
  grid.height = height;
  grid.tile_size = tile_size;
  grid.tiles_x = ceil_div(width, tile_size);
  grid.tiles_y = ceil_div(height, tile_size);
  grid.blocks_x = ceil_div(grid.tiles_x, kBlockTiles);
  grid.blocks_y = ceil_div(grid.tiles_y, kBlockTiles);
  // Index counts, vertex indices and blocked offsets are 32-bit (the GPU's index type); the
  // index count (6 per tile) and the padded block storage are the largest of them. A point
  // index keeps bits 30..31 for its side (tile_primitive.h), so corner vertices stay below 2^30.
  constexpr std::uint64_t kLimit = std::numeric_limits<std::uint32_t>::max();
  const std::uint64_t tiles = std::uint64_t{grid.tiles_x} * grid.tiles_y;
  const std::uint64_t padded = std::uint64_t{grid.blocks_x} * grid.blocks_y * kBlockTileCount;
  const std::uint64_t corners = std::uint64_t{grid.tiles_x + 1} * (grid.tiles_y + 1);
  if (tiles * 6 > kLimit || padded > kLimit) {
    throw Error(
        fmt::format("TileGrid: frame {}x{} at tile size {} has too many tiles ({})", width, height, tile_size, tiles));
  }
  if (corners > kPointCornerMask) {
    throw Error(fmt::format("TileGrid: frame {}x{} at tile size {} has too many tile corners ({}, at most {})", width,
                            height, tile_size, corners, kPointCornerMask));
  }
  return grid;
}

std::uint32_t TileGrid::tile_count() const { return tiles_x * tiles_y; }

std::uint32_t TileGrid::block_count() const { return blocks_x * blocks_y; }

std::size_t TileGrid::id_bytes() const { return std::size_t{block_count()} * kBlockTileCount; }

std::uint32_t TileGrid::blocked_offset(std::uint32_t tile_x, std::uint32_t tile_y) const {
  const std::uint32_t block = (tile_y / kBlockTiles) * blocks_x + tile_x / kBlockTiles;
  return block * kBlockTileCount + (tile_y % kBlockTiles) * kBlockTiles + tile_x % kBlockTiles;
}

std::uint32_t TileGrid::vertex_count() const { return (tiles_x + 1) * (tiles_y + 1); }

std::uint32_t TileGrid::vertex_index(std::uint32_t corner_x, std::uint32_t corner_y) const {
  return corner_y * (tiles_x + 1) + corner_x;
}

std::vector<float> TileGrid::corner_vertices() const {
  std::vector<float> out;
  out.reserve(std::size_t{vertex_count()} * 2);
  for (std::uint32_t cy = 0; cy <= tiles_y; ++cy) {
    const auto y = std::min<std::uint64_t>(std::uint64_t{cy} * tile_size, height);
    for (std::uint32_t cx = 0; cx <= tiles_x; ++cx) {
      const auto x = std::min<std::uint64_t>(std::uint64_t{cx} * tile_size, width);
      out.push_back(static_cast<float>(x));
      out.push_back(static_cast<float>(y));
    }
  }
  return out;
}

std::uint32_t TileGrid::max_index_count() const { return tile_count() * 6; }

std::vector<std::uint8_t> to_blocked(const TileGrid& grid, std::span<const std::uint8_t> row_major) {
  check_size(row_major.size(), grid.tile_count(), "to_blocked");
  std::vector<std::uint8_t> blocked(grid.id_bytes(), kNoTile);
  for (std::uint32_t ty = 0; ty < grid.tiles_y; ++ty) {
    for (std::uint32_t tx = 0; tx < grid.tiles_x; ++tx) {
      blocked[grid.blocked_offset(tx, ty)] = row_major[std::size_t{ty} * grid.tiles_x + tx];
    }
  }
  return blocked;
}

std::vector<std::uint8_t> to_row_major(const TileGrid& grid, std::span<const std::uint8_t> blocked) {
  check_size(blocked.size(), grid.id_bytes(), "to_row_major");
  std::vector<std::uint8_t> row_major(grid.tile_count());
  for (std::uint32_t ty = 0; ty < grid.tiles_y; ++ty) {
    for (std::uint32_t tx = 0; tx < grid.tiles_x; ++tx) {
      row_major[std::size_t{ty} * grid.tiles_x + tx] = blocked[grid.blocked_offset(tx, ty)];
    }
  }
  return row_major;
}

}  // namespace tilelight
