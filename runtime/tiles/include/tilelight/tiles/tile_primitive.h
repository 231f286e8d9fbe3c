#pragma once
// How the tile pass turns a rectangle of tiles into primitives.
//
// Vulkan has no rectangle primitive. The chapter draws each rectangle as two triangles, but a
// rasteriser shades a 2x2 quad (GPUs) or a 4x4 block (lavapipe) once per triangle that touches
// it: the diagonal of every tile-sized rectangle cuts through the very pixels it covers, and on
// lavapipe every block on a diagonal is shaded twice. A point sprite is a screen-aligned square
// with no interior edge, so a square rectangle drawn as one point shades each pixel once.
//
//   triangles  6 indices per rectangle over the corner grid (TileGrid::vertex_index):
//              v(x0,y0), v(x1,y0), v(x0,y1), v(x1,y0), v(x1,y1), v(x0,y1).
//   points     1 index per square: a square rectangle (w == h tiles) is one point; any other
//              rectangle is one point per tile. The index is the corner-grid vertex of the
//              square's top-left corner with (side in tiles - 1) in bits 30..31
//              (point_index()); uber/tile_point.vert decodes it (no per-vertex data; the
//              grid's shape comes as an instance-rate attribute).
//              Needs the largePoints feature and a point size range reaching 4 tiles.

#include <cstdint>
#include <optional>
#include <string_view>

namespace tilelight {

enum class TilePrimitive { triangles, points };

inline constexpr std::uint32_t kPointSideShift = 30;  // bits 30..31: side in tiles - 1 (1..4 tiles)
inline constexpr std::uint32_t kPointCornerMask = (1u << kPointSideShift) - 1;

// Precondition: corner_vertex <= kPointCornerMask (TileGrid::make guarantees it), 1 <= side <= 4.
constexpr std::uint32_t point_index(std::uint32_t corner_vertex, std::uint32_t side_tiles) {
  return corner_vertex | ((side_tiles - 1) << kPointSideShift);
}
constexpr std::uint32_t point_corner_vertex(std::uint32_t index) { return index & kPointCornerMask; }
constexpr std::uint32_t point_side_tiles(std::uint32_t index) { return (index >> kPointSideShift) + 1; }

// Primitives a w x h rectangle of tiles becomes.
constexpr std::uint32_t primitives_for_rect(TilePrimitive primitive, std::uint32_t w, std::uint32_t h) {
  return primitive == TilePrimitive::points && w != h ? w * h : 1;
}
constexpr std::uint32_t indices_per_primitive(TilePrimitive primitive) {
  return primitive == TilePrimitive::points ? 1 : 6;
}

constexpr std::string_view to_string(TilePrimitive primitive) {
  return primitive == TilePrimitive::points ? "points" : "triangles";
}
std::optional<TilePrimitive> parse_tile_primitive(std::string_view text);

}  // namespace tilelight
