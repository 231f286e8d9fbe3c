#version 450
// scene.vert -- instanced scene geometry for the G-buffer and the sun shadow map.
//
// One vertex buffer per mesh (position, normal, base colour uv) plus one per-instance buffer
// (model matrix and material). With SHADOW_PASS defined it is the depth-only shadow-map vertex shader.
#extension GL_GOOGLE_include_directive : require
#include "scene_params.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_model_col0;  // per instance: model matrix columns
layout(location = 3) in vec4 in_model_col1;
layout(location = 4) in vec4 in_model_col2;
layout(location = 5) in vec4 in_model_col3;
layout(location = 6) in vec4 in_albedo_spec; // per instance: rgb albedo, a specular amount
layout(location = 7) in vec4 in_material;    // x specular power, y motion ID, z checker scale, w flat faces
layout(location = 8) in vec2 in_uv;          // base colour texture coordinate

layout(location = 0) out vec3 out_world_pos;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out vec4 out_albedo_spec;
layout(location = 3) flat out vec4 out_material;
// The plane of this vertex's face, for meshes whose faces are flat (in_material.w): its world
// normal (w = 1; 0 on other meshes) and a world point on it. Both are computed only from the
// normal, dot(normal, position) and the instance, which every vertex of a flat face shares
// exactly, so every triangle of the face passes the same plane whichever vertex provokes it.
layout(location = 4) flat out vec4 out_face_normal;
layout(location = 5) flat out vec3 out_face_point;
layout(location = 6) out vec2 out_uv;

void main()
{
    mat4 model = mat4(in_model_col0, in_model_col1, in_model_col2, in_model_col3);
    vec4 world = model * vec4(in_position, 1.0);
    // Non-uniformly scaled boxes need the inverse transpose for their normals.
    mat3 normal_matrix = transpose(inverse(mat3(model)));
    out_world_pos = world.xyz;
    out_normal = normal_matrix * in_normal;
    out_albedo_spec = in_albedo_spec;
    out_material = in_material;
    out_face_normal = vec4(normal_matrix * in_normal, in_material.w);
    out_face_point = (model * vec4(in_normal * dot(in_normal, in_position), 1.0)).xyz;
    out_uv = in_uv;
    gl_Position = scene.view_proj * world;
}
