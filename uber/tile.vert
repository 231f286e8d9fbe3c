#version 450
// tile.vert -- places the corners of screen tiles for the tiled light pass.
//
// The vertex buffer is the prebuilt grid of tile corners in pixels; per-class index buffers
// pick the tiles. Pixel (0, 0) is the top-left corner, and Vulkan's clip space has y down,
// so pixels map to NDC without a flip.

layout(location = 0) in vec2 in_corner_pixel;

layout(push_constant) uniform TilePush {
    vec2 inv_viewport;  // 1 / framebuffer size in pixels
} push;

void main()
{
    gl_Position = vec4(in_corner_pixel * push.inv_viewport * 2.0 - 1.0, 0.0, 1.0);
}
