0 an escape sequence in the shader: glslang quotes the token, and the diagnostic carries ESC [ 2 J unescaped (a known finding)
#version 450
layout(location = 0) out vec4 out_color;
[2J
void main() { out_color = vec4(1.0); }
