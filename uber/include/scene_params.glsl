// scene_params.glsl -- the descriptor interface of the scene passes (G-buffer, sky, shadow map).
//
// Set 0 of the scene pipelines; the runtime mirrors this block field for field (std140, see
// runtime/scene/include/tilelight/scene/uniform_blocks.h). Kept apart from lighting_params.glsl
// because the scene passes run before the lighting and bind none of its images.

#ifndef UBER_SCENE_PARAMS_GLSL
#define UBER_SCENE_PARAMS_GLSL

layout(set = 0, binding = 0, std140) uniform SceneParams {
    mat4 view_proj;       // world -> camera clip
    mat4 inv_view_proj;   // camera clip -> world (sky directions)
    mat4 sun_view_proj;   // world -> sun shadow clip (orthographic)
    vec4 camera_pos;      // xyz
    vec4 sun_direction;   // xyz normalised, TOWARDS the sun
    vec4 sky_zenith;      // rgb
    vec4 sky_horizon;     // rgb
    vec4 ambient_sky;     // rgb ambient from above (prelit lighting)
    vec4 ambient_ground;  // rgb ambient from below
    vec4 viewport;        // xy framebuffer size, zw 1/size
} scene;

#endif // UBER_SCENE_PARAMS_GLSL
