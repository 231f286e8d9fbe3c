// tile_lists.glsl -- the compute light pass's work: one list of tiles per draw class.
//
// One buffer holds every class's list back to back: class c's tiles are
// tiles[first[c] .. first[c] + count[c]), each packed as x | y << 16 (tile coordinates). The
// host (runtime/tiles' TileListBuilder, CPU path) or uber/classify/tile_lists.comp (GPU path)
// writes it after classification; lighting.comp reads it, one indirect dispatch per class, whose
// VkDispatchIndirectCommand is { ceil(count[c] / tiles per workgroup), 1, 1 }.
//
// Before including this file, define TILE_LISTS_SET, TILE_LISTS_BINDING and TILE_LISTS_ACCESS
// (readonly or writeonly, or leave it empty) to place the buffer in the includer's layout; the
// defaults are the light pass's: set 1, binding 1, readonly.

#ifndef UBER_TILE_LISTS_GLSL
#define UBER_TILE_LISTS_GLSL

#ifndef TILE_LISTS_SET
#define TILE_LISTS_SET 1
#define TILE_LISTS_BINDING 1
#define TILE_LISTS_ACCESS readonly
#endif

// Draw classes: the 32 optimised IDs, or all 128 raw IDs when the raw permutations are drawn.
const uint TILE_LIST_MAX_CLASSES = 128u;

layout(set = TILE_LISTS_SET, binding = TILE_LISTS_BINDING, std430) TILE_LISTS_ACCESS buffer TileLists {
    uint first[TILE_LIST_MAX_CLASSES]; // index of the class's first tile in tiles[]
    uint count[TILE_LIST_MAX_CLASSES]; // tiles in the class's list
    uint tiles[];                      // x | y << 16
} tile_lists;

uint tile_list_pack(uvec2 tile)
{
    return tile.x | (tile.y << 16u);
}

uvec2 tile_list_unpack(uint packed)
{
    return uvec2(packed & 0xFFFFu, packed >> 16u);
}

#endif // UBER_TILE_LISTS_GLSL
