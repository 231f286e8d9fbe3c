// The point encoding the CPU and GPU index builds share with uber/tile_point.vert, and how many
// primitives a rectangle of tiles becomes (tile_primitive.h).
#include "tilelight/tiles/tile_primitive.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>

namespace tilelight {
namespace {

// The largest corner vertex and the widest point fill all 32 bits; nothing spills over.
static_assert(point_index(kPointCornerMask, 4) == 0xFFFFFFFFu);
static_assert(kPointCornerMask == (1u << 30) - 1);

TEST(TilePrimitive, PointIndexRoundTrips) {
  for (const std::uint32_t corner : {0u, 1u, 5u, 12345u, 1u << 29, kPointCornerMask - 1, kPointCornerMask}) {
    for (std::uint32_t side = 1; side <= 4; ++side) {
      const std::uint32_t index = point_index(corner, side);
      EXPECT_EQ(point_corner_vertex(index), corner) << corner << " side " << side;
      EXPECT_EQ(point_side_tiles(index), side) << corner << " side " << side;
    }
  }
}

TEST(TilePrimitive, PointIndexKeepsTheSideInBits30And31) {
  EXPECT_EQ(point_index(0, 1), 0u);  // a one-tile point is its plain corner vertex
  EXPECT_EQ(point_index(32, 2), 0x40000020u);
  EXPECT_EQ(point_index(7, 3), 0x80000007u);
  EXPECT_EQ(point_index(7, 4), 0xC0000007u);
  EXPECT_EQ(point_index(kPointCornerMask, 1), 0x3FFFFFFFu);
}

struct RectCase {
  TilePrimitive primitive;
  std::uint32_t w, h;
  std::uint32_t primitives;
};

TEST(TilePrimitive, PrimitivesPerRectangle) {
  const RectCase cases[] = {{TilePrimitive::points, 1, 1, 1},
                            {TilePrimitive::points, 2, 2, 1},
                            {TilePrimitive::points, 3, 3, 1},
                            {TilePrimitive::points, 4, 4, 1},
                            // Not square: one point per tile.
                            {TilePrimitive::points, 3, 1, 3},
                            {TilePrimitive::points, 4, 1, 4},
                            {TilePrimitive::points, 1, 4, 4},
                            {TilePrimitive::points, 2, 4, 8},
                            {TilePrimitive::points, 4, 3, 12},
                            // Triangles: one pair per rectangle, whatever its shape.
                            {TilePrimitive::triangles, 1, 1, 1},
                            {TilePrimitive::triangles, 4, 4, 1},
                            {TilePrimitive::triangles, 2, 4, 1},
                            {TilePrimitive::triangles, 4, 1, 1}};
  for (const RectCase& c : cases) {
    EXPECT_EQ(primitives_for_rect(c.primitive, c.w, c.h), c.primitives)
        << to_string(c.primitive) << " " << c.w << "x" << c.h;
  }
}

TEST(TilePrimitive, IndicesPerPrimitive) {
  EXPECT_EQ(indices_per_primitive(TilePrimitive::triangles), 6u);
  EXPECT_EQ(indices_per_primitive(TilePrimitive::points), 1u);
}

TEST(TilePrimitive, NamesRoundTrip) {
  EXPECT_EQ(to_string(TilePrimitive::points), "points");
  EXPECT_EQ(to_string(TilePrimitive::triangles), "triangles");
  for (const TilePrimitive p : {TilePrimitive::points, TilePrimitive::triangles}) {
    EXPECT_EQ(parse_tile_primitive(to_string(p)), std::optional{p});
  }
  // "auto" is the CLI's word for "let the renderer choose", not a primitive.
  for (const char* text : {"auto", "Points", "point", "triangles ", ""}) {
    EXPECT_EQ(parse_tile_primitive(text), std::nullopt) << "'" << text << "'";
  }
}

}  // namespace
}  // namespace tilelight
