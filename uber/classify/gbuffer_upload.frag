#version 450
// gbuffer_upload.frag -- writes a G-buffer given sample by sample (the layout of
// gbuffer_dump.comp) instead of rendering the scene: tests build synthetic tiles with it to
// reach every tile class. Reading gl_SampleID runs this shader once per sample.
#extension GL_GOOGLE_include_directive : require

layout(set = 0, binding = 0, std430) readonly buffer Samples {
    vec4 texels[]; // per pixel, per sample: rt0, rt1, rt2, vec4(depth, 0, 0, 0)
} source;

layout(push_constant) uniform UploadPush {
    uvec4 size; // width, height, samples
} push;

layout(location = 0) out vec4 out_rt0;
layout(location = 1) out vec4 out_rt1;
layout(location = 2) out vec4 out_rt2;

void main()
{
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uint at = ((pixel.y * push.size.x + pixel.x) * push.size.z + uint(gl_SampleID)) * 4u;
    out_rt0 = source.texels[at + 0u];
    out_rt1 = source.texels[at + 1u];
    out_rt2 = source.texels[at + 2u];
    gl_FragDepth = source.texels[at + 3u].x;
}
