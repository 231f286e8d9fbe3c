4 a compute companion sharing the fragment shader's layout
#version 450
layout(set = 0, binding = 0) uniform Params { vec4 tint; } params;
layout(location = 0) out vec4 out_color;
void main() {
  out_color = params.tint;
#ifdef FEAT_B
  out_color.a = 1.0;
#endif
}
//--
//--
#version 450
layout(local_size_x = 32) in;
layout(set = 0, binding = 1, std430) buffer Keys { uint keys[]; } keys;
void main() { keys.keys[gl_GlobalInvocationID.x] = 1u; }
