#version 450
// gbuffer_upload.frag -- writes a G-buffer given sample by sample (the layout of
// gbuffer_dump.comp) instead of rendering the scene: tests build synthetic tiles with it to
// reach every tile class. Reading gl_SampleID runs this shader once per sample.
#extension GL_GOOGLE_include_directive : require
#define GBUFFER_ENCODE_ONLY
#include "gbuffer.glsl"

layout(set = 0, binding = 0, std430) readonly buffer Samples {
    vec4 texels[]; // per pixel, per sample: rt0, rt1, rt2, vec4(rt3, flag bits, 0, 0)
} source;

layout(push_constant) uniform UploadPush {
    uvec4 size;         // width, height, samples
    vec4 sun_direction; // xyz: towards the sun, as the material shaders see it
} push;

layout(location = 0) out vec4 out_rt0;
layout(location = 1) out vec4 out_rt1;
layout(location = 2) out vec4 out_rt2;
layout(location = 3) out float out_rt3;
#ifndef GBUFFER_SINGLE_SAMPLED
layout(location = 4) out uint out_flags;
#endif

uint sample_texel(uvec2 pixel, uint sample_index, uint target)
{
    return ((pixel.y * push.size.x + pixel.x) * push.size.z + sample_index) * 4u + target;
}

// The upload stands in for the material shaders, so it must keep their promises (gbuffer.glsl):
// a pixel without flags has equal samples -- a test's edits may make samples differ that the
// scene wrote alike; such a pixel gets the shared flag on every sample, so that readers compare
// its values -- and a geometry sample's sun-facing bit is that of its stored normal, its depth
// below the sky's. Samples that keep the promises already are written exactly as given.
bool pixel_samples_differ(uvec2 pixel)
{
    for (uint s = 1u; s < push.size.z; ++s) {
        for (uint target = 0u; target < 4u; ++target) {
            vec4 first = source.texels[sample_texel(pixel, 0u, target)];
            vec4 other = source.texels[sample_texel(pixel, s, target)];
            if (target == 3u ? floatBitsToUint(first.x) != floatBitsToUint(other.x)
                             : any(notEqual(floatBitsToUint(first), floatBitsToUint(other)))) {
                return true;
            }
        }
    }
    return false;
}

uint given_flags(uvec2 pixel, uint sample_index)
{
    return floatBitsToUint(source.texels[sample_texel(pixel, sample_index, 3u)].y);
}

// True when some given sample already carries a flag.
bool flags_mark_pixel(uvec2 pixel)
{
    uint flags = 0u;
    for (uint s = 0u; s < push.size.z; ++s) {
        flags |= given_flags(pixel, s);
    }
    return flags != 0u;
}

void main()
{
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uint at = sample_texel(pixel, uint(gl_SampleID), 0u);
    float depth = source.texels[at + 3u].x;
    vec4 rt1 = source.texels[at + 1u];
    if (depth != GBUFFER_SKY_DEPTH) {
        rt1.xyz = gbuffer_stored_normal(rt1.xyz);
        depth = gbuffer_encode_depth(depth, gbuffer_faces_sun(rt1.xyz, push.sun_direction.xyz));
    }
    out_rt0 = source.texels[at + 0u];
    out_rt1 = rt1;
    out_rt2 = source.texels[at + 2u];
    out_rt3 = depth;
#ifndef GBUFFER_SINGLE_SAMPLED
    uint flags = given_flags(pixel, uint(gl_SampleID));
    out_flags = !flags_mark_pixel(pixel) && pixel_samples_differ(pixel) ? GBUFFER_FLAG_SHARED : flags;
#endif
}
