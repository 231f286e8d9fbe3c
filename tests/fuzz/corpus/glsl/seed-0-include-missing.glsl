0 an include that is not there, only with FEAT_A
#version 450
#ifdef FEAT_A
#include "missing.glsl"
#endif
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(0.0); }
