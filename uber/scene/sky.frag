#version 450
// sky.frag -- the sky: drawn after the geometry with depth test LESS_OR_EQUAL against the
// cleared depth of 1, so it fills exactly the pixels nothing else covered. Its final colour
// (gradient plus sun disc) goes to the prelit target; motion ID 0 marks it as sky.
#extension GL_GOOGLE_include_directive : require
#ifdef GBUFFER_COVERAGE_FLAGS
#extension GL_ARB_post_depth_coverage : require
layout(early_fragment_tests) in;
layout(post_depth_coverage) in;
#endif
#define GBUFFER_ENCODE_ONLY
#include "gbuffer.glsl"
#include "scene_params.glsl"

layout(location = 0) out vec4 out_rt0;
layout(location = 1) out vec4 out_rt1;
layout(location = 2) out vec4 out_rt2;
layout(location = 3) out float out_rt3;
#ifdef GBUFFER_COVERAGE_FLAGS
layout(location = 4) out uint out_flags;
#endif

void main()
{
    vec2 ndc = gl_FragCoord.xy * scene.viewport.zw * 2.0 - 1.0;
    vec4 far_point = scene.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec3 direction = normalize(far_point.xyz / far_point.w - scene.camera_pos.xyz);
    float height = clamp(direction.y, 0.0, 1.0);
    vec3 colour = mix(scene.sky_horizon.rgb, scene.sky_zenith.rgb, sqrt(height));
    float sun = max(dot(direction, scene.sun_direction.xyz), 0.0);
    colour += vec3(1.0, 0.9, 0.7) * (pow(sun, 512.0) * 4.0 + pow(sun, 16.0) * 0.15);

    out_rt0 = gbuffer_encode_rt0(vec3(0.0), 0.0);
    out_rt1 = gbuffer_encode_sky_rt1();
    out_rt2 = gbuffer_encode_rt2(colour, 0.0);
    out_rt3 = GBUFFER_SKY_DEPTH;
#ifdef GBUFFER_COVERAGE_FLAGS
    // Shared values: every sky fragment of a pixel stores the same values (they depend on the
    // pixel centre only). The driver may split the full-screen triangle, and flagging its parts
    // as partial would make sky tiles MSAA edges for nothing; where geometry covers the rest of
    // the pixel, the comparison finds the difference.
    out_flags = gbuffer_encode_flags(gbuffer_fragment_is_partial(), true);
#endif
}
