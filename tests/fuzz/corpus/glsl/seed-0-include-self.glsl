0 an include file that includes itself, guarded
#version 450
#include "fuzz.glsl"
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(VALUE); }
//--
#ifndef FUZZ_GLSL
#define FUZZ_GLSL
#include "fuzz.glsl"
#define VALUE 0.25
#endif
