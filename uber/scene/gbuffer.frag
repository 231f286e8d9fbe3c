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
layout(location = 4) flat in vec4 in_face_normal; // w: 1 on a flat-faced mesh (scene.vert)
layout(location = 5) flat in vec3 in_face_point;
layout(location = 6) in vec2 in_uv;

// The mesh's base colour texture (sRGB, so read in linear light), or 1x1 white for meshes
// without one: the albedo is then multiplied by exactly 1.
layout(set = 1, binding = 0) uniform sampler2D base_colour_texture;

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

// The surface point of this pixel's centre, its normal and its depth, where two triangles of one
// flat face both cover part of the pixel: computed from the face's plane and the view ray
// through the pixel centre -- inputs both triangles share exactly -- instead of each triangle's
// own interpolation, which differs in the last bits. Both fragments then store the same
// values, the pixel's samples are equal and classification does not see an MSAA edge in a
// face's inner diagonal (gbuffer.glsl, "MSAA-edge bit").
struct Surface {
    vec3 world_pos;
    vec3 normal;
    float depth;
};

// Relative: 64 units in the last place of a float depth.
const float FACE_PLANE_DEPTH_TOLERANCE = 64.0 / 8388608.0;

Surface face_plane_surface()
{
    vec2 ndc = gl_FragCoord.xy * scene.viewport.zw * 2.0 - 1.0;
    vec4 far_point = scene.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec3 origin = scene.camera_pos.xyz;
    vec3 ray = far_point.xyz / far_point.w - origin;
    vec3 n = in_face_normal.xyz;
    float t = dot(n, in_face_point - origin) / dot(n, ray);
    vec3 world_pos = origin + t * ray;
    vec4 clip = scene.view_proj * vec4(world_pos, 1.0);
    return Surface(world_pos, normalize(n), clip.z / clip.w);
}

void main()
{
    bool partial = gbuffer_fragment_is_partial();
    bool on_face_plane = false;
    Surface surface = Surface(in_world_pos, normalize(in_normal), gl_FragCoord.z);
    if (partial && in_face_normal.w > 0.5) {
        // The plane's depth at the pixel centre is the rasteriser's, up to rounding; where the
        // two part ways (a face seen edge-on, whose ray meets its plane ill-conditioned) keep
        // the rasteriser's values: the pixel then stays an edge, which is always safe.
        Surface on_plane = face_plane_surface();
        if (abs(on_plane.depth - gl_FragCoord.z) <= FACE_PLANE_DEPTH_TOLERANCE * gl_FragCoord.z) {
            surface = on_plane;
            on_face_plane = true;
        }
    }
    vec3 normal = surface.normal;
    if (!gl_FrontFacing) {
        normal = -normal; // thin geometry seen from behind
    }
    vec3 albedo = in_albedo_spec.rgb * texture(base_colour_texture, in_uv).rgb * checker(surface.world_pos, in_material.z);
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
    // A partial fragment marks its samples: with the face bit where it stored its face's
    // canonical values (the pixel is an edge only if the samples then differ), else with the
    // MSAA-edge bit (an edge).
    gl_FragDepth = gbuffer_encode_depth(surface.depth, partial && !on_face_plane,
                                        gbuffer_faces_sun(stored_normal, scene.sun_direction.xyz), on_face_plane);
}
