#version 450
// local_light.frag -- one local light added into the light target (Tabula Rasa, §19.7): the
// deferred local-light uber-shader of permutations/local_lights.json. The runtime draws each
// light with its own permutation, over the whole frame (the full-screen reference) or over its
// volume mesh (local_light_volume.vert), blended ONE + ONE after the global pass. The shading is local_light.glsl's; this
// file reads the G-buffer as the global pass does (gbuffer.glsl, set 0 of lighting_params.glsl)
// and says which light, from what.
//
// Switches (one raw feature each):
//   LIGHT_TYPE   POINT, SPOT or BOX: the light's attenuation and direction.
//   GLOBE        the light's colour is filtered by its globe map (set 2).
//   BACK_COLOUR  surfaces facing away receive the back colour (box lights only: a rule).
//   SHADOWED     the light's shadow map (set 3; local_shadow.glsl) dims its direct term.
//   MSAA_EDGE    where a pixel's samples may differ, every sample is shaded and averaged
//                (sample_mean.glsl), as the global pass does; elsewhere sample 0 alone. The
//                runtime picks it for every light of a multisampled G-buffer.
// Sky pixels get exactly nothing: adding 0 leaves the light target as the global pass wrote it.

#extension GL_GOOGLE_include_directive : require

#define POINT 0
#define SPOT 1
#define BOX 2

#include "gbuffer.glsl"
#include "local_light.glsl"
#include "local_light_draw.glsl"
#include "sample_mean.glsl"
#include "world_position.glsl"

#ifndef LIGHT_TYPE
#error "LIGHT_TYPE must be POINT, SPOT or BOX"
#endif
#if defined(BACK_COLOUR) && LIGHT_TYPE != BOX
#error "BACK_COLOUR is a box light's: such a permutation is impossible"
#endif

#ifdef GLOBE
// The light's globe map: a scene texture, in the set layout of the material textures.
layout(set = 2, binding = 0) uniform sampler2D globe_map;
#endif

#ifdef SHADOWED
// Set 3: the shadow atlas and its faces; local_light_visibility().
#include "local_shadow_bindings.glsl"
#endif

// Whether the bound G-buffer has coverage flags (the classified path's): the runtime sets it as
// it does for the tile pass; the baselines' plain G-buffer is compared sample by sample instead.
layout(constant_id = 2) const bool TAGGED_GBUFFER = false;

layout(location = 0) out vec4 out_color;

LocalLightData this_light()
{
    LocalLightData light = local_lights.lights[draw.light_index];
    // The permutation knows the type: the compiler folds every branch on it.
    light.kind.x = uint(LIGHT_TYPE);
    return light;
}

vec3 shade_local_sample(LocalLightData light, ivec2 pixel, int sample_index)
{
    GSample g = gbuffer_load(pixel, sample_index);
    if (g.is_sky) {
        return vec3(0.0);
    }
    vec3 world_pos = world_position_from_depth(pixel, g.depth);
#ifdef GLOBE
    // Level 0, no derivatives: every pass that samples the map reads the same texels.
    vec3 tint = textureLod(globe_map, local_light_globe_uv(light, world_pos), 0.0).rgb;
#else
    vec3 tint = vec3(1.0);
#endif
#ifdef BACK_COLOUR
    const bool back_colour = true;
#else
    const bool back_colour = false;
#endif
#ifdef SHADOWED
    float visibility = local_light_visibility(light, pixel, world_pos, g.normal);
#else
    const float visibility = 1.0;
#endif
    return local_light_surface_radiance_visible(light, back_colour, tint, g.albedo, g.normal, world_pos,
                                                params.camera_pos.xyz, g.spec_amount, g.spec_power, visibility);
}

bool local_pixel_needs_other_samples(ivec2 pixel)
{
#ifndef GBUFFER_SINGLE_SAMPLED
    if (TAGGED_GBUFFER) {
        return gbuffer_flags_say_samples_may_differ(pixel);
    }
#endif
    return gbuffer_pixel_samples_differ(pixel);
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    LocalLightData light = this_light();
    vec3 colour = shade_local_sample(light, pixel, 0);
#ifdef MSAA_EDGE
    if (local_pixel_needs_other_samples(pixel)) {
        int samples = gbuffer_sample_count();
        for (int s = 1; s < samples; ++s) {
            colour = add_sample_to_mean(colour, shade_local_sample(light, pixel, s), s);
        }
    }
#endif
    // Alpha 0: the blend adds nothing to the global pass's alpha.
    out_color = vec4(colour, 0.0);
}
