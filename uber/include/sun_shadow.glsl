// sun_shadow.glsl -- sun shadow map lookup: 8-tap percentage-closer filtering.
//
// Everything goes through ONE lookup (sun_shadow_lookup: where the receiver
// lands, its biased depth) and ONE set of taps:
//   sun_shadow_lit_taps(p)  0..8 unoccluded taps (the CPU reference classifier
//                           counts them too);
//   sun_shadow_pcf(p)       lit / 8.0, the shadow factor lighting.frag uses.
// The classifier does not count taps: every tap lies in
// [base + SUN_SHADOW_TAP_MIN_OFFSET, base + SUN_SHADOW_TAP_MAX_OFFSET], so the
// stored depths over one rectangle bound every tap of a tile: all lit (0 taps
// occluded) or all occluded (classify_tiles.comp).
// Because the factor counts taps, "0 taps lit" is exactly factor 0.0 and
// "8 taps lit" exactly 1.0 (n * 0.125 is exact in float), so the SOLID_SHADOW
// permutation (factor 0) and the no-shadow permutation (factor 1) reproduce
// the full PCF shader bit for bit on the tiles they are used for.
//
// The map is read with texelFetch only (the classifier also with textureGather,
// which returns the same stored texels four at a time): no filtering, no
// sampler state, no hardware compare, and therefore nothing that could differ
// between the fragment and the compute stage.

#ifndef UBER_SUN_SHADOW_GLSL
#define UBER_SUN_SHADOW_GLSL

#include "lighting_params.glsl"

const uint SUN_SHADOW_TAP_COUNT = 8u;

// Integer texel offsets from the texel just below-left of the lookup point
// (the point lies in the square between base and base + (1, 1)). The 2x2 core
// around the point plus a pinwheel of four outer taps gives a roughly round
// footprint centred on the point (the offsets sum to (4, 4) = 8 * (0.5, 0.5)).
const ivec2 SUN_SHADOW_TAP_OFFSETS[8] = ivec2[8](
    ivec2( 0,  0), ivec2( 1,  0), ivec2( 0,  1), ivec2( 1,  1),
    ivec2(-1,  1), ivec2( 2,  0), ivec2( 0, -1), ivec2( 1,  2));

// The taps reach at most this far outside the map (offset -1 and +2 around
// floor(point - 0.5)); used to keep the float -> int conversion defined.
const float SUN_SHADOW_TAP_REACH = 4.0;

// The smallest and largest of SUN_SHADOW_TAP_OFFSETS per axis: every tap of a
// lookup lies in [base + MIN, base + MAX], which is what lets the classifier
// bound a whole tile's taps by one texel rectangle.
const ivec2 SUN_SHADOW_TAP_MIN_OFFSET = ivec2(-1, -1);
const ivec2 SUN_SHADOW_TAP_MAX_OFFSET = ivec2(2, 2);

// Where a receiver lands in the map, before any tap is read.
struct SunShadowLookup {
    bool  in_volume;      // false: outside the sun's depth range, every tap counts as lit
    ivec2 base;           // the texel just below-left of the lookup point
    float receiver_depth; // biased; a tap is lit when receiver_depth <= the stored depth
};

SunShadowLookup sun_shadow_lookup(vec3 world_pos)
{
    // `precise` on the projection: each tap's lit/occluded verdict is a
    // threshold, so the classifier and every permutation must round it alike
    // (see precise_math.glsl).
    precise vec4 clip = params.sun_view_proj * vec4(world_pos, 1.0);
    precise vec3 ndc = clip.xyz / clip.w; // w == 1 for the orthographic sun; kept general

    SunShadowLookup lookup;
    // A receiver in front of the near or beyond the far plane of the sun's
    // volume cannot be compared against the map: it counts as lit (all taps).
    // Written so that NaN also lands here.
    lookup.in_volume = ndc.z >= 0.0 && ndc.z <= 1.0;

    // NDC -> continuous texel coordinates (texel centres at i + 0.5). The sun
    // is rendered with the same Vulkan convention as the camera (NDC y = -1 is
    // row 0), so no flip.
    vec2 map_size = params.shadow_map_size.xy;
    precise vec2 texel_pos = (ndc.xy * 0.5 + 0.5) * map_size;

    // Far outside the map every tap is outside, and it still is after this
    // clamp, so the clamp changes no result; it only keeps int() defined for
    // points projected arbitrarily far away.
    texel_pos = clamp(texel_pos, vec2(-SUN_SHADOW_TAP_REACH), map_size + SUN_SHADOW_TAP_REACH);
    lookup.base = ivec2(floor(texel_pos - 0.5));

    precise float receiver_depth = ndc.z - params.distances.w; // bias against self-shadowing acne
    lookup.receiver_depth = receiver_depth;
    return lookup;
}

bool sun_shadow_texel_in_map(ivec2 texel)
{
    return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, ivec2(params.shadow_map_size.xy)));
}

// The nearest occluder's depth stored at `texel`. Precondition: sun_shadow_texel_in_map(texel).
float sun_shadow_stored_depth(ivec2 texel)
{
    return texelFetch(shadow_map, texel, 0).r;
}

uint sun_shadow_lit_taps(SunShadowLookup lookup)
{
    if (!lookup.in_volume) {
        return SUN_SHADOW_TAP_COUNT;
    }
    uint lit = 0u;
    for (int i = 0; i < int(SUN_SHADOW_TAP_COUNT); ++i) {
        ivec2 texel = lookup.base + SUN_SHADOW_TAP_OFFSETS[i];
        // Outside the map nothing was rendered: lit. Inside, the map stores the
        // nearest occluder's depth; the tap is lit unless that occluder is in
        // front of the (biased) receiver.
        if (!sun_shadow_texel_in_map(texel) || lookup.receiver_depth <= sun_shadow_stored_depth(texel)) {
            lit += 1u;
        }
    }
    return lit;
}

uint sun_shadow_lit_taps(vec3 world_pos)
{
    return sun_shadow_lit_taps(sun_shadow_lookup(world_pos));
}

float sun_shadow_pcf(vec3 world_pos)
{
    return float(sun_shadow_lit_taps(world_pos)) / float(SUN_SHADOW_TAP_COUNT);
}

#endif // UBER_SUN_SHADOW_GLSL
