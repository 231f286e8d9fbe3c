#version 450
// shadow.vert -- depth-only sun shadow map: the scene's instances seen from the sun. With
// ALPHA_MASK (the shadow_masked companion) it also passes shadow_mask.frag what the mask needs:
// the base colour texture coordinate and the instance's alpha factor and cutoff.
#extension GL_GOOGLE_include_directive : require
#include "scene_params.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 2) in vec4 in_model_col0;
layout(location = 3) in vec4 in_model_col1;
layout(location = 4) in vec4 in_model_col2;
layout(location = 5) in vec4 in_model_col3;
#ifdef ALPHA_MASK
layout(location = 8) in vec2 in_uv;
layout(location = 9) in vec2 in_alpha_mask; // per instance: x base colour factor alpha, y cutoff

layout(location = 0) out vec2 out_uv;
layout(location = 1) flat out vec2 out_alpha_mask;
#endif

void main()
{
    mat4 model = mat4(in_model_col0, in_model_col1, in_model_col2, in_model_col3);
    gl_Position = scene.sun_view_proj * (model * vec4(in_position, 1.0));
#ifdef ALPHA_MASK
    out_uv = in_uv;
    out_alpha_mask = in_alpha_mask;
#endif
}
