// sun_lighting.glsl -- direct sunlight: Lambert diffuse + Blinn-Phong specular.
//
//     radiance = sun_color * N.L * (albedo + spec_amount * max(N.H, 0)^spec_power)
//
// Exactness contract: where the surface does not face the sun (the G-buffer's
// sun-facing bit, set by the material where N.L > 0) the sun term (diffuse AND
// specular) is exactly vec3(0), by an early return rather than a smooth
// falloff. A tile whose non-sky pixels all face away from the sun (SUN_LIGHT
// bit clear) then gets exactly prelit from the full shader too, so its
// permutation may drop the sun code without changing a single pixel. The
// classifier reads the same bit (gbuffer.glsl), so it and the lighting cannot
// disagree about which pixels face the sun.
//
// The specular lobe is scaled by N.L like the diffuse one, so the whole term
// also goes to 0 continuously at the terminator: a normal the bit calls facing
// whose renormalised N.L rounds to 0 gets no highlight popping in.

#ifndef UBER_SUN_LIGHTING_GLSL
#define UBER_SUN_LIGHTING_GLSL

#include "lighting_params.glsl"
#include "precise_math.glsl"

// Largest finite half float: RT2 is 16F, so no meaningful power exceeds it.
const float SUN_MAX_SPEC_POWER = 65504.0;
// Lower bound for N.H inside pow(): keeps log2() finite (pow is exp2(p * log2(x))),
// and x^p for x below it is 0 for any useful power anyway.
const float SUN_MIN_N_DOT_H = 1e-20;

struct SunTerm {
    vec3 diffuse;   // multiplied by albedo by the caller
    vec3 specular;
};

// N.L with the stored normal renormalised (16F storage drifts from unit
// length); precise_dot(), so that every permutation rounds it alike.
float sun_n_dot_l(vec3 normal)
{
    return precise_dot(normalize(normal), params.sun_direction.xyz);
}

// Every value returned is finite whatever the G-buffer holds (spec_amount is
// unorm; NaN/Inf powers and degenerate half vectors are caught), so that
// "sun term * shadow factor 0" is exactly 0, as the solid-shadow class assumes.
// `faces_sun`: the sample's sun-facing bit (GSample.faces_sun).
SunTerm sun_lighting(bool faces_sun, vec3 normal, vec3 world_pos, float spec_amount, float spec_power)
{
    SunTerm term;
    term.diffuse = vec3(0.0);
    term.specular = vec3(0.0);

    if (!faces_sun) {
        return term; // exactly zero: the contract SUN_LIGHT relies on
    }
    // The bit was decided on the stored normal; renormalised, N.L of a grazing
    // one may still round to 0 or below, or be NaN for an infinite normal: no
    // sun then, and every value stays finite.
    float n_dot_l = sun_n_dot_l(normal);
    n_dot_l = n_dot_l > 0.0 ? n_dot_l : 0.0;

    vec3 n = normalize(normal);
    vec3 l = params.sun_direction.xyz;
    vec3 v = normalize(params.camera_pos.xyz - world_pos);
    vec3 h = normalize(l + v);
    float n_dot_h = dot(n, h);

    // NaN power (comparison false) -> 0, +Inf -> the cap: pow() then cannot
    // produce Inf or NaN. N.H <= 0, or NaN from a degenerate half vector
    // (camera at the point, or looking straight into the sun), gives no highlight.
    float power = spec_power > 0.0 ? min(spec_power, SUN_MAX_SPEC_POWER) : 0.0;
    float highlight = 0.0;
    if (n_dot_h > 0.0) {
        highlight = pow(clamp(n_dot_h, SUN_MIN_N_DOT_H, 1.0), power);
    }

    term.diffuse = params.sun_color.rgb * n_dot_l;
    term.specular = params.sun_color.rgb * (spec_amount * highlight * n_dot_l);
    return term;
}

// The sun's contribution to a surface before shadowing.
vec3 sun_surface_radiance(vec3 albedo, bool faces_sun, vec3 normal, vec3 world_pos, float spec_amount,
                          float spec_power)
{
    SunTerm term = sun_lighting(faces_sun, normal, world_pos, spec_amount, spec_power);
    return albedo * term.diffuse + term.specular;
}

#endif // UBER_SUN_LIGHTING_GLSL
