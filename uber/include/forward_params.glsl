// forward_params.glsl -- what the forward pass (uber/forward.vert, uber/forward.frag) binds
// besides lighting_params.glsl's set 0 bindings (the lighting parameters and the sun's shadow
// map): its own block at set 0 binding 8, the scene's local lights (set 1), the mesh's base
// colour texture (set 2, the scene textures' set layout) and, per draw, the K local lights
// chosen for the instance (push constants). The runtime mirrors all of it
// (runtime/render/src/forward_pass.cpp).

#ifndef UBER_FORWARD_PARAMS_GLSL
#define UBER_FORWARD_PARAMS_GLSL

// The most local lights one blended instance is lit by (§19.3.3: the K most important).
const uint FORWARD_MAX_LIGHTS = 8u;

layout(set = 0, binding = 8, std140) uniform ForwardParams {
    mat4 view_proj;       // world -> camera clip, as the G-buffer pass's
    vec4 ambient_sky;     // rgb: the prelit hemisphere light, as gbuffer.frag's
    vec4 ambient_ground;  // rgb
} forward;

layout(push_constant) uniform ForwardDraw {
    uvec4 light_count;                        // x: 0..FORWARD_MAX_LIGHTS
    uvec4 light_indices[FORWARD_MAX_LIGHTS / 4u]; // into local_lights.lights, most important first
} draw;

#endif // UBER_FORWARD_PARAMS_GLSL
