#version 450
// forward_full_screen.vert -- one triangle over the whole frame (vertices 0..2, no buffers): the
// forward pass's depth copy (forward_depth.frag).

void main()
{
    vec2 corner = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
