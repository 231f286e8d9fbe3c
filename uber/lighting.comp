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
//
// The tile pass of an MSAA_EDGE class spreads the per-sample work over the workgroup instead
// (shade_tiles_spread()): every lane shades sample 0 of its pixel; the pixels whose coverage
// flags say their samples may differ (a few in a tile: the others are equal) go to a list in
// shared memory, and the workgroup's 64 lanes shade the other samples of those pixels together,
// one (pixel, sample) pair a lane, instead of one lane looping over all samples of its pixel
// while its neighbours idle. Each pixel's owner then averages its samples in sample order with
// add_sample_to_mean(), the arithmetic every pass uses, so the colour is the same bit for bit.
#extension GL_GOOGLE_include_directive : require

#include "light_pass.glsl"
#include "tile_lists.glsl"

layout(constant_id = 0) const uint TILE_SIZE = 4u;      // pixels: 4, 8 or 16
layout(constant_id = 1) const bool FULL_FRAME = false;  // naive / dynamic: no tile list
// (constant_id 2: TAGGED_GBUFFER, light_pass.glsl.) Samples per pixel of the G-buffer: sizes
// the shared list of samples to shade (the runtime specialises it to the targets' count).
layout(constant_id = 8) const uint LIGHT_GBUFFER_SAMPLES = 4u;
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

#if defined(MSAA_EDGE) && !defined(GBUFFER_SINGLE_SAMPLED)
const uint OTHER_SAMPLES = LIGHT_GBUFFER_SAMPLES - 1u; // 1 or more: this build reads 2+ samples
shared uint spread_pixel_count;
shared uint spread_pixels[LIGHT_GROUP_SIZE];                       // packed (x, y) of each listed pixel
shared vec3 spread_colours[LIGHT_GROUP_SIZE * OTHER_SAMPLES];      // per listed pixel: samples 1 ..

uint pack_pixel(ivec2 pixel) { return uint(pixel.x) | (uint(pixel.y) << 16); }
ivec2 unpack_pixel(uint packed) { return ivec2(packed & 0xFFFFu, packed >> 16); }

// One pixel per lane (`valid` false for lanes past the tile list or the frame): every lane
// reaches every barrier. Shared memory is reused by the next call, hence the closing barrier.
void shade_pixels_spread(ivec2 pixel, bool valid, uint lane)
{
    if (lane == 0u) {
        spread_pixel_count = 0u;
    }
    vec3 colour = vec3(0.0);
    bool listed = false;
    if (valid) {
        colour = shade_sample(pixel, 0);
        listed = pixel_needs_other_samples(pixel);
    }
    barrier();
    uint slot = 0u;
    if (listed) {
        slot = atomicAdd(spread_pixel_count, 1u);
        spread_pixels[slot] = pack_pixel(pixel);
    }
    barrier();
    uint work = spread_pixel_count * OTHER_SAMPLES;
    for (uint item = lane; item < work; item += LIGHT_GROUP_SIZE) {
        uint listed_pixel = item / OTHER_SAMPLES;
        int s = int(item % OTHER_SAMPLES) + 1;
        spread_colours[item] = shade_sample(unpack_pixel(spread_pixels[listed_pixel]), s);
    }
    barrier();
    if (valid) {
        int samples = gbuffer_sample_count();
        for (int s = 1; listed && s < samples; ++s) {
            colour = add_sample_to_mean(colour, spread_colours[slot * OTHER_SAMPLES + uint(s - 1)], s);
        }
        imageStore(light_target, pixel, vec4(colour, 1.0));
    }
    barrier();
}

// The tile pass of an MSAA_EDGE class: the same pixels as the loop in main(), in rounds of one
// pixel per lane.
void shade_tiles_spread(ivec2 frame, uint lane)
{
    const uint tile_pixels = TILE_SIZE * TILE_SIZE;
    const uint tiles_per_group = max(1u, LIGHT_GROUP_SIZE / tile_pixels);
    const uint pixels_per_lane = max(1u, tile_pixels / LIGHT_GROUP_SIZE);
    uint slot = gl_WorkGroupID.x * tiles_per_group + lane / min(tile_pixels, LIGHT_GROUP_SIZE);
    bool in_list = slot < tile_lists.count[push.draw_class];
    uvec2 tile = in_list ? tile_list_unpack(tile_lists.tiles[tile_lists.first[push.draw_class] + slot]) : uvec2(0u);
    ivec2 origin = ivec2(tile * TILE_SIZE);
    for (uint k = 0u; k < pixels_per_lane; ++k) {
        uint p = lane % min(tile_pixels, LIGHT_GROUP_SIZE) + k * LIGHT_GROUP_SIZE;
        ivec2 pixel = origin + ivec2(p % TILE_SIZE, p / TILE_SIZE);
        shade_pixels_spread(pixel, in_list && all(lessThan(pixel, frame)), lane);
    }
}
#endif

void main()
{
    ivec2 frame = imageSize(light_target);
    uint lane = gl_LocalInvocationID.x;
#if defined(MSAA_EDGE) && !defined(GBUFFER_SINGLE_SAMPLED)
    if (!FULL_FRAME && TAGGED_GBUFFER) {
        shade_tiles_spread(frame, lane);
        return;
    }
#endif
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
