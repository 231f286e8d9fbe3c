#version 450
// gbuffer_upload.frag -- writes a G-buffer given sample by sample (the layout of
// gbuffer_dump.comp) instead of rendering the scene: tests build synthetic tiles with it to
// reach every tile class. Reading gl_SampleID runs this shader once per sample.
#extension GL_GOOGLE_include_directive : require
#define GBUFFER_ENCODE_ONLY
#include "gbuffer.glsl"

layout(set = 0, binding = 0, std430) readonly buffer Samples {
    vec4 texels[]; // per pixel, per sample: rt0, rt1, rt2, vec4(depth, 0, 0, 0)
} source;

layout(push_constant) uniform UploadPush {
    uvec4 size;         // width, height, samples
    vec4 sun_direction; // xyz: towards the sun, as the material shaders see it
} push;

layout(location = 0) out vec4 out_rt0;
layout(location = 1) out vec4 out_rt1;
layout(location = 2) out vec4 out_rt2;

uint sample_texel(uvec2 pixel, uint sample_index, uint target)
{
    return ((pixel.y * push.size.x + pixel.x) * push.size.z + sample_index) * 4u + target;
}

// The upload stands in for the material shaders, so it must keep their promises (gbuffer.glsl):
// a pixel whose samples differ carries the MSAA-edge bit on some sample -- a test's edits may make
// samples differ that the scene wrote alike; such a pixel gets the bit on every sample -- and a
// geometry sample's sun-facing bit is that of its stored normal, its depth below the sky's.
// Samples that keep the promises already are written exactly as given.
bool pixel_samples_differ(uvec2 pixel)
{
    for (uint s = 1u; s < push.size.z; ++s) {
        for (uint target = 0u; target < 4u; ++target) {
            if (any(notEqual(source.texels[sample_texel(pixel, 0u, target)],
                             source.texels[sample_texel(pixel, s, target)]))) {
                return true;
            }
        }
    }
    return false;
}

bool pixel_has_edge_bit(uvec2 pixel)
{
    for (uint s = 0u; s < push.size.z; ++s) {
        if (gbuffer_decode_msaa_edge_bit(source.texels[sample_texel(pixel, s, 3u)].x)) {
            return true;
        }
    }
    return false;
}

void main()
{
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uint at = sample_texel(pixel, uint(gl_SampleID), 0u);
    float depth = source.texels[at + 3u].x;
    vec4 rt1 = source.texels[at + 1u];
    if (depth != GBUFFER_SKY_DEPTH) {
        bool edge = gbuffer_decode_msaa_edge_bit(depth) || (!pixel_has_edge_bit(pixel) && pixel_samples_differ(pixel));
        rt1.xyz = gbuffer_stored_normal(rt1.xyz);
        depth = gbuffer_encode_depth(depth, edge, gbuffer_faces_sun(rt1.xyz, push.sun_direction.xyz), false);
    }
    out_rt0 = source.texels[at + 0u];
    out_rt1 = rt1;
    out_rt2 = source.texels[at + 2u];
    gl_FragDepth = depth;
}
