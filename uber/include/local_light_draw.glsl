// local_light_draw.glsl -- what every local-light draw binds besides the G-buffer: the frame's
// lights (set 1) and, per draw, which light and the camera's transform (push constants; the
// volume vertex shader places the light's mesh with it, the fragment shaders read the index).
// The runtime mirrors both (local_light_block.h, local_light_passes.cpp).

#ifndef UBER_LOCAL_LIGHT_DRAW_GLSL
#define UBER_LOCAL_LIGHT_DRAW_GLSL

#include "local_light.glsl"

layout(set = 1, binding = 0, std430) readonly buffer LocalLights {
    LocalLightData lights[];
} local_lights;

layout(push_constant) uniform LocalLightDraw {
    mat4 view_proj;    // world -> clip
    uint light_index;  // into local_lights.lights
} draw;

#endif // UBER_LOCAL_LIGHT_DRAW_GLSL
