#version 450
// tile_lists.comp -- the GPU-driven build of the compute light pass's work (--path gpu
// --light-pass compute): per draw class, the list of its tiles and the indirect dispatch that
// shades them (tile_lists.glsl). Three passes of this one shader, chosen by PASS:
//   0 count:  one invocation per block row (4 tiles); a shared histogram of draw classes per
//             workgroup, then one global atomic per class per workgroup; tiles whose raw ID is
//             impossible or out of range are counted apart and shaded by nobody;
//   1 prefix: one invocation: each class's first slot (exclusive prefix sum), its count and its
//             VkDispatchIndirectCommand;
//   2 fill:   the same walk as the count; each workgroup reserves its range of each class with
//             one atomic and writes its tiles' coordinates there.
// Within a class the order of tiles depends on which workgroup ran first; every tile appears
// once, so the lit image does not depend on it.
#extension GL_GOOGLE_include_directive : require

#define TILE_LISTS_SET 0
#define TILE_LISTS_BINDING 3
#define TILE_LISTS_ACCESS
#include "tile_lists.glsl"

layout(constant_id = 0) const uint PASS = 0u;
const uint PASS_COUNT = 0u;
const uint PASS_PREFIX = 1u;
const uint PASS_FILL = 2u;
layout(local_size_x = 128) in; // == TILE_LIST_MAX_CLASSES: one invocation per class flushes

layout(set = 0, binding = 0, std430) readonly buffer TileIds {
    uint block_rows[]; // raw IDs, blocked layout (classify_tiles.comp)
} tile_ids;

layout(set = 0, binding = 1, std430) readonly buffer Lut {
    uint class_for_byte[256]; // raw ID byte -> draw class; 0xFF = impossible or out of range
} lut;

layout(set = 0, binding = 2, std430) buffer Counters {
    uint tiles[TILE_LIST_MAX_CLASSES];  // per draw class (count pass)
    uint cursor[TILE_LIST_MAX_CLASSES]; // next free slot per class (prefix, then fill)
    uint invalid_tiles;                 // tiles whose raw ID is impossible or out of range
} counters;

struct DispatchIndirect {
    uint x, y, z;
};

layout(set = 0, binding = 4, std430) writeonly buffer Dispatches {
    DispatchIndirect dispatches[TILE_LIST_MAX_CLASSES];
} dispatch_records;

layout(push_constant) uniform ListPush {
    uvec4 grid;    // tiles_x, tiles_y, blocks_x, blocks_y
    uvec4 classes; // x: draw classes in use (32 or 128), y: tiles per light workgroup
} push;

const uint NO_CLASS = 0xFFu;

shared uint group_tiles[TILE_LIST_MAX_CLASSES];
shared uint group_base[TILE_LIST_MAX_CLASSES];

// The draw class of each of the 4 tiles of block row `row_index` (NO_CLASS outside the frame),
// and the number of invalid tiles among them.
uvec4 row_classes(uint row_index, out uint invalid, out uvec2 first_tile)
{
    uint block = row_index / 4u;
    first_tile = uvec2(block % push.grid.z, block / push.grid.z) * 4u + uvec2(0u, row_index % 4u);
    uint packed_row = tile_ids.block_rows[row_index];
    uvec4 classes = uvec4(NO_CLASS);
    invalid = 0u;
    for (uint i = 0u; i < 4u; ++i) {
        if (first_tile.x + i < push.grid.x && first_tile.y < push.grid.y) {
            uint c = lut.class_for_byte[(packed_row >> (8u * i)) & 0xFFu];
            classes[i] = c;
            invalid += c == NO_CLASS ? 1u : 0u;
        }
    }
    return classes;
}

void prefix()
{
    uint first = 0u;
    for (uint c = 0u; c < push.classes.x; ++c) {
        uint count = counters.tiles[c];
        tile_lists.first[c] = first;
        tile_lists.count[c] = count;
        counters.cursor[c] = first;
        dispatch_records.dispatches[c] = DispatchIndirect((count + push.classes.y - 1u) / push.classes.y, 1u, 1u);
        first += count;
    }
}

void main()
{
    if (PASS == PASS_PREFIX) {
        if (gl_GlobalInvocationID.x == 0u) prefix();
        return;
    }
    uint lane = gl_LocalInvocationID.x;
    group_tiles[lane] = 0u;
    barrier();

    uint row_index = gl_GlobalInvocationID.x;
    bool in_grid = row_index < push.grid.z * push.grid.w * 4u;
    uvec4 classes = uvec4(NO_CLASS);
    uvec2 first_tile = uvec2(0u);
    uvec4 slots = uvec4(0u);
    if (in_grid) {
        uint invalid;
        classes = row_classes(row_index, invalid, first_tile);
        if (PASS == PASS_COUNT && invalid != 0u) atomicAdd(counters.invalid_tiles, invalid);
        for (uint i = 0u; i < 4u; ++i) {
            if (classes[i] != NO_CLASS) slots[i] = atomicAdd(group_tiles[classes[i]], 1u);
        }
    }
    barrier();
    if (PASS == PASS_COUNT) {
        if (group_tiles[lane] != 0u) atomicAdd(counters.tiles[lane], group_tiles[lane]);
        return;
    }
    if (group_tiles[lane] != 0u) group_base[lane] = atomicAdd(counters.cursor[lane], group_tiles[lane]);
    barrier();
    for (uint i = 0u; i < 4u; ++i) {
        if (classes[i] != NO_CLASS) {
            tile_lists.tiles[group_base[classes[i]] + slots[i]] = tile_list_pack(first_tile + uvec2(i, 0u));
        }
    }
}
