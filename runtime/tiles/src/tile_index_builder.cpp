#include "tilelight/tiles/tile_index_builder.h"

#include "raw_class_map.h"
#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace tilelight {
namespace {

static_assert(kMaxDrawClasses <= kNoClass, "a draw class must never read as kNoClass");

// A block row whose 4 bytes are all equal to its lowest byte.
constexpr bool row_is_uniform(std::uint32_t row) { return row == (row & 0xFFu) * 0x01010101u; }

bool rows_are_uniform(const std::uint32_t (&rows)[kBlockTiles]) {
  return rows[0] == rows[1] && rows[0] == rows[2] && rows[0] == rows[3] && row_is_uniform(rows[0]);
}

}  // namespace

struct TileIndexBuilder::Counts {
  // Several histograms, summed at the end: consecutive rectangles of one ID (a uniform region)
  // would otherwise make one long store-to-load dependency chain through a single counter.
  static constexpr std::uint32_t kLanes = 4;
  std::array<std::array<std::uint32_t, kMaxDrawClasses>, kLanes> rects{};
  std::array<std::array<std::uint32_t, kMaxDrawClasses>, kLanes> tiles{};
  std::array<std::array<std::uint32_t, kMaxDrawClasses>, kLanes> primitives{};
  TilePrimitive primitive = TilePrimitive::triangles;

  // Appends one rectangle to `out` and counts it in `lane` (< kLanes; neighbours should differ);
  // returns the number of rectangles written (1).
  std::uint32_t emit(Rect* out, std::uint32_t lane, std::uint32_t v00, std::uint8_t id, std::uint32_t w,
                     std::uint32_t h) {
    *out = Rect{v00, id, static_cast<std::uint8_t>(w), static_cast<std::uint8_t>(h)};
    ++rects[lane][id];
    tiles[lane][id] += w * h;
    primitives[lane][id] += primitives_for_rect(primitive, w, h);
    return 1;
  }

  static std::array<std::uint32_t, kMaxDrawClasses> sum(
      const std::array<std::array<std::uint32_t, kMaxDrawClasses>, kLanes>& lanes) {
    std::array<std::uint32_t, kMaxDrawClasses> total{};
    for (const auto& lane : lanes) {
      for (std::uint32_t id = 0; id < kMaxDrawClasses; ++id) total[id] += lane[id];
    }
    return total;
  }
};

TileIndexBuilder::TileIndexBuilder(const TileGrid& grid, std::span<const std::uint8_t> lut,
                                   std::span<const bool> pruned, std::uint32_t class_count, TilePrimitive primitive)
    : grid_(grid),
      class_count_(class_count),
      primitive_(primitive),
      map_(make_raw_class_map("TileIndexBuilder", lut, pruned, class_count, kMaxDrawClasses)) {
  rects_.resize(grid_.tile_count());
}

void TileIndexBuilder::throw_bad_tile(const std::uint8_t* raw, std::uint32_t bx, std::uint32_t by) const {
  // Cold path: rescan the block in blocked order to name its first bad tile.
  const std::uint32_t w = std::min(kBlockTiles, grid_.tiles_x - bx * kBlockTiles);
  const std::uint32_t h = std::min(kBlockTiles, grid_.tiles_y - by * kBlockTiles);
  for (std::uint32_t row = 0; row < h; ++row) {
    for (std::uint32_t col = 0; col < w; ++col) {
      const std::uint8_t value = raw[row * kBlockTiles + col];
      if ((map_[value] & kNoClass) == 0) continue;
      throw_no_class(bx * kBlockTiles + col, by * kBlockTiles + row, value);
    }
  }
  throw Error(fmt::format("block ({}, {}): invalid raw ID not found (internal error)", bx, by));
}

std::uint32_t TileIndexBuilder::full_block(const std::uint8_t* raw, std::uint32_t bx, std::uint32_t by, bool coalesce,
                                           Rect* out, Counts& counts) const {
  const std::uint32_t stride = grid_.tiles_x + 1;
  const std::uint32_t v00 = by * kBlockTiles * stride + bx * kBlockTiles;
  std::uint32_t rows[kBlockTiles];
  std::memcpy(rows, raw, sizeof rows);
  // Scene-like frames are mostly blocks of one raw ID: one lookup instead of sixteen.
  if (coalesce && rows_are_uniform(rows)) {
    const std::uint8_t id = map_[raw[0]];
    if ((id & kNoClass) != 0) throw_bad_tile(raw, bx, by);
    return counts.emit(out, bx % Counts::kLanes, v00, id, kBlockTiles, kBlockTiles);
  }
  std::uint8_t mapped[kBlockTileCount];
  std::uint8_t bad = 0;
  for (std::uint32_t i = 0; i < kBlockTileCount; ++i) {
    mapped[i] = map_[raw[i]];
    bad |= mapped[i];
  }
  if ((bad & kNoClass) != 0) throw_bad_tile(raw, bx, by);

  std::uint32_t n = 0;
  if (!coalesce) {
    for (std::uint32_t row = 0; row < kBlockTiles; ++row) {
      for (std::uint32_t col = 0; col < kBlockTiles; ++col) {
        n += counts.emit(out + n, col, v00 + row * stride + col, mapped[row * kBlockTiles + col], 1, 1);
      }
    }
    return n;
  }
  // Different raw IDs may still share an optimised ID: compare after the LUT.
  std::memcpy(rows, mapped, sizeof rows);
  if (rows_are_uniform(rows)) {
    return counts.emit(out, bx % Counts::kLanes, v00, mapped[0], kBlockTiles, kBlockTiles);
  }
  for (std::uint32_t row = 0; row < kBlockTiles; ++row) {
    const std::uint8_t* ids = mapped + std::size_t{row} * kBlockTiles;
    const std::uint32_t v_row = v00 + row * stride;
    if (row_is_uniform(rows[row])) {
      n += counts.emit(out + n, row, v_row, ids[0], kBlockTiles, 1);
      continue;
    }
    std::uint32_t start = 0;
    for (std::uint32_t col = 1; col <= kBlockTiles; ++col) {
      if (col == kBlockTiles || ids[col] != ids[start]) {
        n += counts.emit(out + n, start, v_row + start, ids[start], col - start, 1);
        start = col;
      }
    }
  }
  return n;
}

std::uint32_t TileIndexBuilder::partial_block(const std::uint8_t* raw, std::uint32_t bx, std::uint32_t by,
                                              bool coalesce, Rect* out, Counts& counts) const {
  // Blocks on the right/bottom edge: only the w x h tiles inside the grid count; the padding
  // slots are never read.
  const std::uint32_t w = std::min(kBlockTiles, grid_.tiles_x - bx * kBlockTiles);
  const std::uint32_t h = std::min(kBlockTiles, grid_.tiles_y - by * kBlockTiles);
  const std::uint32_t stride = grid_.tiles_x + 1;
  const std::uint32_t v00 = by * kBlockTiles * stride + bx * kBlockTiles;
  std::uint8_t mapped[kBlockTileCount]{};
  std::uint8_t bad = 0;
  bool uniform = true;
  for (std::uint32_t row = 0; row < h; ++row) {
    for (std::uint32_t col = 0; col < w; ++col) {
      const std::uint32_t i = row * kBlockTiles + col;
      mapped[i] = map_[raw[i]];
      bad |= mapped[i];
      uniform = uniform && mapped[i] == mapped[0];
    }
  }
  if ((bad & kNoClass) != 0) throw_bad_tile(raw, bx, by);
  if (coalesce && uniform) return counts.emit(out, bx % Counts::kLanes, v00, mapped[0], w, h);

  std::uint32_t n = 0;
  for (std::uint32_t row = 0; row < h; ++row) {
    const std::uint8_t* ids = mapped + std::size_t{row} * kBlockTiles;
    const std::uint32_t v_row = v00 + row * stride;
    std::uint32_t start = 0;
    for (std::uint32_t col = 1; col <= w; ++col) {
      if (!coalesce || col == w || ids[col] != ids[start]) {
        n += counts.emit(out + n, start, v_row + start, ids[start], col - start, 1);
        start = col;
      }
    }
  }
  return n;
}

std::uint32_t TileIndexBuilder::find_rects(const std::uint8_t* ids, bool coalesce, Counts& counts) {
  const std::uint32_t full_bx = grid_.tiles_x / kBlockTiles;
  const std::uint32_t full_by = grid_.tiles_y / kBlockTiles;
  Rect* out = rects_.data();
  std::uint32_t n = 0;
  for (std::uint32_t by = 0; by < grid_.blocks_y; ++by) {
    const std::uint32_t row_full_bx = by < full_by ? full_bx : 0;
    for (std::uint32_t bx = 0; bx < grid_.blocks_x; ++bx) {
      const std::uint8_t* block = ids + (std::size_t{by} * grid_.blocks_x + bx) * kBlockTileCount;
      n += bx < row_full_bx ? full_block(block, bx, by, coalesce, out + n, counts)
                            : partial_block(block, bx, by, coalesce, out + n, counts);
    }
  }
  return n;
}

void TileIndexBuilder::write_indices(std::uint32_t rect_count,
                                     const std::array<std::uint32_t, kMaxDrawClasses>& primitives,
                                     std::span<std::uint32_t> indices, std::span<DrawRecord> draws) const {
  // Pass 2: exclusive prefix sum of the per-ID index counts gives each ID's first index.
  const std::uint32_t per_primitive = indices_per_primitive(primitive_);
  std::array<std::uint32_t, kMaxDrawClasses> cursor{};
  std::uint32_t first = 0;
  for (std::uint32_t id = 0; id < class_count_; ++id) {
    cursor[id] = first;
    draws[id] = DrawRecord{primitives[id] * per_primitive, 1, first, 0, 0};
    first += primitives[id] * per_primitive;
  }
  if (rect_count == 0) return;
  // Pass 3: scatter each rectangle's primitives into its ID's range, keeping block order.
  // The current ID's write position stays in a register while the ID repeats (large regions).
  std::uint32_t* const base = indices.data();
  std::uint8_t current = rects_[0].id;
  std::uint32_t* dst = base + cursor[current];
  const bool points = primitive_ == TilePrimitive::points;
  for (std::uint32_t i = 0; i < rect_count; ++i) {
    const Rect r = rects_[i];
    if (r.id != current) {
      cursor[current] = static_cast<std::uint32_t>(dst - base);
      current = r.id;
      dst = base + cursor[current];
    }
    dst = points ? write_points(r, dst) : write_triangles(r, dst);
  }
}

std::uint32_t* TileIndexBuilder::write_triangles(const Rect& r, std::uint32_t* dst) const {
  const std::uint32_t stride = grid_.tiles_x + 1;
  const std::uint32_t v10 = r.v00 + r.w;
  const std::uint32_t v01 = r.v00 + r.h * stride;
  const std::uint32_t v11 = v01 + r.w;
  dst[0] = r.v00;
  dst[1] = v10;
  dst[2] = v01;
  dst[3] = v10;
  dst[4] = v11;
  dst[5] = v01;
  return dst + 6;
}

std::uint32_t* TileIndexBuilder::write_points(const Rect& r, std::uint32_t* dst) const {
  if (r.w == r.h) {
    *dst = point_index(r.v00, r.w);
    return dst + 1;
  }
  // A run in a block row, or a uniform partial block at the frame's edge: one point per tile.
  const std::uint32_t stride = grid_.tiles_x + 1;
  for (std::uint32_t row = 0; row < r.h; ++row) {
    for (std::uint32_t col = 0; col < r.w; ++col) *dst++ = point_index(r.v00 + row * stride + col, 1);
  }
  return dst;
}

IndexBuildStats TileIndexBuilder::build(std::span<const std::uint8_t> blocked_raw_ids, bool coalesce,
                                        std::span<std::uint32_t> indices, std::span<DrawRecord> draws) {
  if (blocked_raw_ids.size() != grid_.id_bytes()) {
    throw Error(fmt::format("TileIndexBuilder::build: expected {} blocked raw ID bytes, got {}", grid_.id_bytes(),
                            blocked_raw_ids.size()));
  }
  if (indices.size() < grid_.max_index_count()) {
    throw Error(fmt::format("TileIndexBuilder::build: the index buffer holds {} indices, needs {}", indices.size(),
                            grid_.max_index_count()));
  }
  if (draws.size() != class_count_) {
    throw Error(fmt::format("TileIndexBuilder::build: expected {} draw records, got {}", class_count_, draws.size()));
  }
  Counts counts;
  counts.primitive = primitive_;
  const std::uint32_t rect_count = find_rects(blocked_raw_ids.data(), coalesce, counts);
  IndexBuildStats stats;
  stats.rectangles = Counts::sum(counts.rects);
  stats.class_tiles = Counts::sum(counts.tiles);
  stats.primitives = Counts::sum(counts.primitives);
  write_indices(rect_count, stats.primitives, indices, draws);

  stats.tiles = grid_.tile_count();
  stats.primitives_uncoalesced = stats.tiles;
  stats.rectangles_coalesced = rect_count;
  for (std::uint32_t id = 0; id < class_count_; ++id) stats.primitives_coalesced += stats.primitives[id];
  stats.index_count = stats.primitives_coalesced * indices_per_primitive(primitive_);
  return stats;
}

}  // namespace tilelight
