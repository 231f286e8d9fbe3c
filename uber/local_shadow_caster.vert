#version 450
// local_shadow_caster.vert -- one face of a local light's shadow map (docs/local-lights.md,
// "Shadows"): the scene's instances seen from the light through the face's transform, pushed per
// face. Depth only; with ALPHA_MASK (the shadow_caster_masked companion) it also passes the sun's
// shadow_mask.frag what the mask needs, so a mask's holes let the local light through as they let
// the sun through. The scene's vertex and instance buffers, as the sun's shadow.vert reads them.

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

layout(push_constant) uniform LocalShadowCasterDraw {
    mat4 face_view_proj; // world -> the face's clip space
} caster;

void main()
{
    mat4 model = mat4(in_model_col0, in_model_col1, in_model_col2, in_model_col3);
    gl_Position = caster.face_view_proj * (model * vec4(in_position, 1.0));
#ifdef ALPHA_MASK
    out_uv = in_uv;
    out_alpha_mask = in_alpha_mask;
#endif
}
