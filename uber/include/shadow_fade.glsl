// shadow_fade.glsl -- fade the sun shadow out towards the end of its range.
//
// Beyond distances.x (view depth) the shadow blends linearly to "no shadow"
// over 1 / distances.y world units, so geometry leaving the shadow map's range
// does not pop.
//
// Exactness contract: at view depths <= fade start the factor is exactly 0 and
// shadow_fade_apply() returns its input unchanged, so a tile whose pixels all
// lie before the fade start (SHADOW_FADE bit clear) may skip the fade. The
// guard is the same comparison as shadow_fade_active(), which the classifier
// uses, and it also avoids 0 * Inf when the fade length is 0.

#ifndef UBER_SHADOW_FADE_GLSL
#define UBER_SHADOW_FADE_GLSL

#include "lighting_params.glsl"

bool shadow_fade_active(float view_depth)
{
    return view_depth > params.distances.x;
}

float shadow_fade_factor(float view_depth)
{
    if (!shadow_fade_active(view_depth)) {
        return 0.0;
    }
    return clamp((view_depth - params.distances.x) * params.distances.y, 0.0, 1.0);
}

// mix(shadow, 1.0, fade), spelt out. This form is exact at every point the
// permutations rely on, with or without fused multiply-add: fade 0 gives
// shadow, shadow 1 gives 1, shadow 0 gives fade. `precise` stops the driver
// from re-deriving it as a*(1-t) + b*t, which is not exact at those points.
// True when the shadow is faded out completely: shadow_fade_apply() then returns exactly 1.0
// for every PCF factor k/8 (1 - k/8 and k/8 + (1 - k/8) are exact), so no shadow type can change
// the sample's colour and the classifier leaves it out when it picks one.
bool shadow_fade_complete(float view_depth)
{
    return shadow_fade_factor(view_depth) >= 1.0;
}

float shadow_fade_apply(float shadow, float view_depth)
{
    precise float faded = shadow + (1.0 - shadow) * shadow_fade_factor(view_depth);
    return faded;
}

#endif // UBER_SHADOW_FADE_GLSL
