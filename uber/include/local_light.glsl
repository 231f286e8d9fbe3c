// local_light.glsl -- the shading of one local light (point, spot or box; the Tabula Rasa
// chapter, GPU Gems 3 ch. 19): attenuation, Lambert + Blinn-Phong, back colour, globe-map
// projection. Pure functions of their arguments: no descriptors, no G-buffer, no permutation
// defines. The deferred passes (uber/local_light.frag) feed it decoded G-buffer samples; a
// forward shader can feed it its interpolated surface. One effect, several techniques.
//
// Every attenuation reaches EXACTLY zero at the edge of its light's volume and stays zero beyond
// it, so a pass that shades only the pixels inside a volume mesh adds, bit for bit, what a
// full-screen pass adds (zero elsewhere):
//   range (point, spot): KHR_lights_punctual's recommended window over inverse-square,
//       clamp(1 - (d / range)^4, 0, 1)^2 / max(d^2, LOCAL_LIGHT_MIN_DISTANCE_SQUARED)
//   cone (spot):  smoothstep(outer_cos, inner_cos, cos(angle to the axis))
//   box:          per axis clamp((half_extent - |q|) / falloff, 0, 1), multiplied over x, y, z
//                 (q: the point in the box's frame); no distance falloff: a directional light
//                 confined to a box.
// The runtime mirrors LocalLightData field for field (local_light_block.h, std430).

#ifndef UBER_LOCAL_LIGHT_GLSL
#define UBER_LOCAL_LIGHT_GLSL

#include "precise_math.glsl"

const uint LOCAL_LIGHT_TYPE_POINT = 0u;
const uint LOCAL_LIGHT_TYPE_SPOT = 1u;
const uint LOCAL_LIGHT_TYPE_BOX = 2u;

// The mesh that encloses a light's nonzero region (the runtime picks it: a spot too wide for a
// cone gets the sphere).
const uint LOCAL_LIGHT_VOLUME_SPHERE = 0u;
const uint LOCAL_LIGHT_VOLUME_CONE = 1u;
const uint LOCAL_LIGHT_VOLUME_BOX = 2u;

// The inverse-square term's floor (1 cm squared): a surface at the light's origin stays finite.
const float LOCAL_LIGHT_MIN_DISTANCE_SQUARED = 1e-4;
// The specular lobe's guards, as the sun's (sun_lighting.glsl): half floats cap the power.
const float LOCAL_LIGHT_MAX_SPEC_POWER = 65504.0;
const float LOCAL_LIGHT_MIN_N_DOT_H = 1e-20;

struct LocalLightData {
    vec4 position_range;        // xyz position (box: centre); w range (point, spot)
    vec4 direction_inner;       // xyz spot axis / box light's travel (the frame's z); w inner cone cos
    vec4 radiance_outer;        // rgb colour * intensity; w outer cone cos
    vec4 back_radiance_falloff; // rgb back colour * intensity; w box falloff distance
    vec4 frame_x;               // xyz the frame's x axis (spot, box); w tan(outer cone angle)
    vec4 frame_y;               // xyz the frame's y axis; w unused
    vec4 box_half_extent;       // xyz half sizes along x, y, z; w unused
    uvec4 kind;                 // x LOCAL_LIGHT_TYPE_*; y LOCAL_LIGHT_VOLUME_*; z its first shadow face,
                                // w its shadow faces (0 unshadowed, 1, or 6: a cube)
};

// Where the light comes from at a surface point, and how much of it arrives.
struct LocalLightIncidence {
    vec3 to_light;      // normalised, towards the light
    float attenuation;  // 0 outside the light's volume, exactly
};

float local_light_range_window(float distance_to_light, float range)
{
    float ratio = distance_to_light / range;
    float ratio2 = ratio * ratio;
    float window = clamp(1.0 - ratio2 * ratio2, 0.0, 1.0);
    return window * window;
}

float local_light_distance_attenuation(float distance_to_light, float range)
{
    float d2 = distance_to_light * distance_to_light;
    return local_light_range_window(distance_to_light, range) / max(d2, LOCAL_LIGHT_MIN_DISTANCE_SQUARED);
}

// Precondition (local_light.h): inner_cos > outer_cos. 0 at and beyond the outer cone.
float local_light_cone_attenuation(float cos_angle, float inner_cos, float outer_cos)
{
    return smoothstep(outer_cos, inner_cos, cos_angle);
}

// One axis of a box light: 1 deep inside, 0 at and beyond the face.
float local_light_box_axis(float q, float half_extent, float falloff)
{
    return clamp((half_extent - abs(q)) / falloff, 0.0, 1.0);
}

// The point `world_pos` in the light's frame (spot, box), relative to its position.
vec3 local_light_frame_position(LocalLightData light, vec3 world_pos)
{
    precise vec3 offset = world_pos - light.position_range.xyz;
    return vec3(precise_dot(offset, light.frame_x.xyz), precise_dot(offset, light.frame_y.xyz),
                precise_dot(offset, light.direction_inner.xyz));
}

LocalLightIncidence local_light_incidence(LocalLightData light, vec3 world_pos)
{
    LocalLightIncidence incidence;
    if (light.kind.x == LOCAL_LIGHT_TYPE_BOX) {
        vec3 q = local_light_frame_position(light, world_pos);
        vec3 h = light.box_half_extent.xyz;
        float falloff = light.back_radiance_falloff.w;
        incidence.to_light = -light.direction_inner.xyz;
        incidence.attenuation = local_light_box_axis(q.x, h.x, falloff) * local_light_box_axis(q.y, h.y, falloff) *
                                local_light_box_axis(q.z, h.z, falloff);
        return incidence;
    }
    vec3 offset = light.position_range.xyz - world_pos;
    float distance_to_light = length(offset);
    incidence.to_light = distance_to_light > 0.0 ? offset / distance_to_light : vec3(0.0);
    incidence.attenuation = local_light_distance_attenuation(distance_to_light, light.position_range.w);
    if (light.kind.x == LOCAL_LIGHT_TYPE_SPOT) {
        float cos_angle = dot(-incidence.to_light, light.direction_inner.xyz);
        incidence.attenuation *=
            local_light_cone_attenuation(cos_angle, light.direction_inner.w, light.radiance_outer.w);
    }
    return incidence;
}

// Where a globe map (§19.4.2) is read for `world_pos`: spot, along the cone (its outer cone
// fills the map); box, across the box's x and y; point, an equirectangular map around it.
vec2 local_light_globe_uv(LocalLightData light, vec3 world_pos)
{
    if (light.kind.x == LOCAL_LIGHT_TYPE_POINT) {
        vec3 dir = normalize(world_pos - light.position_range.xyz);
        const float pi = 3.14159265358979;
        return vec2(atan(dir.z, dir.x) / (2.0 * pi) + 0.5, acos(clamp(dir.y, -1.0, 1.0)) / pi);
    }
    vec3 q = local_light_frame_position(light, world_pos);
    if (light.kind.x == LOCAL_LIGHT_TYPE_BOX) {
        return q.xy / light.box_half_extent.xy * 0.5 + 0.5;
    }
    return q.xy / max(q.z * light.frame_x.w, 1e-20) * 0.5 + 0.5;
}

// Lambert + Blinn-Phong (the sun's model, sun_lighting.glsl) with the lobe scaled by N.L, and
// with `back_colour` the back colour (§19.4.1) on surfaces facing away, diffuse only. `tint`
// multiplies the light's colour (the globe map's texel; vec3(1) without one); `visibility` (0..1,
// the shadow map's verdict, local_shadow.glsl) the direct term only: the back colour stands for
// light arriving from elsewhere, which the light's map does not see. Exactly vec3(0) where the
// attenuation is 0, and finite for any stored surface. A visibility of 1 gives the unshadowed
// result bit for bit (x * 1.0 == x).
vec3 local_light_surface_radiance_visible(LocalLightData light, bool back_colour, vec3 tint, vec3 albedo, vec3 normal,
                                          vec3 world_pos, vec3 camera_pos, float spec_amount, float spec_power,
                                          float visibility)
{
    LocalLightIncidence incidence = local_light_incidence(light, world_pos);
    if (!(incidence.attenuation > 0.0)) {
        return vec3(0.0);
    }
    vec3 n = normalize(normal);
    vec3 l = incidence.to_light;
    float n_dot_l = dot(n, l);
    if (n_dot_l > 0.0) {
        vec3 v = normalize(camera_pos - world_pos);
        vec3 h = normalize(l + v);
        float n_dot_h = dot(n, h);
        float power = spec_power > 0.0 ? min(spec_power, LOCAL_LIGHT_MAX_SPEC_POWER) : 0.0;
        float highlight = n_dot_h > 0.0 ? pow(clamp(n_dot_h, LOCAL_LIGHT_MIN_N_DOT_H, 1.0), power) : 0.0;
        vec3 radiance = light.radiance_outer.rgb * tint * (incidence.attenuation * visibility * n_dot_l);
        return radiance * (albedo + spec_amount * highlight);
    }
    if (back_colour && n_dot_l < 0.0) {
        return light.back_radiance_falloff.rgb * tint * albedo * (incidence.attenuation * -n_dot_l);
    }
    return vec3(0.0);
}

// The same, unshadowed.
vec3 local_light_surface_radiance(LocalLightData light, bool back_colour, vec3 tint, vec3 albedo, vec3 normal,
                                  vec3 world_pos, vec3 camera_pos, float spec_amount, float spec_power)
{
    return local_light_surface_radiance_visible(light, back_colour, tint, albedo, normal, world_pos, camera_pos,
                                                spec_amount, spec_power, 1.0);
}

// A vertex of the light's volume in world space, from a vertex of its unit mesh (the runtime's
// local_light_volumes.cpp, each already enlarged to enclose its shape with a margin): the sphere
// (radius 1) scaled by the range; the cone (apex at the origin, axis +z, height 1, radius 1 at
// z = 1) by the range along the axis and range * tan(outer) across it; the box (-1..1) by its
// half extents; the last two in the light's frame.
vec3 local_light_volume_position(LocalLightData light, vec3 unit)
{
    vec3 x = light.frame_x.xyz, y = light.frame_y.xyz, z = light.direction_inner.xyz;
    float range = light.position_range.w;
    if (light.kind.y == LOCAL_LIGHT_VOLUME_BOX) {
        vec3 q = unit * light.box_half_extent.xyz;
        return light.position_range.xyz + q.x * x + q.y * y + q.z * z;
    }
    if (light.kind.y == LOCAL_LIGHT_VOLUME_CONE) {
        float radius = range * light.frame_x.w;
        return light.position_range.xyz + (unit.x * radius) * x + (unit.y * radius) * y + (unit.z * range) * z;
    }
    return light.position_range.xyz + unit * range;
}

#endif // UBER_LOCAL_LIGHT_GLSL
