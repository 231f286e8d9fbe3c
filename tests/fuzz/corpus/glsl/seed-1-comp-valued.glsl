1 compute, a layout per permutation (Vulkan 1.0): bindings differ by QUALITY, which is allowed here
#version 450
layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) buffer Data { float values[]; } data;
#if QUALITY == 2
layout(set = 0, binding = 1, std430) readonly buffer Extra { float more[]; } extra;
#endif
void main() {
  uint i = gl_GlobalInvocationID.x;
  float v = data.values[i] * float(FIXED);
#ifdef FEAT_A
  v += 1.0;
#endif
#if QUALITY == 2
  v += extra.more[i];
#elif QUALITY == 1
  v *= 0.5;
#endif
  data.values[i] = v;
}
