#version 450
// forward.vert -- alpha-blended (glTF BLEND) geometry for the forward pass (docs/local-lights.md,
// "Forward pass for blended materials"). The same vertex and instance inputs as scene.vert (the
// runtime binds the same MeshVertex and Instance layouts), minus what only the G-buffer needs
// (motion ID, face planes, alpha cutoff).

#extension GL_GOOGLE_include_directive : require

#include "forward_params.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_model_col0;  // per instance: model matrix columns
layout(location = 3) in vec4 in_model_col1;
layout(location = 4) in vec4 in_model_col2;
layout(location = 5) in vec4 in_model_col3;
layout(location = 6) in vec4 in_albedo_spec; // per instance: rgb albedo, a specular amount
layout(location = 7) in vec4 in_material;    // x specular power, z checker scale
layout(location = 8) in vec2 in_uv;          // base colour texture coordinate
layout(location = 9) in vec2 in_alpha;       // per instance: x base colour factor alpha

layout(location = 0) out vec3 out_world_pos;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out vec4 out_albedo_spec;
layout(location = 3) flat out vec4 out_material;
layout(location = 4) out vec2 out_uv;
layout(location = 5) flat out float out_alpha;

void main()
{
    mat4 model = mat4(in_model_col0, in_model_col1, in_model_col2, in_model_col3);
    vec4 world = model * vec4(in_position, 1.0);
    out_world_pos = world.xyz;
    out_normal = transpose(inverse(mat3(model))) * in_normal;
    out_albedo_spec = in_albedo_spec;
    out_material = in_material;
    out_uv = in_uv;
    out_alpha = in_alpha.x;
    gl_Position = forward.view_proj * world;
}
