// tile_rects.glsl -- the GPU-driven index build: shared interface and the coalescing rule.
//
// The same rule as the CPU builder (runtime/tiles/src/tile_index_builder.cpp), so both paths
// emit the same rectangles: a block of 4x4 tiles whose tiles (inside the frame) all have one
// optimised ID becomes one rectangle; otherwise each maximal run of equal IDs in a block row
// becomes one rectangle. Counting and filling both call for_each_rectangle-style code below
// with a different action, so they cannot disagree.
//
// Each rectangle becomes primitives as runtime/tiles/include/tilelight/tiles/tile_primitive.h
// says: two triangles (6 indices over the corner grid), or with POINT_PRIMITIVES one point per square
// (a square rectangle whole, any other one tile at a time), indexed by the square's top-left
// corner vertex with (side in tiles - 1) in bits 30..31.

#ifndef UBER_TILE_RECTS_GLSL
#define UBER_TILE_RECTS_GLSL

// Draw classes: the 32 optimised IDs, or all 128 raw IDs when the raw permutations are drawn.
const uint MAX_DRAW_CLASSES = 128u;

layout(set = 0, binding = 0, std430) readonly buffer TileIds {
    uint block_rows[]; // raw IDs, blocked layout (classify_tiles.comp)
} tile_ids;

layout(set = 0, binding = 1, std430) readonly buffer Lut {
    uint class_for_byte[256]; // raw ID byte -> draw class (optimised ID, or the raw ID itself
                              // when drawing raw permutations); 0xFF = impossible or out of range
} lut;

// Specialisation constant 2 of both passes: draw points instead of triangle pairs.
layout(constant_id = 2) const bool POINT_PRIMITIVES = false;
const uint POINT_SIDE_SHIFT = 30u;

layout(set = 0, binding = 2, std430) buffer Counters {
    uint primitives[MAX_DRAW_CLASSES]; // per draw class
    uint rectangles[MAX_DRAW_CLASSES]; // per draw class
    uint tiles[MAX_DRAW_CLASSES];      // per draw class
    uint cursor[MAX_DRAW_CLASSES];     // next free primitive slot per class (set by the prefix pass)
    uint invalid_tiles;   // tiles whose raw ID is impossible or out of range
} counters;

layout(set = 0, binding = 3, std430) writeonly buffer Indices {
    uint indices[];
} index_buffer;

struct DrawIndexedIndirect {
    uint index_count;
    uint instance_count;
    uint first_index;
    int vertex_offset;
    uint first_instance;
};

layout(set = 0, binding = 4, std430) buffer Draws {
    DrawIndexedIndirect draws[MAX_DRAW_CLASSES];
} draw_records;

layout(push_constant) uniform RectPush {
    uvec4 grid;    // tiles_x, tiles_y, blocks_x, blocks_y
    uvec4 classes; // x: draw classes in use (32 optimised or 128 raw)
} push;

const uint NO_TILE = 0xFFu;
const uint INVALID_TILE = 0xFEu;

struct Block {
    uint ids[16];      // optimised IDs, NO_TILE outside the frame, INVALID_TILE for bad raw IDs
    uvec2 first_tile;
    uvec2 tile_count;  // tiles of this block inside the frame (1..4 each)
};

Block load_block(uint block_index)
{
    Block b;
    b.first_tile = uvec2(block_index % push.grid.z, block_index / push.grid.z) * 4u;
    b.tile_count = min(uvec2(4u), push.grid.xy - b.first_tile);
    for (uint row = 0u; row < 4u; ++row) {
        uint packed_row = tile_ids.block_rows[block_index * 4u + row];
        for (uint i = 0u; i < 4u; ++i) {
            bool inside = i < b.tile_count.x && row < b.tile_count.y;
            uint raw = (packed_row >> (8u * i)) & 0xFFu;
            uint id = lut.class_for_byte[raw];
            b.ids[row * 4u + i] = inside ? (id == NO_TILE ? INVALID_TILE : id) : NO_TILE;
        }
    }
    return b;
}

bool block_is_uniform(Block b)
{
    uint first = b.ids[0];
    for (uint i = 1u; i < 16u; ++i) {
        if (b.ids[i] != NO_TILE && b.ids[i] != first) {
            return false;
        }
    }
    return first != INVALID_TILE;
}

uint indices_per_primitive()
{
    return POINT_PRIMITIVES ? 1u : 6u;
}

// Primitives the tile rectangle [x0, x1) x [y0, y1) becomes.
uint primitives_for_rect(uint x0, uint y0, uint x1, uint y1)
{
    uvec2 size = uvec2(x1 - x0, y1 - y0);
    return POINT_PRIMITIVES && size.x != size.y ? size.x * size.y : 1u;
}

// The indices of the tile rectangle [x0, x1) x [y0, y1), from index `first` on: six over the
// corner grid (two triangles), or one per point.
void write_rectangle(uint first, uint x0, uint y0, uint x1, uint y1)
{
    uint stride = push.grid.x + 1u;
    uint v00 = y0 * stride + x0;
    if (POINT_PRIMITIVES) {
        uvec2 size = uvec2(x1 - x0, y1 - y0);
        if (size.x == size.y) {
            index_buffer.indices[first] = v00 | ((size.x - 1u) << POINT_SIDE_SHIFT);
            return;
        }
        for (uint row = 0u; row < size.y; ++row) {
            for (uint col = 0u; col < size.x; ++col) {
                index_buffer.indices[first + row * size.x + col] = v00 + row * stride + col;
            }
        }
        return;
    }
    uint v10 = y0 * stride + x1;
    uint v01 = y1 * stride + x0;
    uint v11 = y1 * stride + x1;
    index_buffer.indices[first + 0u] = v00;
    index_buffer.indices[first + 1u] = v10;
    index_buffer.indices[first + 2u] = v01;
    index_buffer.indices[first + 3u] = v10;
    index_buffer.indices[first + 4u] = v11;
    index_buffer.indices[first + 5u] = v01;
}

#endif // UBER_TILE_RECTS_GLSL
