5 a mesh shader and its task shader
#version 450
#extension GL_EXT_mesh_shader : require
layout(local_size_x = 1) in;
layout(triangles, max_vertices = 3, max_primitives = 1) out;
void main() {
  SetMeshOutputsEXT(3, 1);
  gl_MeshVerticesEXT[0].gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
  gl_MeshVerticesEXT[1].gl_Position = vec4(1.0, 0.0, 0.0, 1.0);
#ifdef FEAT_A
  gl_MeshVerticesEXT[2].gl_Position = vec4(0.0, 2.0, 0.0, 1.0);
#else
  gl_MeshVerticesEXT[2].gl_Position = vec4(0.0, 1.0, 0.0, 1.0);
#endif
  gl_PrimitiveTriangleIndicesEXT[0] = uvec3(0, 1, 2);
}
//--
//--
#version 450
#extension GL_EXT_mesh_shader : require
layout(local_size_x = 1) in;
void main() { EmitMeshTasksEXT(1, 1, 1); }
