0 a syntax error only with FEAT_B: grouped over the permutations that have it
#version 450
layout(location = 0) out vec4 out_color;
void main() {
  vec4 c = vec4(1.0);
#ifdef FEAT_A
  c.r = 0.5;
#endif
#ifdef FEAT_B
  c.g = undeclared_thing * 2.0
#endif
  out_color = c;
}
