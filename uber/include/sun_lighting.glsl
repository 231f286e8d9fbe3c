// sun_lighting.glsl -- direct sunlight: Lambert diffuse + Blinn-Phong specular.
//
// Exactness contract: where N.L <= 0 the sun term (diffuse AND specular) is
// exactly vec3(0), by an early return rather than a smooth falloff. A tile
// whose non-sky pixels all face away from the sun (SUN_LIGHT bit clear) then
// gets exactly prelit from the full shader too, so its permutation may drop
// the sun code without changing a single pixel.
//
// The classifier must decide "faces the sun" with sun_faces() below, so that
// it and the lighting test the same value.

#ifndef UBER_SUN_LIGHTING_GLSL
#define UBER_SUN_LIGHTING_GLSL

#include "lighting_params.glsl"

struct SunTerm {
    vec3 diffuse;   // multiplied by albedo by the caller
    vec3 specular;
};

// N.L with the stored normal renormalised (16F storage drifts from unit
// length). Normalising does not change the sign, and a zero or broken normal
// yields NaN, which sun_faces() reports as not facing.
float sun_n_dot_l(vec3 normal)
{
    return dot(normalize(normal), params.sun_direction.xyz);
}

// The one "faces the sun" test. x > 0 is false for NaN, so a broken normal
// counts as not facing, in the classifier and in sun_lighting() alike.
bool sun_faces(vec3 normal)
{
    return sun_n_dot_l(normal) > 0.0;
}

SunTerm sun_lighting(vec3 normal, vec3 world_pos, float spec_amount, float spec_power)
{
    SunTerm term;
    term.diffuse = vec3(0.0);
    term.specular = vec3(0.0);

    float n_dot_l = sun_n_dot_l(normal);
    if (!(n_dot_l > 0.0)) { // the negation of sun_faces(), NaN included
        return term;        // exactly zero: the contract SUN_LIGHT relies on
    }

    vec3 n = normalize(normal);
    vec3 l = params.sun_direction.xyz;
    vec3 v = normalize(params.camera_pos.xyz - world_pos);
    vec3 h = normalize(l + v);
    float n_dot_h = dot(n, h);

    // pow(0, 0) is undefined and a negative power blows up near 0; both could
    // turn into Inf/NaN, and 0 * NaN would break "shadow 0 means prelit". So
    // the power is clamped to >= 0 and N.H <= 0 (or NaN from a degenerate
    // half vector) gives no highlight.
    float highlight = 0.0;
    if (n_dot_h > 0.0) {
        highlight = pow(min(n_dot_h, 1.0), max(spec_power, 0.0));
    }

    term.diffuse = params.sun_color.rgb * n_dot_l;
    term.specular = spec_amount * params.sun_color.rgb * highlight;
    return term;
}

// The sun's contribution to a surface before shadowing.
vec3 sun_surface_radiance(vec3 albedo, vec3 normal, vec3 world_pos, float spec_amount, float spec_power)
{
    SunTerm term = sun_lighting(normal, world_pos, spec_amount, spec_power);
    return albedo * term.diffuse + term.specular;
}

#endif // UBER_SUN_LIGHTING_GLSL
