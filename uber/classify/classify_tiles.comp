#version 450
// classify_tiles.comp -- screen-space tile classification (Split/Second, Sections 4.4-4.6).
//
// One invocation classifies one row of a block of 4x4 tiles (Fig. 4.3), tile by tile, and
// writes the row's four IDs as one uint32. Every decision calls the same include functions as
// lighting.frag (sun_faces, sun_shadow_lookup, shadow_fade_active, shadow_fade_complete,
// light_scattering_active), so a tile's ID admits what its pixels need. IDs are bytes
// in the blocked layout: block b holds 16 bytes, one uint32 per block row (byte i = tile i of
// the row); tiles beyond the frame's partial edge blocks get 0xFF.
//
// The cost is kept far below the lighting's (the point of the technique):
// - no shared memory, atomics or barriers: on a CPU driver (lavapipe) their bookkeeping alone
//   costs a third of the full lighting pass; the SIMD lanes are simply rows classified side
//   by side;
// - MSAA edges come from the per-sample edge bit the materials write (gbuffer.glsl): one fetch
//   of one target per sample instead of comparing every target;
// - the shadow type of a tile comes from bounds instead of 8 taps per sample. The pass over the
//   tile's pixels collects the rectangle of shadow-map texels that any tap of any sun-facing
//   sample can touch and the range of the samples' receiver depths; then the stored depths
//   over that rectangle are read, and
//     every stored depth >= every receiver depth  -> every tap lit: LIT (exactly);
//     every stored depth <  every receiver depth, rectangle inside the map -> SHADOWED (exactly);
//     otherwise (a shadow boundary, or a rectangle too large to read) -> SOFT.
//   SOFT is full PCF, which is right for every sample, so a tile wrongly called SOFT costs
//   lighting time, never correctness. Counting each sample's taps to settle those tiles
//   exactly was measured and cost more classification time than it saved lighting time.
#extension GL_GOOGLE_include_directive : require
#include "gbuffer.glsl"
#include "light_scattering.glsl"
#include "shadow_fade.glsl"
#include "sun_lighting.glsl"
#include "sun_shadow.glsl"
#include "tile_classes.glsl"
#include "world_position.glsl"

layout(constant_id = 0) const uint TILE_SIZE = 4u; // pixels; 4, 8 or 16
layout(local_size_x = 64) in;

layout(set = 1, binding = 0, std430) writeonly buffer TileIds {
    uint block_rows[]; // 4 per block
} tile_ids;

layout(push_constant) uniform ClassifyPush {
    uvec4 grid; // tiles_x, tiles_y, blocks_x, blocks_y
} push;

// A tile whose tap rectangle holds more texels than this is SOFT without reading it. Measured
// on the default 720p frame (docs/results.md): larger rectangles settle few more tiles.
const int MAX_BOUNDED_TEXELS = 128;

const int INT_MAX = 0x7FFFFFFF;
const int INT_MIN = -INT_MAX - 1;

// An unsigned key with the order of the float (for every non-NaN value; -0 is keyed as +0,
// because the float comparison finds them equal).
uint order_key(float value)
{
    uint bits = floatBitsToUint(value);
    if (bits == 0x80000000u) {
        bits = 0u;
    }
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

// What one invocation learns about the sun-facing samples of its pixels.
struct ShadowBounds {
    bool  any;            // some sun-facing sample inside the sun's volume
    ivec2 rect_min;       // tap rectangle, in texels
    ivec2 rect_max;
    uint  receiver_min;   // order keys of the biased receiver depths
    uint  receiver_max;
};

ShadowBounds no_shadow_bounds()
{
    return ShadowBounds(false, ivec2(INT_MAX), ivec2(INT_MIN), 0xFFFFFFFFu, 0u);
}

void add_to_bounds(inout ShadowBounds bounds, SunShadowLookup lookup)
{
    bounds.any = true;
    bounds.rect_min = min(bounds.rect_min, lookup.base + SUN_SHADOW_TAP_MIN_OFFSET);
    bounds.rect_max = max(bounds.rect_max, lookup.base + SUN_SHADOW_TAP_MAX_OFFSET);
    uint key = order_key(lookup.receiver_depth);
    bounds.receiver_min = min(bounds.receiver_min, key);
    bounds.receiver_max = max(bounds.receiver_max, key);
}

// Flags of one sample, except the shadow type: a sun-facing sample inside the sun's volume is
// added to `bounds` instead; one outside it has every tap lit; one whose shadow is faded out
// completely has no say in the shadow type.
uint classify_sample(ivec2 pixel, int sample_index, inout ShadowBounds bounds)
{
    GSample g = gbuffer_load(pixel, sample_index);
    if (g.is_sky) {
        return TILE_FLAG_SKY; // sky takes no lighting: no depth or shadow bits
    }
    vec3 world_pos = world_position_from_depth(pixel, g.depth);
    float view_depth = linear_view_depth(world_pos);
    uint flags = 0u;
    if (shadow_fade_active(view_depth)) flags |= TILE_FLAG_FADE;
    if (light_scattering_active(view_depth)) flags |= TILE_FLAG_SCATTERING;
    if (sun_faces(g.normal)) {
        flags |= TILE_FLAG_SUN;
        if (shadow_fade_complete(view_depth)) {
            return flags; // lit alike whatever the tile's shadow type
        }
        SunShadowLookup lookup = sun_shadow_lookup(world_pos);
        if (lookup.in_volume) {
            add_to_bounds(bounds, lookup);
        } else {
            flags |= TILE_FLAG_LIT;
        }
    }
    return flags;
}

bool pixel_is_edge(ivec2 pixel, int samples)
{
    bool edge = false;
    for (int s = 0; s < samples; ++s) {
        edge = edge || gbuffer_load_msaa_edge_bit(pixel, s);
    }
    return edge;
}

// An edge pixel classifies all its samples; any other pixel sample 0 alone, which speaks for its
// equal siblings exactly as the lighting shades only sample 0 of such a pixel.
uint classify_pixel(ivec2 pixel, int samples, inout ShadowBounds bounds)
{
    bool edge = pixel_is_edge(pixel, samples);
    uint flags = edge ? TILE_FLAG_EDGE : 0u;
    int classified = edge ? samples : 1;
    for (int s = 0; s < classified; ++s) {
        flags |= classify_sample(pixel, s, bounds);
    }
    return flags;
}

// The part of the tap rectangle inside the map; empty when lo > hi.
void clipped_rect(ShadowBounds bounds, out ivec2 lo, out ivec2 hi)
{
    lo = max(bounds.rect_min, ivec2(0));
    hi = min(bounds.rect_max, ivec2(params.shadow_map_size.xy) - 1);
}

// LIT or SHADOWED when the stored depths under the tap rectangle settle the shadow type of every
// sample in `bounds`; else PARTIAL, which makes the tile SOFT: full PCF, right for any sample.
uint shadow_type_from_bounds(ShadowBounds bounds)
{
    ivec2 lo, hi;
    clipped_rect(bounds, lo, hi);
    if (any(greaterThan(lo, hi))) {
        return TILE_FLAG_LIT; // every tap outside the map, where nothing was rendered
    }
    ivec2 extent = hi - lo + 1;
    if (extent.x * extent.y > MAX_BOUNDED_TEXELS) {
        return TILE_FLAG_PARTIAL;
    }
    uint stored_min = 0xFFFFFFFFu;
    uint stored_max = 0u;
    for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
            uint key = order_key(sun_shadow_stored_depth(ivec2(x, y)));
            stored_min = min(stored_min, key);
            stored_max = max(stored_max, key);
        }
    }
    // Taps outside the map are lit, so they never stop LIT; SHADOWED needs every tap inside.
    if (bounds.receiver_max <= stored_min) {
        return TILE_FLAG_LIT;
    }
    bool inside_map = all(equal(lo, bounds.rect_min)) && all(equal(hi, bounds.rect_max));
    if (inside_map && bounds.receiver_min > stored_max) {
        return TILE_FLAG_SHADOWED;
    }
    return TILE_FLAG_PARTIAL;
}

// The raw ID of `tile`, which lies inside the grid.
uint classify_tile(uvec2 tile, ivec2 size, int samples)
{
    ivec2 first_pixel = ivec2(tile * TILE_SIZE);
    ivec2 end_pixel = min(first_pixel + int(TILE_SIZE), size);
    uint flags = 0u;
    ShadowBounds bounds = no_shadow_bounds();
    for (int y = first_pixel.y; y < end_pixel.y; ++y) {
        for (int x = first_pixel.x; x < end_pixel.x; ++x) {
            flags |= classify_pixel(ivec2(x, y), samples, bounds);
        }
    }
    if (bounds.any) {
        flags |= shadow_type_from_bounds(bounds);
    }
    return raw_id_from_tile_flags(flags);
}

void main()
{
    uint block = gl_GlobalInvocationID.x / 4u;
    if (block >= push.grid.z * push.grid.w) {
        return;
    }
    uint row = gl_GlobalInvocationID.x % 4u;
    uvec2 first_tile = uvec2(block % push.grid.z, block / push.grid.z) * 4u + uvec2(0u, row);
    ivec2 size = ivec2(params.viewport.xy);
    int samples = gbuffer_sample_count();
    uint packed_row = 0u;
    for (uint i = 0u; i < 4u; ++i) {
        uvec2 tile = first_tile + uvec2(i, 0u);
        uint id = all(lessThan(tile, push.grid.xy)) ? classify_tile(tile, size, samples) : 0xFFu;
        packed_row |= id << (8u * i);
    }
    tile_ids.block_rows[block * 4u + row] = packed_row;
}
