2 vertex, Vulkan 1.3, debug information stripped, optimised permutations only
#version 450
layout(location = 0) in vec3 position;
layout(location = 0) out vec3 colour;
layout(set = 0, binding = 0) uniform Camera { mat4 view_projection; } camera;
void main() {
  vec3 p = position;
#if defined(FEAT_A) && defined(FEAT_B)
  p *= 2.0;
  colour = vec3(1.0, 0.0, 0.0);
#else
  colour = vec3(0.0);
#endif
  gl_Position = camera.view_projection * vec4(p, 1.0);
}
