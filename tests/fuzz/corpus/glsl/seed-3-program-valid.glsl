3 a program: the fragment half, then the include, then the vertex half
#version 450
#include "fuzz.glsl"
layout(location = 0) in vec3 normal;
#ifdef FEAT_A
layout(location = 1) in vec2 uv;
#endif
layout(location = 0) out vec4 out_color;
void main() {
  vec3 c = normalize(normal) * 0.5 + 0.5;
#ifdef FEAT_A
  c *= uv.x;
#endif
  out_color = vec4(c * fog(), 1.0);
}
//--
float fog() {
#ifdef FEAT_B
  return 0.7;
#else
  return 1.0;
#endif
}
//--
#version 450
layout(location = 0) in vec3 position;
layout(location = 0) out vec3 normal;
#ifdef FEAT_A
layout(location = 1) out vec2 uv;
#endif
void main() {
  normal = position;
#ifdef FEAT_A
  uv = position.xy;
#endif
  gl_Position = vec4(position, 1.0);
}
