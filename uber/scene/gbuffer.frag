#version 450
// gbuffer.frag -- the material shader: writes the Table 4.1 G-buffer through gbuffer.glsl,
// with prelit (ambient) lighting already applied, as in Split/Second.
#extension GL_GOOGLE_include_directive : require
#define GBUFFER_ENCODE_ONLY
#include "gbuffer.glsl"
#include "scene_params.glsl"

layout(location = 0) in vec3 in_world_pos;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec4 in_albedo_spec;
layout(location = 3) flat in vec4 in_material;

layout(location = 0) out vec4 out_rt0;
layout(location = 1) out vec4 out_rt1;
layout(location = 2) out vec4 out_rt2;

// A world-space checkerboard so shadows and fog read clearly in the pictures.
float checker(vec3 p, float scale)
{
    if (scale <= 0.0) {
        return 1.0;
    }
    ivec3 cell = ivec3(floor(p / scale));
    return ((cell.x + cell.y + cell.z) & 1) == 0 ? 1.0 : 0.72;
}

void main()
{
    vec3 normal = normalize(in_normal);
    if (!gl_FrontFacing) {
        normal = -normal; // thin geometry seen from behind
    }
    vec3 albedo = in_albedo_spec.rgb * checker(in_world_pos, in_material.z);
    float hemisphere = normal.y * 0.5 + 0.5;
    vec3 ambient = mix(scene.ambient_ground.rgb, scene.ambient_sky.rgb, hemisphere);
    uint motion_id = uint(in_material.y);

    // The sun-facing bit is decided on the normal exactly as RT1 stores it.
    vec3 stored_normal = gbuffer_stored_normal(normal);
    out_rt0 = gbuffer_encode_rt0(albedo, in_albedo_spec.a);
    out_rt1 = gbuffer_encode_rt1(stored_normal, motion_id);
    out_rt2 = gbuffer_encode_rt2(albedo * ambient, in_material.x);
    // One depth per pixel: every covered sample stores the pixel-centre depth, so a pixel
    // inside one surface has bit-identical samples; its two lowest bits are the MSAA-edge and
    // sun-facing bits (see gbuffer.glsl).
    gl_FragDepth = gbuffer_encode_depth(gl_FragCoord.z, gbuffer_fragment_is_partial(),
                                        gbuffer_faces_sun(stored_normal, scene.sun_direction.xyz));
}
