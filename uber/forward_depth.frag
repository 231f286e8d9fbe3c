#version 450
// forward_depth.frag -- the single-sampled depth the forward pass tests blended geometry against,
// from the G-buffer, once at the start of each light target's forward pass (drawn over the whole
// frame by forward_full_screen.vert): the NEAREST of the pixel's samples' surface depths (RT3,
// what the lighting shades), as the local lights' resolve takes it. Glass is hidden wherever any
// sample's opaque surface lies in front of it, so an edge pixel of an opaque object in front of
// glass shows the object's lit average, not glass blended over it. Sky keeps depth 1.0: glass
// in front of the sky passes the LESS test.

#extension GL_GOOGLE_include_directive : require

#include "gbuffer.glsl"

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float nearest = GBUFFER_SKY_DEPTH;
    for (int s = 0; s < gbuffer_sample_count(); ++s) {
        nearest = min(nearest, gbuffer_load_depth(pixel, s).depth);
    }
    gl_FragDepth = nearest;
}
