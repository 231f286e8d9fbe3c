#version 450
// local_light_volume.vert -- a light's volume mesh (§19.7.1): a vertex of the unit mesh of its
// shape, placed around the light and projected. The runtime culls the front faces and tests
// "greater or equal" against the resolved scene depth, so each pixel whose surface may lie
// inside the volume runs local_light.frag once, the camera inside the volume or not.

#extension GL_GOOGLE_include_directive : require

#include "local_light_draw.glsl"

layout(location = 0) in vec3 unit_position;

void main()
{
    LocalLightData light = local_lights.lights[draw.light_index];
    gl_Position = draw.view_proj * vec4(local_light_volume_position(light, unit_position), 1.0);
}
