#version 450
// classify_tiles.comp -- screen-space tile classification (Split/Second, Sections 4.4-4.6).
//
// One work group classifies one block of 4x4 tiles; each invocation covers TILE_SIZE/4 x
// TILE_SIZE/4 pixels of one tile. Every decision calls the same include functions as
// lighting.frag (sun_faces, sun_shadow_lit_taps, shadow_fade_active, light_scattering_active,
// gbuffer_samples_equal), so a tile's ID admits exactly what its pixels need. IDs are written
// as bytes in the blocked layout of Fig. 4.3: block b holds 16 bytes, one uint32 per block row
// (byte i = tile i of the row); tiles beyond the frame's partial edge blocks get 0xFF.
#extension GL_GOOGLE_include_directive : require
#include "gbuffer.glsl"
#include "light_scattering.glsl"
#include "shadow_fade.glsl"
#include "sun_lighting.glsl"
#include "sun_shadow.glsl"
#include "tile_classes.glsl"
#include "world_position.glsl"

layout(constant_id = 0) const uint TILE_SIZE = 4u; // pixels; 4, 8 or 16
layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 1, binding = 0, std430) writeonly buffer TileIds {
    uint block_rows[]; // 4 per block
} tile_ids;

layout(push_constant) uniform ClassifyPush {
    uvec4 grid; // tiles_x, tiles_y, blocks_x, blocks_y
} push;

shared uint tile_flags[16];

uint classify_sample(ivec2 pixel, int sample_index)
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
        uint lit = sun_shadow_lit_taps(world_pos);
        flags |= lit == 0u ? TILE_FLAG_SHADOWED
               : lit == SUN_SHADOW_TAP_COUNT ? TILE_FLAG_LIT : TILE_FLAG_PARTIAL;
    }
    return flags;
}

uint classify_pixel(ivec2 pixel)
{
    int samples = gbuffer_sample_count();
    bool edge = gbuffer_load_msaa_edge_bit(pixel, 0);
    for (int s = 1; s < samples && !edge; ++s) {
        edge = !gbuffer_samples_equal(pixel, 0, s);
    }
    // Equal samples classify alike: sample 0 speaks for a non-edge pixel, exactly as the
    // lighting shades only sample 0 of it.
    uint flags = edge ? TILE_FLAG_EDGE : 0u;
    int classified = edge ? samples : 1;
    for (int s = 0; s < classified; ++s) {
        flags |= classify_sample(pixel, s);
    }
    return flags;
}

void main()
{
    uint local_index = gl_LocalInvocationIndex;
    if (local_index < 16u) {
        tile_flags[local_index] = 0u;
    }
    barrier();

    const uint span = TILE_SIZE / 4u; // pixels per invocation along each axis
    uvec2 block_origin = gl_WorkGroupID.xy * (4u * TILE_SIZE);
    uvec2 first_pixel = block_origin + gl_LocalInvocationID.xy * span;
    ivec2 size = ivec2(params.viewport.xy);
    uint flags = 0u;
    for (uint y = 0u; y < span; ++y) {
        for (uint x = 0u; x < span; ++x) {
            ivec2 pixel = ivec2(first_pixel + uvec2(x, y));
            if (pixel.x < size.x && pixel.y < size.y) {
                flags |= classify_pixel(pixel);
            }
        }
    }
    uint tile_in_block = (gl_LocalInvocationID.y / 4u) * 4u + gl_LocalInvocationID.x / 4u;
    if (flags != 0u) {
        atomicOr(tile_flags[tile_in_block], flags);
    }
    barrier();

    if (local_index < 4u) {
        uint row = local_index;
        uvec2 first_tile = gl_WorkGroupID.xy * 4u + uvec2(0u, row);
        uint packed_row = 0u;
        for (uint i = 0u; i < 4u; ++i) {
            uint id = 0xFFu;
            if (first_tile.x + i < push.grid.x && first_tile.y < push.grid.y) {
                id = raw_id_from_tile_flags(tile_flags[row * 4u + i]);
            }
            packed_row |= id << (8u * i);
        }
        uint block = gl_WorkGroupID.y * push.grid.z + gl_WorkGroupID.x;
        tile_ids.block_rows[block * 4u + row] = packed_row;
    }
}
