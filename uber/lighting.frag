#version 450
// lighting.frag -- the deferred global-light pass as one uber-shader, raster form: the tile pass
// draws each class's tiles with this permutation, the naive and dynamic passes draw it over the
// whole frame. The shading itself, its seven switches and DYNAMIC_BRANCHING are in
// light_pass.glsl, shared with the compute form (lighting.comp).

// shadergen enables #include itself; naming it here keeps the file compilable by plain
// glslangValidator -I<include dir> as well.
#extension GL_GOOGLE_include_directive : require

#include "light_pass.glsl"

layout(location = 0) out vec4 out_color;

void main()
{
    out_color = vec4(shade_pixel(ivec2(gl_FragCoord.xy)), 1.0);
}
