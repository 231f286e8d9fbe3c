// world_position.glsl -- world position and linear view depth from a depth sample.
//
// Every sample of a pixel is reconstructed at the pixel CENTRE, not at its own
// sample position: with equal stored values the samples then shade
// identically, which is what allows a non-edge pixel to shade sample 0 alone.
//
// Functions take the integer pixel and compute the centre themselves, so the
// fragment shader (pixel = ivec2(gl_FragCoord.xy), whose centre is exactly
// pixel + 0.5) and a compute classifier (pixel = invocation ID) run the very
// same arithmetic and agree on which side of a distance threshold a pixel is.
//
// `precise` throughout: these values decide classification bits (distance
// thresholds, shadow-map taps), so they must be rounded the same way in every
// shader that computes them (see precise_math.glsl).

#ifndef UBER_WORLD_POSITION_GLSL
#define UBER_WORLD_POSITION_GLSL

#include "lighting_params.glsl"
#include "precise_math.glsl"

// Vulkan clip space: NDC x and y run -1..1 with y pointing DOWN (framebuffer
// row 0 is NDC y = -1), so no flip; depth is z in 0..1.
vec2 pixel_centre_ndc(ivec2 pixel)
{
    precise vec2 ndc = (vec2(pixel) + 0.5) * params.viewport.zw * 2.0 - 1.0;
    return ndc;
}

vec3 world_position_from_depth(ivec2 pixel, float depth)
{
    precise vec4 world = params.inv_view_proj * vec4(pixel_centre_ndc(pixel), depth, 1.0);
    precise vec3 position = world.xyz / world.w;
    return position;
}

// Distance along the camera's forward axis: the "depth" that shadow fade and
// light scattering thresholds (and the depth classification bits) refer to.
float linear_view_depth(vec3 world_pos)
{
    precise vec3 offset = world_pos - params.camera_pos.xyz;
    return precise_dot(offset, params.camera_forward.xyz);
}

#endif // UBER_WORLD_POSITION_GLSL
