// light_scattering.glsl -- distance fog: extinction plus in-scattering.
//
// Over the distance t travelled beyond distances.z (view depth), the surface
// colour is attenuated by extinction = exp(-density * t) and the fog colour
// fills the remainder:
//     colour * extinction + fog_color.rgb * (1 - extinction)
// with density = fog_color.a (per world unit, one scalar for all channels).
//
// Exactness contract: at view depths <= scattering start the function returns
// its input colour untouched (extinction 1, in-scatter 0, not merely close to
// them), so a tile whose pixels all lie before the start (LIGHT_SCATTERING bit
// clear) may skip it. The guard is light_scattering_active(), the same
// comparison the classifier makes.

#ifndef UBER_LIGHT_SCATTERING_GLSL
#define UBER_LIGHT_SCATTERING_GLSL

#include "lighting_params.glsl"

bool light_scattering_active(float view_depth)
{
    return view_depth > params.distances.z;
}

vec3 light_scattering_apply(vec3 colour, float view_depth)
{
    if (!light_scattering_active(view_depth)) {
        return colour;
    }
    float t = max(view_depth - params.distances.z, 0.0);
    float extinction = exp(-params.fog_color.a * t);
    return colour * extinction + params.fog_color.rgb * (1.0 - extinction);
}

#endif // UBER_LIGHT_SCATTERING_GLSL
