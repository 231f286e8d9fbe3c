#version 450
// gbuffer.frag -- the material shader: writes the Table 4.1 G-buffer through gbuffer.glsl,
// with prelit (ambient) lighting already applied, as in Split/Second. Compiled twice: plain (the
// baselines' G-buffer: RT0..RT3, what lighting reads) and with GBUFFER_COVERAGE_FLAGS (the
// classified path's: the same RT0..RT3 plus RT4, the coverage flags classification reads).
// With ALPHA_MASK (gbuffer_masked, gbuffer_masked_flagged: alpha-masked meshes) it discards the
// texels the mask cuts away (alpha_mask.glsl), identically in both.
#extension GL_GOOGLE_include_directive : require
#if defined(GBUFFER_COVERAGE_FLAGS) && !defined(ALPHA_MASK)
// The coverage flags need the samples this fragment won in the depth test (gbuffer.glsl). A
// masked fragment cannot test early: a discarded fragment must not write depth. Its flags are
// then worked out without post-depth coverage (gbuffer_encode_masked_flags()).
#extension GL_ARB_post_depth_coverage : require
layout(early_fragment_tests) in;
layout(post_depth_coverage) in;
#endif
#define GBUFFER_ENCODE_ONLY
#include "gbuffer.glsl"
#include "scene_params.glsl"
#ifdef ALPHA_MASK
#include "alpha_mask.glsl"
#endif

layout(location = 0) in vec3 in_world_pos;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec4 in_albedo_spec;
layout(location = 3) flat in vec4 in_material;
layout(location = 4) flat in vec4 in_face_normal; // w: 1 on a flat-faced mesh (scene.vert)
layout(location = 5) flat in vec3 in_face_depth;  // the face's depth plane over gl_FragCoord.xy
layout(location = 6) in vec2 in_uv;
#ifdef ALPHA_MASK
layout(location = 7) flat in vec2 in_alpha_mask; // x base colour factor alpha, y cutoff
#endif

// The mesh's base colour texture (sRGB, so read in linear light), or 1x1 white for meshes
// without one: the albedo is then multiplied by exactly 1.
layout(set = 1, binding = 0) uniform sampler2D base_colour_texture;

layout(location = 0) out vec4 out_rt0;
layout(location = 1) out vec4 out_rt1;
layout(location = 2) out vec4 out_rt2;
layout(location = 3) out float out_rt3;
#ifdef GBUFFER_COVERAGE_FLAGS
layout(location = 4) out uint out_flags;
#endif

// A world-space checkerboard so shadows and fog read clearly in the pictures.
float checker(vec3 p, float scale)
{
    if (scale <= 0.0) {
        return 1.0;
    }
    ivec3 cell = ivec3(floor(p / scale));
    return ((cell.x + cell.y + cell.z) & 1) == 0 ? 1.0 : 0.72;
}

// Relative: 64 units in the last place of a float depth.
const float FACE_PLANE_DEPTH_TOLERANCE = 64.0 / 8388608.0;

// The depth this fragment stores: on a flat face the face plane's depth at the pixel centre,
// from coefficients every triangle of the face receives alike (scene.vert), so two triangles
// sharing a pixel store the same value; elsewhere, and where the plane and the rasteriser part
// ways (a face seen edge-on, whose plane is ill-conditioned), the rasteriser's.
float surface_depth(bool flat_face)
{
    if (!flat_face) {
        return gl_FragCoord.z;
    }
    float plane = in_face_depth.x * gl_FragCoord.x + in_face_depth.y * gl_FragCoord.y + in_face_depth.z;
    return abs(plane - gl_FragCoord.z) <= FACE_PLANE_DEPTH_TOLERANCE * gl_FragCoord.z ? plane : gl_FragCoord.z;
}

void main()
{
    bool flat_face = in_face_normal.w > 0.5;
    // A flat face's normal is the face's own, which its triangles share exactly.
    vec3 normal = normalize(flat_face ? in_face_normal.xyz : in_normal);
    if (!gl_FrontFacing) {
        normal = -normal; // thin geometry seen from behind
    }
    vec4 texel = texture(base_colour_texture, in_uv);
#ifdef ALPHA_MASK
    if (alpha_mask_discards(texel.a, in_alpha_mask)) {
        discard;
    }
#endif
    vec3 albedo = in_albedo_spec.rgb * texel.rgb * checker(in_world_pos, in_material.z);
    float hemisphere = normal.y * 0.5 + 0.5;
    vec3 ambient = mix(scene.ambient_ground.rgb, scene.ambient_sky.rgb, hemisphere);
    uint motion_id = uint(in_material.y);

    // The sun-facing bit is decided on the normal exactly as RT1 stores it.
    vec3 stored_normal = gbuffer_stored_normal(normal);
    out_rt0 = gbuffer_encode_rt0(albedo, in_albedo_spec.a);
    out_rt1 = gbuffer_encode_rt1(stored_normal, motion_id);
    out_rt2 = gbuffer_encode_rt2(albedo * ambient, in_material.x);
    out_rt3 = gbuffer_encode_depth(surface_depth(flat_face),
                                   gbuffer_faces_sun(stored_normal, scene.sun_direction.xyz));
#if defined(GBUFFER_COVERAGE_FLAGS) && defined(ALPHA_MASK)
    out_flags = gbuffer_encode_masked_flags(gbuffer_fragment_is_partial(), flat_face);
#elif defined(GBUFFER_COVERAGE_FLAGS)
    out_flags = gbuffer_encode_flags(gbuffer_fragment_is_partial(), flat_face);
#endif
}
