#version 450
// local_light_resolve.frag -- the single-sampled depth and stencil the light volumes are tested
// against, from the multisampled G-buffer, once before a light target's volumes (drawn over the
// whole frame by local_light_full_screen.vert):
// - depth: the NEAREST of the pixel's samples' surface depths (RT3, what the lighting shades,
//   at the pixel centre), so the volumes' "greater or equal" test passes wherever any sample
//   may lie inside a volume: conservative, the light's attenuation does the rest exactly;
// - stencil: kept (REPLACE, by the pipeline) only where some sample's G-buffer stencil was
//   marked by a material (§19.7.2); where none was (sky) the fragment is discarded and the
//   cleared 0 stays, which the volumes reject.

#extension GL_GOOGLE_include_directive : require

#include "gbuffer.glsl"

#ifdef GBUFFER_SINGLE_SAMPLED
layout(set = 0, binding = 7) uniform usampler2D gbuffer_stencil;
#else
layout(set = 0, binding = 7) uniform usampler2DMS gbuffer_stencil;
#endif

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint marked = 0u;
    float nearest = GBUFFER_SKY_DEPTH;
    for (int s = 0; s < gbuffer_sample_count(); ++s) {
        marked |= gbuffer_fetch(gbuffer_stencil, pixel, s).r;
        nearest = min(nearest, gbuffer_load_depth(pixel, s).depth);
    }
    if (marked == 0u) {
        discard;
    }
    gl_FragDepth = nearest;
}
