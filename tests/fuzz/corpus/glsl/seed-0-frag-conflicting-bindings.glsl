0 set 0 binding 1 is a sampler with FEAT_A and a uniform buffer without: the shared layout refuses it
#version 450
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;
#ifdef FEAT_A
layout(set = 0, binding = 1) uniform sampler2D tex;
vec4 base() { return texture(tex, in_uv); }
#else
layout(set = 0, binding = 1) uniform Base { vec4 colour; } base_block;
vec4 base() { return base_block.colour; }
#endif
#ifdef FEAT_B
layout(push_constant) uniform Push { vec4 scale; vec4 bias; } push;
#else
layout(push_constant) uniform Push { vec4 scale; } push;
#endif
void main() { out_color = base() * push.scale; }
