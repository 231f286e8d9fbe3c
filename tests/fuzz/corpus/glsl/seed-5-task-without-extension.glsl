5 a task companion without its extension: glslang lists the extensions that would do on the lines after its message, which the diagnostic loses (a known finding)
#version 450
#extension GL_EXT_mesh_shader : require
layout(local_size_x = 1) in;
layout(triangles, max_vertices = 3, max_primitives = 1) out;
void main() { SetMeshOutputsEXT(0, 0); }
//--
//--
#version 450
layout(local_size_x = 1) in;
void main() { EmitMeshTasksEXT(1, 1, 1); }
