#version 450
// tile_point.vert -- places one square of tiles as a point sprite for the tiled light pass.
//
// A point is a screen-aligned square with no interior edge: unlike the two triangles of a
// rectangle, it has no diagonal cutting through the pixels it covers, so a rasteriser shades
// each of them once (runtime/tiles/include/tilelight/tiles/tile_primitive.h). The index is the
// corner-grid vertex of the square's top-left corner, with (side in tiles - 1) in bits 30..31; no
// per-vertex data is read. The viewport spans whole tiles (tiles_x * tile_size pixels wide), so
// the centre of a partial tile at the right or bottom edge lies inside it (a point whose centre
// is outside is culled whole); the scissor keeps drawing inside the frame.
//
// The grid's shape comes in as an instance-rate attribute (one instance) rather than a push
// constant: lavapipe draws the same points about 40 % slower when the vertex shader has no
// input attribute at all (measured, docs/results.md).

layout(location = 0) in vec2 in_grid;  // per instance: corner vertices per grid row (tiles_x + 1), tile size in pixels

layout(push_constant) uniform TilePush {
    vec2 inv_viewport;  // 1 / viewport size in pixels (whole tiles)
} push;

const uint POINT_SIDE_SHIFT = 30u;
const uint POINT_CORNER_MASK = (1u << POINT_SIDE_SHIFT) - 1u;

void main()
{
    uint index = uint(gl_VertexIndex);
    uint corner_stride = uint(in_grid.x);
    float tile_size = in_grid.y;
    uint corner = index & POINT_CORNER_MASK;
    float side = float((index >> POINT_SIDE_SHIFT) + 1u) * tile_size;
    vec2 top_left = vec2(float(corner % corner_stride), float(corner / corner_stride)) * tile_size;
    gl_PointSize = side;
    gl_Position = vec4((top_left + 0.5 * side) * push.inv_viewport * 2.0 - 1.0, 0.0, 1.0);
}
