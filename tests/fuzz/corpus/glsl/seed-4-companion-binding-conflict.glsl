4 a compute companion in the shared layout whose binding 0 is a storage buffer where the fragment shader has a uniform buffer
#version 450
layout(set = 0, binding = 0) uniform Params { vec4 tint; } params;
layout(location = 0) out vec4 out_color;
void main() { out_color = params.tint; }
//--
//--
#version 450
layout(local_size_x = 32) in;
layout(set = 0, binding = 0, std430) buffer Keys { uint keys[]; } keys;
void main() {
#ifdef COMPANION
  keys.keys[gl_GlobalInvocationID.x] = 0u;
#endif
}
