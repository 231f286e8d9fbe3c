// sun_shadow.glsl -- sun shadow map lookup: 8-tap percentage-closer filtering.
//
// Two entry points over ONE set of taps:
//   sun_shadow_lit_taps(p)  0..8 unoccluded taps; the classifier calls it and
//                           marks a tile solid (all non-sky pixels 0), lit
//                           (all 8) or soft (anything else);
//   sun_shadow_pcf(p)       lit / 8.0, the shadow factor lighting.frag uses.
// Because both count the same taps, "0 taps lit" is exactly factor 0.0 and
// "8 taps lit" exactly 1.0 (n * 0.125 is exact in float), so the SOLID_SHADOW
// permutation (factor 0) and the no-shadow permutation (factor 1) reproduce
// the full PCF shader bit for bit on the tiles they are used for.
//
// The map is read with texelFetch only: no filtering, no sampler state, no
// hardware compare, and therefore nothing that could differ between the
// fragment and the compute stage.

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

uint sun_shadow_lit_taps(vec3 world_pos)
{
    // `precise` on the projection: each tap's lit/occluded verdict is a
    // threshold, so the classifier and every permutation must round it alike
    // (see precise_math.glsl).
    precise vec4 clip = params.sun_view_proj * vec4(world_pos, 1.0);
    precise vec3 ndc = clip.xyz / clip.w; // w == 1 for the orthographic sun; kept general

    // A receiver in front of the near or beyond the far plane of the sun's
    // volume cannot be compared against the map: it counts as lit (all taps).
    // Written so that NaN also lands here.
    if (!(ndc.z >= 0.0 && ndc.z <= 1.0)) {
        return SUN_SHADOW_TAP_COUNT;
    }

    // NDC -> continuous texel coordinates (texel centres at i + 0.5). The sun
    // is rendered with the same Vulkan convention as the camera (NDC y = -1 is
    // row 0), so no flip.
    vec2 map_size = params.shadow_map_size.xy;
    precise vec2 texel_pos = (ndc.xy * 0.5 + 0.5) * map_size;

    // Far outside the map every tap is outside, and it still is after this
    // clamp, so the clamp changes no result; it only keeps int() defined for
    // points projected arbitrarily far away.
    texel_pos = clamp(texel_pos, vec2(-SUN_SHADOW_TAP_REACH), map_size + SUN_SHADOW_TAP_REACH);
    ivec2 base = ivec2(floor(texel_pos - 0.5));
    ivec2 texel_count = ivec2(map_size);

    precise float receiver_depth = ndc.z - params.distances.w; // bias against self-shadowing acne

    uint lit = 0u;
    for (int i = 0; i < int(SUN_SHADOW_TAP_COUNT); ++i) {
        ivec2 texel = base + SUN_SHADOW_TAP_OFFSETS[i];
        // Outside the map nothing was rendered: lit.
        if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, texel_count))) {
            lit += 1u;
            continue;
        }
        // The map stores the nearest occluder's depth; the tap is lit unless
        // that occluder is in front of the (biased) receiver.
        float occluder_depth = texelFetch(shadow_map, texel, 0).r;
        if (receiver_depth <= occluder_depth) {
            lit += 1u;
        }
    }
    return lit;
}

float sun_shadow_pcf(vec3 world_pos)
{
    return float(sun_shadow_lit_taps(world_pos)) / float(SUN_SHADOW_TAP_COUNT);
}

#endif // UBER_SUN_SHADOW_GLSL
