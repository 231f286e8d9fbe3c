0 no entry point
#version 450
layout(location = 0) out vec4 out_color;
void shade() { out_color = vec4(1.0); }
