6 ray generation and closest hit
#version 460
#extension GL_EXT_ray_tracing : require
layout(set = 0, binding = 0) uniform accelerationStructureEXT scene;
layout(set = 0, binding = 1, rgba8) uniform image2D target;
layout(location = 0) rayPayloadEXT vec3 colour;
void main() {
  vec2 p = vec2(gl_LaunchIDEXT.xy) / vec2(gl_LaunchSizeEXT.xy);
  traceRayEXT(scene, gl_RayFlagsOpaqueEXT, 0xff, 0, 0, 0, vec3(p, 0.0), 0.001, vec3(0.0, 0.0, 1.0), 100.0, 0);
#ifdef FEAT_A
  colour *= 0.5;
#endif
  imageStore(target, ivec2(gl_LaunchIDEXT.xy), vec4(colour, 1.0));
}
//--
//--
#version 460
#extension GL_EXT_ray_tracing : require
layout(location = 0) rayPayloadInEXT vec3 colour;
void main() { colour = vec3(gl_HitTEXT); }
