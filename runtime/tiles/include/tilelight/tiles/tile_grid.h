#pragma once
// Screen tiling for tile-classified deferred lighting (GPU Pro 2, "Screen-Space Classification
// for Efficient Deferred Shading"). The frame is cut into square tiles; the classifier writes one
// raw ID byte per tile in a blocked layout of 4x4 tiles (the chapter's Xbox 360 layout, Fig. 4.3)
// so that one block row is one 32-bit word and coalescing can compare a row in one operation.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace tilelight {

inline constexpr std::uint32_t kBlockTiles = 4;  // a block is 4x4 tiles (Xbox 360 layout, Fig. 4.3)
inline constexpr std::uint32_t kBlockTileCount = 16;
inline constexpr std::uint8_t kNoTile = 0xFF;  // ID slot of a block entry outside the frame

struct TileGrid {
  std::uint32_t width = 0, height = 0, tile_size = 0;  // pixels
  std::uint32_t tiles_x = 0, tiles_y = 0;              // ceil(width / tile_size), ceil(height / tile_size)
  std::uint32_t blocks_x = 0, blocks_y = 0;            // ceil(tiles_x / 4), ceil(tiles_y / 4)

  // Throws tilelight::Error naming the value when width/height is 0 or tile_size is not 4, 8 or
  // 16, e.g. "TileGrid: width must be > 0 (got 0)", "TileGrid: tile_size must be 4, 8 or 16
  // (got 5)". Also throws when the frame is so large that the index count (6 per tile) would not
  // fit in 32 bits, or a corner vertex would not fit in the 30 bits of a point index
  // (tile_primitive.h).
  static TileGrid make(std::uint32_t width, std::uint32_t height, std::uint32_t tile_size = 4);

  std::uint32_t tile_count() const;   // tiles_x * tiles_y
  std::uint32_t block_count() const;  // blocks_x * blocks_y
  std::size_t id_bytes() const;       // block_count() * 16: size of the blocked ID array

  // Blocked layout: block b = (ty/4)*blocks_x + tx/4 holds 16 bytes, row-major inside the block:
  // offset = b*16 + (ty%4)*4 + (tx%4). A block row (4 bytes) is therefore one little-endian uint32
  // whose byte i is tile x%4 == i. Entries for tiles outside the grid (partial blocks) hold kNoTile.
  // Precondition (unchecked): tile_x < blocks_x*4, tile_y < blocks_y*4.
  std::uint32_t blocked_offset(std::uint32_t tile_x, std::uint32_t tile_y) const;

  std::uint32_t vertex_count() const;  // (tiles_x + 1) * (tiles_y + 1)
  // corner_y*(tiles_x+1)+corner_x. Precondition (unchecked): corner_x <= tiles_x, corner_y <= tiles_y.
  std::uint32_t vertex_index(std::uint32_t corner_x, std::uint32_t corner_y) const;

  // Corner positions in pixels, 2 floats per vertex in vertex_index order; x = min(cx*tile_size, width),
  // y = min(cy*tile_size, height) so partial tiles at the right/bottom edge end at the frame edge.
  std::vector<float> corner_vertices() const;

  std::uint32_t max_index_count() const;  // tile_count() * 6: the preallocated index buffer size
};

// Row-major per-tile IDs (tiles_x*tiles_y) <-> blocked layout (id_bytes(), kNoTile padding).
// Both throw tilelight::Error when the input size does not match the grid.
std::vector<std::uint8_t> to_blocked(const TileGrid& grid, std::span<const std::uint8_t> row_major);
std::vector<std::uint8_t> to_row_major(const TileGrid& grid, std::span<const std::uint8_t> blocked);

}  // namespace tilelight
