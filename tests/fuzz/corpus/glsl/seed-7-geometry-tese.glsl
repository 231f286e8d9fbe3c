7 a geometry shader with a tessellation evaluation companion
#version 450
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
#ifdef FEAT_B
    gl_Position.y = -gl_Position.y;
#endif
    EmitVertex();
  }
  EndPrimitive();
}
//--
//--
#version 450
layout(triangles, equal_spacing, ccw) in;
void main() {
  gl_Position = gl_TessCoord.x * gl_in[0].gl_Position + gl_TessCoord.y * gl_in[1].gl_Position +
                gl_TessCoord.z * gl_in[2].gl_Position;
}
