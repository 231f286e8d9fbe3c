// local_shadow_bindings.glsl -- set 3 of every pass that shades with the local lights' shadow
// maps (docs/local-lights.md, "Shadows"): the deferred local-light pass's SHADOWED permutations
// and the forward pass's LOCAL_SHADOWS ones, so both read a light's shadow the same way. Include
// after local_light.glsl (LocalLightData, local_light_incidence).

#ifndef UBER_LOCAL_SHADOW_BINDINGS_GLSL
#define UBER_LOCAL_SHADOW_BINDINGS_GLSL

#include "local_shadow.glsl"

// Every shadowed light's faces in one depth atlas, and each face's transform and place in it.
layout(set = 3, binding = 0) uniform sampler2D local_shadow_atlas;
layout(set = 3, binding = 1, std430) readonly buffer LocalShadowFaces {
    LocalShadowFace faces[];
} local_shadow_faces;

// The light's shadow over `world_pos`, only where its direct term lands: elsewhere 1 (it
// multiplies nothing or zero), and 1 for a light without a map (kind.w, its face count, is 0).
// A cube's face by the direction from its eye (kind.z: the light's first face).
float local_light_visibility(LocalLightData light, ivec2 pixel, vec3 world_pos, vec3 normal)
{
    if (light.kind.w == 0u) {
        return 1.0;
    }
    LocalLightIncidence incidence = local_light_incidence(light, world_pos);
    vec3 n = normalize(normal);
    if (!(incidence.attenuation > 0.0) || !(dot(n, incidence.to_light) > 0.0)) {
        return 1.0;
    }
    uint face = light.kind.z;
    if (light.kind.w == 6u) {
        face += local_shadow_cube_face(world_pos - local_shadow_faces.faces[face].eye_offset.xyz);
    }
    return local_shadow_visibility(local_shadow_atlas, local_shadow_faces.faces[face], pixel, world_pos, n);
}

#endif // UBER_LOCAL_SHADOW_BINDINGS_GLSL
