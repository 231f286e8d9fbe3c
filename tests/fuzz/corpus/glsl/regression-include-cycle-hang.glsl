0 an include file that includes itself with no guard: glslang follows the cycle without end (skipped until the includer limits the depth)
#version 450
#include "fuzz.glsl"
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(1.0); }
//--
#include "fuzz.glsl"
