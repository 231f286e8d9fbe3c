#version 450
// lighting.comp -- the deferred global-light pass as one uber-shader, compute form. The same
// permutations as lighting.frag (light_pass.glsl holds the shading both forms share); what
// differs is only which pixels an invocation shades and where the colour goes:
//
//   tile pass (FULL_FRAME false): one indirect dispatch per class, over that class's tile list
//     (TileLists below), recorded before classification ran and patched after it, by the host or
//     by the GPU (uber/classify/tile_lists.comp). A workgroup of 64 invocations shades
//     64 / (TILE_SIZE * TILE_SIZE) whole tiles of its class (4 at tile size 4, 1 at 8); at tile
//     size 16 one tile, 4 pixels per invocation.
//   naive and dynamic passes (FULL_FRAME true): one dispatch over the whole frame, 8x8 pixels a
//     workgroup.
//
// Each pixel is shaded exactly as the raster pass shades it (shade_pixel(): sample 0, and every
// sample averaged in where MSAA_EDGE says so) and stored to the single-sampled light target.
#extension GL_GOOGLE_include_directive : require

#include "light_pass.glsl"
#include "tile_lists.glsl"

layout(constant_id = 0) const uint TILE_SIZE = 4u;      // pixels: 4, 8 or 16
layout(constant_id = 1) const bool FULL_FRAME = false;  // naive / dynamic: no tile list
const uint LIGHT_GROUP_SIZE = 64u;
const uint FULL_FRAME_GROUP_SIDE = 8u;                  // 8 x 8 = LIGHT_GROUP_SIZE
layout(local_size_x = LIGHT_GROUP_SIZE) in;

layout(set = 1, binding = 0, rgba16f) uniform writeonly image2D light_target;

layout(push_constant) uniform LightPush {
    uint draw_class;  // whose tile list this dispatch shades (tile pass only)
} push;

void shade_and_store(ivec2 pixel, ivec2 frame)
{
    if (all(lessThan(pixel, frame))) {
        imageStore(light_target, pixel, vec4(shade_pixel(pixel), 1.0));
    }
}

void main()
{
    ivec2 frame = imageSize(light_target);
    uint lane = gl_LocalInvocationID.x;
    if (FULL_FRAME) {
        uvec2 in_group = uvec2(lane % FULL_FRAME_GROUP_SIDE, lane / FULL_FRAME_GROUP_SIDE);
        shade_and_store(ivec2(gl_WorkGroupID.xy * FULL_FRAME_GROUP_SIDE + in_group), frame);
        return;
    }
    const uint tile_pixels = TILE_SIZE * TILE_SIZE;
    const uint tiles_per_group = max(1u, LIGHT_GROUP_SIZE / tile_pixels);
    const uint pixels_per_lane = max(1u, tile_pixels / LIGHT_GROUP_SIZE);
    uint slot = gl_WorkGroupID.x * tiles_per_group + lane / min(tile_pixels, LIGHT_GROUP_SIZE);
    if (slot >= tile_lists.count[push.draw_class]) {
        return; // the class's last workgroup may be partly empty
    }
    uvec2 tile = tile_list_unpack(tile_lists.tiles[tile_lists.first[push.draw_class] + slot]);
    ivec2 origin = ivec2(tile * TILE_SIZE);
    for (uint k = 0u; k < pixels_per_lane; ++k) {
        uint p = lane % min(tile_pixels, LIGHT_GROUP_SIZE) + k * LIGHT_GROUP_SIZE;
        shade_and_store(origin + ivec2(p % TILE_SIZE, p / TILE_SIZE), frame);
    }
}
