#pragma once
// Builds, on the CPU, the one index buffer and the 32 indirect draw records that draw every
// optimised class's tiles with its own shader (GPU Pro 2, "Screen-Space Classification for
// Efficient Deferred Shading", Sections 4.9-4.10), with the chapter's tile coalescing.

#include "tilelight/tiles/draw_record.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/tiles/tile_primitive.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tilelight {

inline constexpr std::uint32_t kOptimisedClassCount = 32;
inline constexpr std::uint32_t kRawClassCount = 128;
// Draw classes: the 32 optimised IDs, or every raw ID when the raw permutations are drawn.
inline constexpr std::uint32_t kMaxDrawClasses = 128;

struct IndexBuildStats {
  // Per draw class (the first class_count entries are used): tiles, rectangles (the chapter's
  // coalescing) and the primitives drawing them (== rectangles for triangles; tile_primitive.h).
  std::array<std::uint32_t, kMaxDrawClasses> class_tiles{};
  std::array<std::uint32_t, kMaxDrawClasses> rectangles{};
  std::array<std::uint32_t, kMaxDrawClasses> primitives{};
  std::uint32_t tiles = 0;
  std::uint32_t primitives_uncoalesced = 0;  // == tiles: one primitive per tile
  std::uint32_t primitives_coalesced = 0;    // primitives actually emitted (== tiles when coalescing is off)
  std::uint32_t rectangles_coalesced = 0;    // rectangles found (== primitives_coalesced for triangles)
  std::uint32_t index_count = 0;             // 6 per rectangle (triangles) or 1 per point
};

// Coalescing rule (the GPU path implements the same rule): for each block in block order (by,
// then bx), if every tile of the block that lies inside the grid has the same optimised ID, emit
// ONE rectangle covering those tiles; otherwise emit, for each row of the block, one rectangle
// per maximal run of equal optimised IDs (left to right). Without coalescing: one rectangle per
// tile in blocked order. Within one optimised ID, rectangles appear in block order.
class TileIndexBuilder {
 public:
  // lut: raw ID -> draw class (128 entries, each < class_count): the optimised-ID LUT (32
  // classes), or the identity when drawing the raw permutations (128 classes); pruned: raw IDs
  // that can never occur (128 entries, or empty for "nothing pruned"); primitive: how each
  // rectangle is drawn (tile_primitive.h). Throws tilelight::Error on
  // a wrong size or an out-of-range LUT entry.
  // Allocates all scratch memory here, sized for the grid; build() never allocates.
  TileIndexBuilder(const TileGrid& grid, std::span<const std::uint8_t> lut, std::span<const bool> pruned,
                   std::uint32_t class_count = kOptimisedClassCount,
                   TilePrimitive primitive = TilePrimitive::triangles);

  // The three passes of the chapter: (1) walk the blocked raw IDs, map them through the LUT, find the
  // rectangles (coalesced or one per tile) and count them per optimised ID; (2) exclusive prefix sum of
  // the counts -> each ID's first index; (3) fill `indices` (triangles: 6 uint32 per rectangle, two
  // triangles v(x0,y0), v(x1,y0), v(x0,y1), v(x1,y0), v(x1,y1), v(x0,y1) over the corner grid, x1/y1
  // exclusive tile corners; points: one point_index() per square, a square rectangle whole, any
  // other one tile by tile in row-major order) and write draws[id] = {indexCount, instanceCount = 1, firstIndex, vertexOffset 0,
  // firstInstance 0}; an ID with no tiles gets indexCount 0 and instanceCount 1.
  // Preconditions (checked, tilelight::Error): blocked_raw_ids.size() == grid.id_bytes();
  // indices.size() >= grid.max_index_count(); draws.size() == class_count. A raw ID >= 128, a pruned raw
  // ID, or kNoTile inside the grid throws an Error naming the tile and value:
  // e.g. "tile (12, 7): raw ID 3 is impossible (a pruned class)" / "tile (12, 7): raw ID 200 is out of range (0..127)".
  // Padding slots (block entries outside the grid) are never read, so they may hold anything.
  // All errors are detected before anything is written: on a throw, indices and draws are unchanged.
  // Only indices[0, index_count) are written.
  IndexBuildStats build(std::span<const std::uint8_t> blocked_raw_ids, bool coalesce, std::span<std::uint32_t> indices,
                        std::span<DrawRecord> draws);

  const TileGrid& grid() const { return grid_; }
  std::uint32_t class_count() const { return class_count_; }
  TilePrimitive primitive() const { return primitive_; }

 private:
  // One emitted rectangle: its top-left corner vertex and its size in tiles (1..4 each).
  struct Rect {
    std::uint32_t v00;
    std::uint8_t id;
    std::uint8_t w;
    std::uint8_t h;
  };

  struct Counts;  // per-ID rectangle and tile counts of pass 1
  // Pass 1 over all blocks; returns the number of rectangles written to rects_.
  std::uint32_t find_rects(const std::uint8_t* ids, bool coalesce, Counts& counts);
  // Pass 1 for one block (a block fully inside the grid / one on the right or bottom edge):
  // writes its rectangles to `out` and returns how many. Throws on an invalid tile.
  std::uint32_t full_block(const std::uint8_t* raw, std::uint32_t bx, std::uint32_t by, bool coalesce, Rect* out,
                           Counts& counts) const;
  std::uint32_t partial_block(const std::uint8_t* raw, std::uint32_t bx, std::uint32_t by, bool coalesce, Rect* out,
                              Counts& counts) const;
  // Cold path: names the first invalid tile of a block known to hold one.
  [[noreturn]] void throw_bad_tile(const std::uint8_t* raw, std::uint32_t bx, std::uint32_t by) const;
  // Passes 2 and 3: prefix sum into the draw records, then the indices of every rectangle.
  void write_indices(std::uint32_t rect_count, const std::array<std::uint32_t, kMaxDrawClasses>& primitives,
                     std::span<std::uint32_t> indices, std::span<DrawRecord> draws) const;
  // Pass 3 for one rectangle; returns the position after its indices.
  std::uint32_t* write_triangles(const Rect& r, std::uint32_t* dst) const;
  std::uint32_t* write_points(const Rect& r, std::uint32_t* dst) const;

  TileGrid grid_;
  std::uint32_t class_count_ = kOptimisedClassCount;
  TilePrimitive primitive_ = TilePrimitive::triangles;
  // byte -> draw class, or no class for raw IDs >= 128 and pruned ones (src/raw_class_map.h);
  // one table lookup per tile both maps and validates.
  std::array<std::uint8_t, 256> map_{};
  std::vector<Rect> rects_;  // pass 1 output, tile_count() entries (the most rectangles possible)
};

}  // namespace tilelight
