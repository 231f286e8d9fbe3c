#version 450
// scene.vert -- instanced scene geometry for the G-buffer and the sun shadow map.
//
// One vertex buffer per mesh (position, normal, base colour uv) plus one per-instance buffer
// (model matrix and material). With ALPHA_MASK (the scene_masked companion, for alpha-masked
// meshes) it also passes the instance's alpha factor and cutoff to gbuffer.frag; unmasked meshes
// keep the shader without them, so their pipelines read no attribute they do not use.
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
#ifdef ALPHA_MASK
layout(location = 9) in vec2 in_alpha_mask;  // per instance: x base colour factor alpha, y cutoff
#endif

layout(location = 0) out vec3 out_world_pos;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out vec4 out_albedo_spec;
layout(location = 3) flat out vec4 out_material;
// The plane of this vertex's face, for meshes whose faces are flat (in_material.w): its world
// normal (w = 1; 0 on other meshes) and its depth as an affine function of the pixel position
// (gbuffer.frag). Both are computed only from the normal, dot(normal, position) and the
// instance, which every vertex of a flat face shares exactly, so every triangle of the face
// passes the same plane whichever vertex provokes it.
layout(location = 4) flat out vec4 out_face_normal;
layout(location = 5) flat out vec3 out_face_depth;
layout(location = 6) out vec2 out_uv;
#ifdef ALPHA_MASK
layout(location = 7) flat out vec2 out_alpha_mask;
#endif

// The depth plane z = a x + b y + c over framebuffer coordinates (gl_FragCoord.xy) of the world
// plane dot(n, p) = dot(n, point). In homogeneous clip space the plane is L * inv_view_proj
// (a row vector); dividing by w gives one linear equation in (x_ndc, y_ndc, z), solved for z.
vec3 face_depth_plane(vec3 n, vec3 point)
{
    vec4 clip_plane = vec4(n, -dot(n, point)) * scene.inv_view_proj;
    vec2 ndc_per_pixel = 2.0 * scene.viewport.zw;
    return vec3(-clip_plane.x * ndc_per_pixel.x, -clip_plane.y * ndc_per_pixel.y,
                -(clip_plane.w - clip_plane.x - clip_plane.y)) / clip_plane.z;
}

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
    vec3 face_point = (model * vec4(in_normal * dot(in_normal, in_position), 1.0)).xyz;
    out_face_depth = in_material.w > 0.5 ? face_depth_plane(out_face_normal.xyz, face_point) : vec3(0.0);
    out_uv = in_uv;
#ifdef ALPHA_MASK
    out_alpha_mask = in_alpha_mask;
#endif

    gl_Position = scene.view_proj * world;
}
