// local_shadow.glsl -- a local light's shadow-map lookup (docs/local-lights.md, "Shadows"):
// jittered percentage-closer filtering over the light's face of the shadow atlas.
//
// Every shadowed light has 1 face (a spot's perspective map, a box's orthographic one) or 6 (a
// point light's cube, or a spot too wide for one map), each a square of texels in ONE depth atlas
// (a 2D image); a cube's face is chosen by hand from the direction to the light (the major axis),
// so no cube-map image is needed. The faces' transforms come from the CPU
// (local_shadow_transforms.cpp), snapped to their texel grid so a light that moves by less than a
// texel keeps the same matrix (no shimmer).
//
// The result is a pure function of the pixel, the surface point and its normal: the taps' disk is
// fixed and its rotation a hash of the pixel, and the map is read with texelFetch only (no
// filtering, no sampler state), so the volume and the full-screen passes, and the classified and
// naive light targets, compute the same bits for the same G-buffer sample.

#ifndef UBER_LOCAL_SHADOW_GLSL
#define UBER_LOCAL_SHADOW_GLSL

// One face of a light's shadow map; the runtime mirrors it (local_shadow_transforms.h, std430).
struct LocalShadowFace {
    mat4 view_proj;    // world -> the face's clip space (Vulkan: y down, depth 0..1)
    vec4 eye_offset;   // xyz the face's (snapped) eye; w the receiver's normal offset: metres per
                       // metre of distance to the eye (perspective), or metres (orthographic)
    uvec4 rect;        // xy the face's first texel in the atlas; z its size in texels; w 1 when
                       // perspective, 0 when orthographic
};

const uint LOCAL_SHADOW_TAP_COUNT = 8u;
// A fixed disk of taps (radius 1), rotated per pixel and scaled to LOCAL_SHADOW_RADIUS texels.
const vec2 LOCAL_SHADOW_DISK[8] = vec2[8](
    vec2( 0.18,  0.05), vec2(-0.42,  0.31), vec2( 0.55, -0.40), vec2(-0.12, -0.71),
    vec2( 0.80,  0.35), vec2(-0.86, -0.22), vec2( 0.24,  0.92), vec2(-0.47,  0.78));
const float LOCAL_SHADOW_RADIUS = 1.5;
// Receiver depth bias, in the face's depth units: what the caster's rasteriser bias and the
// normal offset leave of acne.
const float LOCAL_SHADOW_DEPTH_BIAS = 2e-5;
const float LOCAL_SHADOW_TAP_REACH = 4.0; // texels beyond the face that keep int() defined

// Which of a cube's 6 faces (+x, -x, +y, -y, +z, -z, the runtime's order) sees `offset`, the
// point relative to the eye: the major axis, ties to x then y.
uint local_shadow_cube_face(vec3 offset)
{
    vec3 a = abs(offset);
    if (a.x >= a.y && a.x >= a.z) {
        return offset.x >= 0.0 ? 0u : 1u;
    }
    if (a.y >= a.z) {
        return offset.y >= 0.0 ? 2u : 3u;
    }
    return offset.z >= 0.0 ? 4u : 5u;
}

// A deterministic angle per pixel, in [0, 2 pi): the same pixel always gets the same rotation.
float local_shadow_pixel_angle(ivec2 pixel)
{
    uint h = uint(pixel.x) * 1973u + uint(pixel.y) * 9277u + 26699u;
    h = (h ^ (h >> 13u)) * 0x5bd1e995u;
    h ^= h >> 15u;
    return float(h & 0xffffu) * (6.28318530718 / 65536.0);
}

// The fraction of the 8 taps that see no caster in front of the receiver: 1 lit, 0 shadowed.
// `normal`: the surface's, facing the light. A receiver outside the face's depth range or behind
// its eye counts as lit, as do taps outside the face.
float local_shadow_visibility(sampler2D atlas, LocalShadowFace face, ivec2 pixel, vec3 world_pos, vec3 normal)
{
    bool perspective = face.rect.w == 1u;
    float scale = perspective ? length(world_pos - face.eye_offset.xyz) : 1.0;
    precise vec3 receiver = world_pos + normal * (face.eye_offset.w * scale);
    precise vec4 clip = face.view_proj * vec4(receiver, 1.0);
    if (!(clip.w > 0.0)) {
        return 1.0;
    }
    precise vec3 ndc = clip.xyz / clip.w;
    if (!(ndc.z >= 0.0 && ndc.z <= 1.0)) {
        return 1.0;
    }
    float size = float(face.rect.z);
    vec2 centre = clamp((ndc.xy * 0.5 + 0.5) * size, vec2(-LOCAL_SHADOW_TAP_REACH), vec2(size + LOCAL_SHADOW_TAP_REACH));
    float angle = local_shadow_pixel_angle(pixel);
    vec2 rotation = vec2(cos(angle), sin(angle));
    precise float receiver_depth = ndc.z - LOCAL_SHADOW_DEPTH_BIAS;
    uint lit = 0u;
    for (int i = 0; i < int(LOCAL_SHADOW_TAP_COUNT); ++i) {
        vec2 o = LOCAL_SHADOW_DISK[i] * LOCAL_SHADOW_RADIUS;
        vec2 r = vec2(o.x * rotation.x - o.y * rotation.y, o.x * rotation.y + o.y * rotation.x);
        ivec2 texel = ivec2(floor(centre + r));
        bool inside = all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, ivec2(face.rect.z)));
        if (!inside || receiver_depth <= texelFetch(atlas, ivec2(face.rect.xy) + texel, 0).r) {
            lit += 1u;
        }
    }
    return float(lit) / float(LOCAL_SHADOW_TAP_COUNT);
}

#endif // UBER_LOCAL_SHADOW_GLSL
