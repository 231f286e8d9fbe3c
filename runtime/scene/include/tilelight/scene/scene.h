#pragma once
// The procedural outdoor scene: meshes, instances, cameras and the sun, on the CPU.
//
// Everything the frame needs to know about the world, independent of Vulkan: the runtime
// uploads the meshes and instances once and fills the scene and lighting uniform blocks from
// a Camera. The layout is deterministic (a fixed seed), so every run and test sees the same
// frame. Units are metres; y is up.

#include "tilelight/scene/local_light.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tilelight {

struct MeshVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv{};  // base colour texture coordinate (0 where the mesh has no texture)
};

// How a texture is read between and outside its texels (glTF's sampler).
enum class TextureWrap { repeat, mirrored_repeat, clamp_to_edge };
enum class TextureFilter { nearest, linear };

struct TextureSampling {
  TextureFilter magnify = TextureFilter::linear;
  TextureFilter minify = TextureFilter::linear;
  TextureFilter between_mips = TextureFilter::linear;
  bool mipmapped = true;  // false: minification reads mip 0 only
  TextureWrap wrap_u = TextureWrap::repeat;
  TextureWrap wrap_v = TextureWrap::repeat;
};

// An RGBA8 image whose colour channels are sRGB-encoded (a glTF base colour texture): uploaded
// as an _SRGB format, so shaders read linear values.
struct Texture {
  std::string name;
  std::uint32_t width = 0;         // > 0
  std::uint32_t height = 0;        // > 0
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, rows from the top (texture v = 0)
  TextureSampling sampling;
};

struct Mesh {
  std::string name;
  std::vector<MeshVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangle list
  // Every face is planar and all its vertices carry the same normal n and the same dot(n,
  // position), exactly (the cube's and the ground's quads). Its instances get material.w = 1, and
  // the G-buffer pass then stores the same values for both triangles of a face where they share
  // a pixel (uber/scene/gbuffer.frag), so a face's inner diagonal is no MSAA edge.
  bool flat_faces = false;
  // Index into Scene::textures: the base colour texture, multiplied into every instance's
  // albedo at the vertices' uv. None: the albedo alone.
  std::optional<std::uint32_t> base_colour_texture;
  // glTF's alphaMode MASK: texels whose base colour alpha (texture alpha times the instance's
  // alpha.x) is below the instance's cutoff (alpha.y) are discarded, in the G-buffer and the sun
  // shadow map. Masked meshes are drawn with pipelines of their own, after the opaque ones.
  bool alpha_mask = false;
  // glTF's alphaMode BLEND: drawn by the forward pass after the deferred ones, blended over the
  // light target with the base colour's alpha (texture alpha times the instance's alpha_mask.x),
  // back to front (docs/local-lights.md, "Forward pass for blended materials"). Not in the
  // G-buffer, and casts no sun shadow. Never together with alpha_mask.
  bool blend = false;
  // false: back faces are culled in the G-buffer (glTF's single-sided materials; their triangles
  // wind counter-clockwise seen from the front). true (the procedural scene's meshes): both sides
  // are drawn, and a back face stores the flipped normal.
  bool double_sided = true;
};

// Per-instance vertex data (binding 1 of the scene pipelines; see uber/scene/scene.vert).
struct Instance {
  glm::mat4 model;
  glm::vec4 albedo_spec;  // rgb albedo, a specular amount (0..1)
  glm::vec4 material;     // x specular power, y motion ID (1..127; 0 is the sky), z checker scale (0 = none),
                          // w 1 when the mesh has flat_faces, else 0
  glm::vec2 alpha_mask{1.0f, 0.0f};  // x base colour factor alpha, y alpha cutoff: read by masked and blended meshes
};

// One mesh drawn with a contiguous range of the instance buffer.
struct MeshBatch {
  std::uint32_t mesh = 0;  // index into Scene::meshes
  std::uint32_t first_instance = 0;
  std::uint32_t instance_count = 0;
};

struct Camera {
  std::string name;
  std::string description;
  glm::vec3 position{};
  glm::vec3 target{};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float vertical_fov_degrees = 60.0f;
  glm::vec3 shadow_focus{};  // ground point the sun's shadow map is centred on
  // Clip planes (view depths). The procedural cameras keep these; a placed or file camera's
  // follow the scene it sees (view_fit.h), so an interior view is neither clipped nor blurred.
  float near_plane = 0.5f;
  float far_plane = 2000.0f;
  // Non-empty: why the camera cannot be drawn (an orthographic or malformed glTF camera); the
  // command line refuses to choose it with this text.
  std::string unusable{};
};

// Lighting constants shared by classification and lighting (distances are view depths).
struct SunAndAtmosphere {
  glm::vec3 sun_direction;  // normalised, towards the sun
  glm::vec3 sun_color;
  glm::vec3 fog_color;
  float fog_density = 0.0f;  // per metre
  float shadow_fade_start = 0.0f;
  float shadow_fade_length = 0.0f;
  float scattering_start = 0.0f;
  float shadow_depth_bias = 0.0f;     // in shadow-map depth units (0..1)
  float shadow_half_extent = 0.0f;    // metres covered either side of the focus
  float shadow_depth_range = 0.0f;    // metres from the sun's near to far plane
  std::uint32_t shadow_map_size = 0;  // texels per side
  glm::vec3 sky_zenith;
  glm::vec3 sky_horizon;
  glm::vec3 ambient_sky;
  glm::vec3 ambient_ground;
};

struct Scene {
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  std::vector<MeshBatch> batches;
  std::vector<Texture> textures;
  std::vector<Camera> cameras;  // cameras[0] is the default
  SunAndAtmosphere sun;
  // Point, spot and box lights drawn after the sun (local_light.h); empty by default.
  std::vector<LocalLight> local_lights;
  std::string source;  // the file the scene was loaded from (its name only); empty: the procedural scene
  // The file's coordinates -> the renderer's (a loaded scene is scaled and centred, see
  // runtime/gltf/src/scene_framing.h): a uniform scale then a translation. Identity for the
  // procedural scene. Placed cameras (--eye) are given in the file's coordinates.
  glm::mat4 world_from_file{1.0f};

  // Triangles drawn per frame: every batch's instances times its mesh's triangles.
  std::uint64_t triangle_count() const;

  // Throws tilelight::Error listing the known names when `name` is not a camera.
  const Camera& camera(std::string_view name) const;
  std::vector<std::string> camera_names() const;
};

// The demo scene: ground, rows of boxes and pillars that cast sun shadows, spheres, distant
// buildings beyond the shadow-fade and scattering distances, a canopy that shades a large
// area, and sky. Cameras: "default" (all seven tile properties in frame), "sky" (only sky),
// "shadow" (only ground in solid shadow), "low" (grazing view across the boxes).
Scene make_demo_scene();

// The demo scene's sun, sky, fog and shadow settings (the shadow map covers the demo's field); a
// loaded scene starts from them and fits the shadow map and distances to its own bounds.
SunAndAtmosphere make_demo_sun();

// Camera matrices for a framebuffer of the given aspect ratio (Vulkan clip space: y down,
// depth 0..1).
struct CameraMatrices {
  glm::mat4 view_proj;
  glm::mat4 inv_view_proj;
  glm::vec3 forward;
};
CameraMatrices camera_matrices(const Camera& camera, float aspect);

// World -> sun shadow clip (orthographic, depth 0..1) centred on camera.shadow_focus.
glm::mat4 sun_view_proj(const SunAndAtmosphere& sun, const Camera& camera);

}  // namespace tilelight
