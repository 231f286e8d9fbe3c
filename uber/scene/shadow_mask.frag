#version 450
// shadow_mask.frag -- the sun shadow map's fragment shader for alpha-masked meshes: it writes
// nothing, and discards where the G-buffer discards (alpha_mask.glsl), so a mask's holes let the
// sun through. Unmasked meshes keep the depth-only pipeline, which has no fragment shader.
#extension GL_GOOGLE_include_directive : require
#include "alpha_mask.glsl"

layout(location = 0) in vec2 in_uv;
layout(location = 1) flat in vec2 in_alpha_mask;

layout(set = 1, binding = 0) uniform sampler2D base_colour_texture;

void main()
{
    if (alpha_mask_discards(texture(base_colour_texture, in_uv).a, in_alpha_mask)) {
        discard;
    }
}
