#version 450
// local_light_full_screen.vert -- one triangle over the whole frame: the full-screen local-light
// pass (the chapter's baseline and the volume pass's per-pixel reference) runs local_light.frag
// on every pixel, and the light's attenuation, zero outside its volume, decides what it adds.
void main()
{
    vec2 corner = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
