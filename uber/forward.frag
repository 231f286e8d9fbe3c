#version 450
// forward.frag -- alpha-blended (glTF BLEND) surfaces, lit in a forward pass after the deferred
// ones (Tabula Rasa §19.3, §19.8.1; docs/local-lights.md, "Forward pass for blended materials").
// The uber-shader of permutations/forward.json: the chapter's "one effect, multiple techniques",
// the deferred passes' shading library fed an interpolated surface instead of a G-buffer sample:
//   - prelit: albedo times the hemisphere ambient, as gbuffer.frag stores it;
//   - the sun: sun_lighting.glsl's term times sun_shadow.glsl's 8-tap PCF after
//     shadow_fade.glsl's fade, as the global pass's full shader (light_pass.glsl) computes it;
//   - LOCAL_LIGHTS: local_light.glsl's term for each of the K lights the runtime chose for
//     this instance (push constants), the box lights with their back colour; no globe maps;
//   - then light_scattering.glsl's fog.
// Output: the lit colour with alpha = base colour alpha (factor times texture), blended
// SRC_ALPHA, ONE_MINUS_SRC_ALPHA over the light target by the pipeline.
//
// Switches (raw features):
//   LOCAL_LIGHTS   the instance has local lights to add (without it, none are read).
//   LOCAL_SHADOWS  some of them have shadow maps (only with LOCAL_LIGHTS: a rule).

#extension GL_GOOGLE_include_directive : require

#include "forward_params.glsl"
#include "light_scattering.glsl"
#include "local_light.glsl"
#include "shadow_fade.glsl"
#include "sun_lighting.glsl"
#include "sun_shadow.glsl"
#include "world_position.glsl"

#ifdef LOCAL_LIGHTS
layout(set = 1, binding = 0, std430) readonly buffer ForwardLocalLights {
    LocalLightData lights[];
} local_lights;
#endif
#ifdef LOCAL_SHADOWS
#include "local_shadow_bindings.glsl"
#endif

// The mesh's base colour texture (sRGB, read in linear light), or 1x1 white without one.
layout(set = 2, binding = 0) uniform sampler2D base_colour_texture;

layout(location = 0) in vec3 in_world_pos;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec4 in_albedo_spec;
layout(location = 3) flat in vec4 in_material;
layout(location = 4) in vec2 in_uv;
layout(location = 5) flat in float in_alpha;

layout(location = 0) out vec4 out_color;

vec3 forward_sun(vec3 albedo, vec3 normal, float view_depth)
{
    bool faces_sun = sun_n_dot_l(normal) > 0.0;
    vec3 sun = sun_surface_radiance(albedo, faces_sun, normal, in_world_pos, in_albedo_spec.a, in_material.x);
    float shadow = shadow_fade_apply(sun_shadow_pcf(in_world_pos), view_depth);
    return sun * shadow;
}

#ifdef LOCAL_LIGHTS
vec3 forward_local_lights(vec3 albedo, vec3 normal)
{
    vec3 sum = vec3(0.0);
    uint count = min(draw.light_count.x, FORWARD_MAX_LIGHTS);
    for (uint i = 0u; i < count; ++i) {
        LocalLightData light = local_lights.lights[draw.light_indices[i / 4u][i % 4u]];
        bool back_colour = light.kind.x == LOCAL_LIGHT_TYPE_BOX;  // 0 where the box has none
#ifdef LOCAL_SHADOWS
        float visibility = local_light_visibility(light, ivec2(gl_FragCoord.xy), in_world_pos, normal);
#else
        const float visibility = 1.0;
#endif
        sum += local_light_surface_radiance_visible(light, back_colour, vec3(1.0), albedo, normal, in_world_pos,
                                                    params.camera_pos.xyz, in_albedo_spec.a, in_material.x, visibility);
    }
    return sum;
}
#endif

void main()
{
    // A surface seen from behind is lit as its front (glTF's double-sided rule, as gbuffer.frag).
    vec3 normal = normalize(in_normal);
    if (!gl_FrontFacing) {
        normal = -normal;
    }
    vec4 texel = texture(base_colour_texture, in_uv);
    vec3 albedo = in_albedo_spec.rgb * texel.rgb;
    float view_depth = linear_view_depth(in_world_pos);
    vec3 ambient = mix(forward.ambient_ground.rgb, forward.ambient_sky.rgb, normal.y * 0.5 + 0.5);
    vec3 colour = albedo * ambient + forward_sun(albedo, normal, view_depth);
#ifdef LOCAL_LIGHTS
    colour += forward_local_lights(albedo, normal);
#endif
    colour = light_scattering_apply(colour, view_depth);
    out_color = vec4(colour, clamp(in_alpha * texel.a, 0.0, 1.0));
}
