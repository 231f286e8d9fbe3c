#version 450
// shadow.vert -- depth-only sun shadow map: the scene's instances seen from the sun.
#extension GL_GOOGLE_include_directive : require
#include "scene_params.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 2) in vec4 in_model_col0;
layout(location = 3) in vec4 in_model_col1;
layout(location = 4) in vec4 in_model_col2;
layout(location = 5) in vec4 in_model_col3;

void main()
{
    mat4 model = mat4(in_model_col0, in_model_col1, in_model_col2, in_model_col3);
    gl_Position = scene.sun_view_proj * (model * vec4(in_position, 1.0));
}
