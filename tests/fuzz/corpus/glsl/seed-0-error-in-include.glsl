0 the error is in the included file; its line is reported there
#version 450
#include <fuzz.glsl>
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(helper()); }
//--
float helper() {
#ifdef FEAT_B
  return 1.0 + ;
#else
  return 1.0;
#endif
}
