#include "tilelight/tiles/tile_primitive.h"

namespace tilelight {

std::optional<TilePrimitive> parse_tile_primitive(std::string_view text) {
  if (text == to_string(TilePrimitive::points)) return TilePrimitive::points;
  if (text == to_string(TilePrimitive::triangles)) return TilePrimitive::triangles;
  return std::nullopt;
}

}  // namespace tilelight
