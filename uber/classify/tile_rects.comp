#version 450
// tile_rects.comp -- GPU-driven index build, passes 1 and 3 (count, fill), one invocation per
// block of 4x4 tiles. FILL_PASS selects the action; the walk over rectangles is shared, so the
// fill writes exactly the rectangles the count pass counted.
//   count: per draw class, primitives, rectangles and tiles (a shared histogram per work group,
//          then one global atomic per ID per work group), and tiles with an invalid raw ID;
//   fill:  each rectangle takes the next slots of its ID (atomic cursor set by tile_prefix.comp)
//          and writes its primitives there (two triangles, or its points).
#extension GL_GOOGLE_include_directive : require
#include "tile_rects.glsl"

layout(local_size_x = 128) in; // >= MAX_DRAW_CLASSES: one invocation per class clears/flushes

layout(constant_id = 0) const bool FILL_PASS = false;
layout(constant_id = 1) const bool COALESCE = true;

shared uint group_primitives[MAX_DRAW_CLASSES];
shared uint group_rectangles[MAX_DRAW_CLASSES];
shared uint group_tiles[MAX_DRAW_CLASSES];

void emit(uint id, uint x0, uint y0, uint x1, uint y1)
{
    uint primitives = primitives_for_rect(x0, y0, x1, y1);
    if (FILL_PASS) {
        uint slot = atomicAdd(counters.cursor[id], primitives);
        write_rectangle(slot * indices_per_primitive(), x0, y0, x1, y1);
    } else {
        atomicAdd(group_primitives[id], primitives);
        atomicAdd(group_rectangles[id], 1u);
        atomicAdd(group_tiles[id], (x1 - x0) * (y1 - y0));
    }
}

void walk_block(uint block_index)
{
    Block b = load_block(block_index);
    if (!FILL_PASS) {
        for (uint i = 0u; i < 16u; ++i) {
            if (b.ids[i] == INVALID_TILE) atomicAdd(counters.invalid_tiles, 1u);
        }
    }
    if (COALESCE && block_is_uniform(b)) {
        uvec2 end = b.first_tile + b.tile_count;
        emit(b.ids[0], b.first_tile.x, b.first_tile.y, end.x, end.y);
        return;
    }
    for (uint row = 0u; row < b.tile_count.y; ++row) {
        uint y = b.first_tile.y + row;
        uint run_start = 0u;
        for (uint i = 1u; i <= b.tile_count.x; ++i) {
            uint id = b.ids[row * 4u + run_start];
            bool run_ends = i == b.tile_count.x || !COALESCE || b.ids[row * 4u + i] != id;
            if (run_ends) {
                if (id < MAX_DRAW_CLASSES) {
                    emit(id, b.first_tile.x + run_start, y, b.first_tile.x + i, y + 1u);
                }
                run_start = i;
            }
        }
    }
}

void main()
{
    if (!FILL_PASS) {
        if (gl_LocalInvocationIndex < MAX_DRAW_CLASSES) {
            group_primitives[gl_LocalInvocationIndex] = 0u;
            group_rectangles[gl_LocalInvocationIndex] = 0u;
            group_tiles[gl_LocalInvocationIndex] = 0u;
        }
        barrier();
    }
    uint block_index = gl_GlobalInvocationID.x;
    if (block_index < push.grid.z * push.grid.w) {
        walk_block(block_index);
    }
    if (!FILL_PASS) {
        barrier();
        uint id = gl_LocalInvocationIndex;
        if (id < MAX_DRAW_CLASSES && group_rectangles[id] != 0u) {
            atomicAdd(counters.primitives[id], group_primitives[id]);
            atomicAdd(counters.rectangles[id], group_rectangles[id]);
            atomicAdd(counters.tiles[id], group_tiles[id]);
        }
    }
}
