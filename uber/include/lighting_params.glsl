// lighting_params.glsl -- the descriptor interface of the global light pass.
//
// Descriptor set 0 is shared by every permutation of lighting.frag and by the
// classification compute shaders, so the runtime can build ONE pipeline layout
// for all of them. The runtime mirrors this block field for field (std140), so
// any change here is an interface change: update runtime/ at the same time.
//
// A permutation that does not need a binding (e.g. no shadow map without a
// sun term) has it removed by the optimiser; the binding numbers never move.

#ifndef UBER_LIGHTING_PARAMS_GLSL
#define UBER_LIGHTING_PARAMS_GLSL

layout(set = 0, binding = 0, std140) uniform LightingParams {
    mat4 inv_view_proj;   // clip -> world
    mat4 sun_view_proj;   // world -> sun shadow clip (orthographic; xy -1..1, z 0..1)
    vec4 camera_pos;      // xyz world position
    vec4 camera_forward;  // xyz normalised view direction
    vec4 sun_direction;   // xyz normalised direction TOWARDS the sun
    vec4 sun_color;       // rgb radiance
    vec4 fog_color;       // rgb in-scatter colour, a = scattering density per world unit
    vec4 distances;       // x shadow fade start, y 1/fade length, z scattering start, w shadow depth bias
    vec4 shadow_map_size; // xy texel count, zw 1/texel count
    vec4 viewport;        // xy framebuffer size in pixels, zw 1/size
} params;

// The G-buffer is multisampled, or single-sampled when the domain is built with
// GBUFFER_SINGLE_SAMPLED defined (tilelight --msaa 1): a single-sampled image may not be bound
// to a sampler2DMS, so that build declares sampler2D and reads mip level 0. Every reader goes
// through gbuffer_fetch() and gbuffer_samples(), which hide the difference.
#ifdef GBUFFER_SINGLE_SAMPLED
layout(set = 0, binding = 1) uniform sampler2D gbuffer_albedo_spec;   // RT0
layout(set = 0, binding = 2) uniform sampler2D gbuffer_normal_motion; // RT1
layout(set = 0, binding = 3) uniform sampler2D gbuffer_prelit_power;  // RT2
layout(set = 0, binding = 4) uniform sampler2D gbuffer_surface_depth; // RT3
// The one sample of `pixel`; `sample_index` is 0 by the caller's loop bounds.
#define gbuffer_fetch(target, pixel, sample_index) texelFetch(target, pixel, 0)
#define gbuffer_samples() 1
#else
layout(set = 0, binding = 1) uniform sampler2DMS gbuffer_albedo_spec;   // RT0
layout(set = 0, binding = 2) uniform sampler2DMS gbuffer_normal_motion; // RT1
layout(set = 0, binding = 3) uniform sampler2DMS gbuffer_prelit_power;  // RT2
layout(set = 0, binding = 4) uniform sampler2DMS gbuffer_surface_depth; // RT3
// RT4, the coverage flags: the classified G-buffer's, read by classification and the tile pass
// (a single-sampled G-buffer has none: no pixel of it can differ between samples).
layout(set = 0, binding = 6) uniform usampler2DMS gbuffer_coverage_flags;
#define gbuffer_fetch(target, pixel, sample_index) texelFetch(target, pixel, sample_index)
#define gbuffer_samples() textureSamples(gbuffer_normal_motion)
#endif
layout(set = 0, binding = 5) uniform sampler2D shadow_map;   // texelFetch / textureGather, no filtering

#endif // UBER_LIGHTING_PARAMS_GLSL
