3 the vertex half includes itself by a path through the include folder (skipped until the includer limits the depth)
#version 450
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(1.0); }
//--
//--
#version 450
#include "include/../second.glsl"
void main() { gl_Position = vec4(0.0); }
