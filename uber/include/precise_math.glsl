// precise_math.glsl -- arithmetic that must round identically in every shader.
//
// Some values decide a classification bit (which side of a distance threshold
// a pixel is, whether it faces the sun, whether a shadow tap is occluded). The
// classifier and every lighting permutation compute them separately, and must
// agree bit for bit near the threshold. `precise` (SPIR-V NoContraction) stops
// a driver from fusing multiply-adds differently per shader, but glslang does
// not put it on OpDot, so the dot product is written out here.

#ifndef UBER_PRECISE_MATH_GLSL
#define UBER_PRECISE_MATH_GLSL

float precise_dot(vec3 a, vec3 b)
{
    precise float d = a.x * b.x + a.y * b.y + a.z * b.z;
    return d;
}

#endif // UBER_PRECISE_MATH_GLSL
