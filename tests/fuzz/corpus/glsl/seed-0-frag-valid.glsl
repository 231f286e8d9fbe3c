0 fragment uber-shader, collapsed; shared layout; an include
#version 450
#include "fuzz.glsl"
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;
void main() {
  vec4 c = params.tint;
#ifdef FEAT_A
  c *= texture(tex, in_uv);
#endif
#ifdef FEAT_B
  c.rgb = shade(c.rgb);
#endif
  out_color = c;
}
//--
layout(set = 0, binding = 0) uniform Params { vec4 tint; } params;
layout(set = 0, binding = 1) uniform sampler2D tex;
vec3 shade(vec3 c) { return c * 0.5; }
