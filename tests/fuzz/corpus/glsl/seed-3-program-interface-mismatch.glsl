3 a program whose fragment half reads location 1, which the vertex half writes only with FEAT_A
#version 450
layout(location = 0) in vec3 normal;
layout(location = 1) in vec4 extra;
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(normal, 1.0) + extra; }
//--
//--
#version 450
layout(location = 0) in vec3 position;
layout(location = 0) out vec3 normal;
#ifdef FEAT_A
layout(location = 1) out vec4 extra;
#endif
void main() {
  normal = position;
#ifdef FEAT_A
  extra = vec4(1.0);
#endif
  gl_Position = vec4(position, 1.0);
}
