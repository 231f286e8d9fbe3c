#version 450
// gbuffer_dump.comp -- copies every sample of the G-buffer into a buffer, as stored, so the CPU
// reference classifier and tests can read it (multisampled images cannot be copied to the host
// directly; the single-sampled build reads its one sample the same way). Layout per pixel: for
// each sample, rt0, rt1, rt2, then vec4(rt3 surface depth, coverage flags as float bits, 0, 0):
// 16 floats per sample, pixels row-major. The single-sampled G-buffer has no flags: 0 there.
#extension GL_GOOGLE_include_directive : require
#include "gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 1, binding = 0, std430) writeonly buffer Dump {
    vec4 texels[];
} dump;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(params.viewport.xy);
    if (pixel.x >= size.x || pixel.y >= size.y) {
        return;
    }
    int samples = gbuffer_samples();
    uint base = uint((pixel.y * size.x + pixel.x) * samples) * 4u;
    for (int s = 0; s < samples; ++s) {
        uint at = base + uint(s) * 4u;
        dump.texels[at + 0u] = gbuffer_fetch(gbuffer_albedo_spec, pixel, s);
        dump.texels[at + 1u] = gbuffer_fetch(gbuffer_normal_motion, pixel, s);
        dump.texels[at + 2u] = gbuffer_fetch(gbuffer_prelit_power, pixel, s);
#ifdef GBUFFER_SINGLE_SAMPLED
        uint flags = 0u;
#else
        uint flags = gbuffer_load_flags(pixel, s);
#endif
        dump.texels[at + 3u] = vec4(gbuffer_fetch(gbuffer_surface_depth, pixel, s).r, uintBitsToFloat(flags), 0.0, 0.0);
    }
}
