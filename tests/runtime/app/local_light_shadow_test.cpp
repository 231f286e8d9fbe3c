// Local lights' shadow maps (issue 38 item 3; docs/local-lights.md, "Shadows"): frames of the
// demo scene with a light and a cube hovering between it and the ground, on lavapipe under
// validation. A shadowed light darkens only pixels whose way to the light some mesh may block,
// and the pixels the cube blocks; the volume pass equals the full-screen reference and the
// classified target the naive one with shadows on; cached maps give the frame rebuilt maps give;
// shadows off is the unshadowed image; the pool's cap leaves the lights beyond it unshadowed.
#include "frame_support.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/error.h"
#include "tilelight_testing/gbuffer_samples.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace tilelight::test {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace local_light_shadow_test {
namespace {

constexpr std::uint32_t kWidth = 96, kHeight = 64;
constexpr std::uint32_t kFaceSize = 256;  // smaller than the default 512: the tests stay fast

// The hovering cube: 1.6 m wide, its centre 2 m above the ground, 10 m in front of the default
// camera (at (0, 7, 22), looking towards -z).
constexpr glm::vec3 kCasterCentre{0.0f, 2.0f, 10.0f};
constexpr float kCasterSize = 1.6f;

LocalLight point_light() {
  LocalLight l;
  l.type = LocalLightType::point;
  l.position = {0.3f, 4.0f, 10.2f};
  l.color = {1.0f, 0.8f, 0.6f};
  l.intensity = 80.0f;
  l.range = 9.0f;
  return l;
}

LocalLight spot_light() {
  LocalLight l;
  l.type = LocalLightType::spot;
  l.position = {0.3f, 5.0f, 10.2f};
  l.direction = glm::normalize(glm::vec3(0.05f, -1.0f, 0.1f));
  l.color = {0.5f, 0.8f, 1.0f};
  l.intensity = 120.0f;
  l.range = 10.0f;
  l.inner_cone_cos = std::cos(glm::radians(25.0f));
  l.outer_cone_cos = std::cos(glm::radians(45.0f));
  return l;
}

LocalLight box_light() {
  LocalLight l;
  l.type = LocalLightType::box;
  l.position = {0.0f, 2.0f, 10.0f};
  l.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  l.color = {0.8f, 1.0f, 0.5f};
  l.intensity = 3.0f;
  l.box_half_extent = {4.0f, 3.0f, 2.5f};
  l.box_falloff = 0.5f;
  return l;
}

struct ShadowCase {
  const char* name;
  LocalLight light;
};

void PrintTo(const ShadowCase& c, std::ostream* os) { *os << c.name; }

const ShadowCase kShadowCases[] = {{"point", point_light()}, {"spot", spot_light()}, {"box", box_light()}};

std::uint32_t mesh_named(const Scene& scene, const std::string& name) {
  for (std::uint32_t i = 0; i < scene.meshes.size(); ++i) {
    if (scene.meshes[i].name == name) return i;
  }
  throw Error("the demo scene has no mesh " + name);
}

// The demo scene with the hovering cube (a batch of its own) and `lights`.
Scene scene_with(const std::vector<LocalLight>& lights) {
  Scene scene = make_demo_scene();
  Instance cube{};
  cube.model = glm::scale(glm::translate(glm::mat4(1.0f), kCasterCentre), glm::vec3(kCasterSize));
  cube.albedo_spec = {0.7f, 0.2f, 0.2f, 0.2f};
  cube.material = {16.0f, 1.0f, 0.0f, 1.0f};
  scene.batches.push_back({mesh_named(scene, "cube"), static_cast<std::uint32_t>(scene.instances.size()), 1});
  scene.instances.push_back(cube);
  scene.local_lights = lights;
  return scene;
}

RendererOptions shadow_options(std::uint32_t msaa) {
  RendererOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.msaa = msaa;
  options.local_light_shadow_face_size = kFaceSize;
  return options;
}

// ---------------------------------------------------------------------------------------------
// Where a shadow may fall, on the CPU: a segment from the surface towards the light against each
// instance's box.

struct Box {
  glm::vec3 lo, hi;
};

std::vector<Box> instance_boxes(const Scene& scene) {
  std::vector<Box> boxes;
  for (const MeshBatch& batch : scene.batches) {
    const Mesh& mesh = scene.meshes[batch.mesh];
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const MeshVertex& v : mesh.vertices) {
      lo = glm::min(lo, v.position);
      hi = glm::max(hi, v.position);
    }
    for (std::uint32_t i = 0; i < batch.instance_count; ++i) {
      const glm::mat4& model = scene.instances[batch.first_instance + i].model;
      Box box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
      for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner{(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z};
        const glm::vec3 p = glm::vec3(model * glm::vec4(corner, 1.0f));
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
      }
      boxes.push_back(box);
    }
  }
  return boxes;
}

Box grown(const Box& b, float by) { return {b.lo - by, b.hi + by}; }

bool contains(const Box& b, glm::vec3 p) {
  return glm::all(glm::greaterThanEqual(p, b.lo)) && glm::all(glm::lessThanEqual(p, b.hi));
}

// Whether the segment from `a` to `b` meets the box (slabs).
bool segment_meets(const Box& box, glm::vec3 a, glm::vec3 b) {
  float t0 = 0.0f, t1 = 1.0f;
  const glm::vec3 d = b - a;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(d[axis]) < 1e-9f) {
      if (a[axis] < box.lo[axis] || a[axis] > box.hi[axis]) return false;
      continue;
    }
    float near = (box.lo[axis] - a[axis]) / d[axis], far = (box.hi[axis] - a[axis]) / d[axis];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return false;
  }
  return true;
}

// Where the light comes from for a surface point: its position, or (box) upstream through the box.
glm::vec3 towards_light(const LocalLight& light, glm::vec3 p) {
  if (light.type == LocalLightType::box) return p - light.direction * (2.0f * light.box_half_extent.z);
  return light.position;
}

glm::vec3 world_position(const LightingParamsBlock& params, std::uint32_t x, std::uint32_t y, float depth) {
  const glm::vec2 ndc = (glm::vec2(static_cast<float>(x), static_cast<float>(y)) + 0.5f) *
                            glm::vec2(params.viewport.z, params.viewport.w) * 2.0f -
                        1.0f;
  const glm::vec4 world = params.inv_view_proj * glm::vec4(ndc, depth, 1.0f);
  return glm::vec3(world) / world.w;
}

bool any_brighter(const RgbaImage& shadowed, const RgbaImage& unshadowed, std::uint32_t x, std::uint32_t y) {
  const auto s = shadowed.at(x, y), u = unshadowed.at(x, y);
  for (int c = 0; c < 3; ++c) {
    if (s[c] > u[c]) return true;
  }
  return false;
}

class LocalLightShadowFrame : public VulkanTest, public ::testing::WithParamInterface<ShadowCase> {};

// Single-sampled, so each pixel is one surface point. Against the same scene without shadows: no
// pixel gets brighter; a pixel gets darker only where some mesh (other than the one it lies on)
// stands between it and the light; and the pixels the cube blocks, which the light reaches, do.
TEST_P(LocalLightShadowFrame, DarkensWhereACasterBlocksTheLightOnly) {
  const ShadowCase& c = GetParam();
  const Scene scene = scene_with({c.light});
  RendererOptions options = shadow_options(1);
  options.baselines = Baselines::none;
  TileRenderer shadowed(context(), scene, options);
  shadowed.render_frame();
  EXPECT_EQ(shadowed.local_light_shadow_pool().maps, 1u);
  options.local_light_shadows = false;
  TileRenderer unshadowed(context(), scene, options);
  unshadowed.render_frame();
  TileRenderer dark(context(), scene_with({}), options);
  dark.render_frame();
  const RgbaImage on = shadowed.read_classified(), off = unshadowed.read_classified(), none = dark.read_classified();
  const GBufferSamples g = TileRendererTestSeam::read_gbuffer(shadowed);
  const LightingParamsBlock& params = TileRendererTestSeam::lighting_params(shadowed);

  const std::vector<Box> boxes = instance_boxes(scene);
  const Box caster = boxes.back();
  constexpr float kMargin = 0.1f;  // metres: the map's texels, the taps' disk, the biases
  std::uint32_t blocked = 0, blocked_darkened = 0, darkened = 0, brighter = 0, unexplained = 0;
  std::string first_unexplained;
  for (std::uint32_t y = 0; y < g.height; ++y) {
    for (std::uint32_t x = 0; x < g.width; ++x) {
      const float depth = g.at(x, y, 0)[12];
      if (depth == 1.0f) continue;
      const glm::vec3 p = world_position(params, x, y, depth);
      const glm::vec3 l = towards_light(c.light, p);
      const bool changed = on.at(x, y) != off.at(x, y);
      darkened += changed ? 1 : 0;
      brighter += any_brighter(on, off, x, y) ? 1 : 0;
      const bool reached = off.at(x, y) != none.at(x, y);
      const Box inner{caster.lo + kMargin, caster.hi - kMargin};
      if (reached && !contains(grown(caster, kMargin), p) && segment_meets(inner, p, l)) {
        ++blocked;
        blocked_darkened += changed ? 1 : 0;
      }
      if (!changed) continue;
      bool explained = false;
      for (const Box& box : boxes) {
        const Box outer = grown(box, kMargin);
        if (!contains(outer, p) && segment_meets(outer, p, l)) explained = true;
      }
      if (!explained && unexplained++ == 0) first_unexplained = std::to_string(x) + ", " + std::to_string(y);
    }
  }
  EXPECT_EQ(brighter, 0u);
  EXPECT_EQ(unexplained, 0u) << "darkened with nothing in the way, first at " << first_unexplained;
  EXPECT_GT(blocked, 20u) << "the cube's shadow is (almost) out of frame";
  EXPECT_GE(blocked_darkened * 100, blocked * 95)
      << blocked_darkened << " of " << blocked << " blocked pixels darkened";
  EXPECT_GE(darkened, blocked_darkened);
}

std::string shadow_case_name(const ::testing::TestParamInfo<ShadowCase>& shadow_case) { return shadow_case.param.name; }

INSTANTIATE_TEST_SUITE_P(Lights, LocalLightShadowFrame, ::testing::ValuesIn(kShadowCases), shadow_case_name);

// An alpha-masked caster discards where the G-buffer does: a cube whose every texel is below
// its cutoff casts nothing into a local light's map (nor the sun's, nor shows): the frame equals
// the one without it.
class LocalLightShadowCasters : public VulkanTest {};

TEST_F(LocalLightShadowCasters, AMasksHolesLetTheLocalLightThrough) {
  Scene masked = scene_with({point_light()});
  Mesh cube = masked.meshes[mesh_named(masked, "cube")];
  cube.name = "transparent cube";
  cube.alpha_mask = true;
  Texture clear;
  clear.name = "alpha 0";
  clear.width = clear.height = 1;
  clear.rgba = {255, 255, 255, 0};
  clear.sampling.magnify = clear.sampling.minify = TextureFilter::nearest;
  clear.sampling.mipmapped = false;
  masked.textures.push_back(clear);
  cube.base_colour_texture = static_cast<std::uint32_t>(masked.textures.size() - 1);
  masked.meshes.push_back(cube);
  masked.batches.back().mesh = static_cast<std::uint32_t>(masked.meshes.size() - 1);
  masked.instances.back().alpha_mask = {1.0f, 0.5f};

  Scene without = make_demo_scene();
  without.local_lights = {point_light()};
  RendererOptions options = shadow_options(1);
  options.baselines = Baselines::none;
  TileRenderer a(context(), masked, options);
  a.render_frame();
  TileRenderer b(context(), without, options);
  b.render_frame();
  const FrameComparison same = compare(a.read_classified(), b.read_classified(), 0.0);
  EXPECT_EQ(same.pixels_over_tolerance, 0u) << same.first_difference;
}

// ---------------------------------------------------------------------------------------------
// The volume pass against the full-screen reference with shadows on, bit for bit, in the
// classified and naive targets (and classified == naive == dynamic within each renderer), for
// each type at 4x and 1x; "inside" puts the camera inside the point light's volume.

struct VolumeCase {
  const char* name;
  LocalLight light;
  std::optional<Camera> camera;
};

void PrintTo(const VolumeCase& c, std::ostream* os) { *os << c.name; }

Camera camera_inside_point_light() {
  Camera camera = make_demo_scene().camera("default");
  camera.position = point_light().position + glm::vec3(0.0f, 1.0f, 6.0f);
  camera.target = kCasterCentre;
  return camera;
}

std::vector<VolumeCase> volume_cases() {
  std::vector<VolumeCase> cases;
  for (const ShadowCase& c : kShadowCases) cases.push_back({c.name, c.light, std::nullopt});
  cases.push_back({"point_camera_inside", point_light(), camera_inside_point_light()});
  return cases;
}

using VolumeFrameCase = std::tuple<VolumeCase, std::uint32_t>;  // case, MSAA

class LocalLightShadowVolumes : public VulkanTest, public ::testing::WithParamInterface<VolumeFrameCase> {};

TEST_P(LocalLightShadowVolumes, EqualTheFullScreenReferencePerPixel) {
  const auto& [c, msaa] = GetParam();
  const Scene scene = scene_with({c.light});
  RendererOptions options = shadow_options(msaa);
  options.camera_pose = c.camera;
  EXPECT_EQ(expect_volumes_equal_full_screen(context(), scene, options).maps, 1u);
}

std::string volume_case_name(const ::testing::TestParamInfo<VolumeFrameCase>& info) {
  return std::string(std::get<0>(info.param).name) + "_msaa" + std::to_string(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(Lights, LocalLightShadowVolumes,
                         ::testing::Combine(::testing::ValuesIn(volume_cases()), ::testing::Values(4u, 1u)),
                         volume_case_name);

// ---------------------------------------------------------------------------------------------
// Every type shadowed at once: classified == naive == dynamic with both light passes; cached maps
// give what maps rendered every frame give; shadows off give the unshadowed image; the cap.

std::vector<LocalLight> every_light() { return {point_light(), spot_light(), box_light()}; }

class LocalLightShadowEquivalence : public VulkanTest, public ::testing::WithParamInterface<LightPass> {};

TEST_P(LocalLightShadowEquivalence, ClassifiedEqualsNaiveWithShadowedLights) {
  RendererOptions options = shadow_options(0);
  options.light_pass = GetParam();
  TileRenderer renderer(context(), scene_with(every_light()), options);
  EXPECT_EQ(renderer.local_light_shadow_pool().faces, 8u);  // 6 + 1 + 1
  render_equivalent_frame(renderer);
  render_equivalent_frame(renderer);  // cached maps, pre-recorded passes
}

INSTANTIATE_TEST_SUITE_P(Passes, LocalLightShadowEquivalence, ::testing::Values(LightPass::compute, LightPass::raster),
                         [](const ::testing::TestParamInfo<LightPass>& pass) {
                           return std::string(to_string(pass.param));
                         });

class LocalLightShadowSettings : public VulkanTest {};

TEST_F(LocalLightShadowSettings, CachedMapsGiveTheFrameRebuiltMapsGive) {
  const Scene scene = scene_with(every_light());
  RendererOptions options = shadow_options(4);
  options.baselines = Baselines::none;
  TileRenderer cached(context(), scene, options);
  options.local_light_shadow_cache = false;
  TileRenderer rebuilt(context(), scene, options);
  EXPECT_TRUE(cached.local_light_shadow_pool().cached);
  EXPECT_FALSE(rebuilt.local_light_shadow_pool().cached);
  for (int frame = 0; frame < 2; ++frame) {
    const FrameResult a = cached.render_frame();
    rebuilt.render_frame();
    // The cached renderer renders its maps in its first frame only.
    if (frame == 1) {
      EXPECT_EQ(a.timings.local_light_shadows, 0.0);
    }
    const FrameComparison same = compare(cached.read_classified(), rebuilt.read_classified(), 0.0);
    EXPECT_EQ(same.pixels_over_tolerance, 0u) << "frame " << frame << ": " << same.first_difference;
  }
}

TEST_F(LocalLightShadowSettings, ShadowsOffGiveTheUnshadowedImage) {
  std::vector<LocalLight> lights = every_light();
  RendererOptions options = shadow_options(4);
  options.baselines = Baselines::none;
  options.local_light_shadows = false;
  TileRenderer off(context(), scene_with(lights), options);
  EXPECT_FALSE(off.local_light_shadow_pool().enabled);
  EXPECT_EQ(off.local_light_shadow_pool().maps, 0u);
  EXPECT_EQ(off.local_light_shadow_pool().unshadowed, 0u);
  off.render_frame();
  for (LocalLight& l : lights) l.casts_shadows = false;
  options.local_light_shadows = true;
  TileRenderer casting_none(context(), scene_with(lights), options);
  EXPECT_EQ(casting_none.local_light_shadow_pool().maps, 0u);
  casting_none.render_frame();
  const FrameComparison same = compare(off.read_classified(), casting_none.read_classified(), 0.0);
  EXPECT_EQ(same.pixels_over_tolerance, 0u) << same.first_difference;
}

// A cap of 4 faces: the point light's 6 do not fit, the spot's and the box's do. The point light
// is drawn unshadowed: the frame equals one whose point light casts no shadow.
TEST_F(LocalLightShadowSettings, LightsBeyondTheCapAreDrawnUnshadowed) {
  std::vector<LocalLight> lights = every_light();
  RendererOptions options = shadow_options(1);
  options.baselines = Baselines::none;
  options.local_light_shadow_cap_bytes = 4ull * kFaceSize * kFaceSize * 4;
  TileRenderer capped(context(), scene_with(lights), options);
  const LocalLightShadowPool pool = capped.local_light_shadow_pool();
  EXPECT_EQ(pool.maps, 2u);
  EXPECT_EQ(pool.faces, 2u);
  EXPECT_EQ(pool.unshadowed, 1u);
  EXPECT_LE(pool.bytes, pool.cap_bytes);
  capped.render_frame();
  lights[0].casts_shadows = false;
  TileRenderer expected(context(), scene_with(lights), options);
  EXPECT_EQ(expected.local_light_shadow_pool().unshadowed, 0u);
  expected.render_frame();
  const FrameComparison same = compare(capped.read_classified(), expected.read_classified(), 0.0);
  EXPECT_EQ(same.pixels_over_tolerance, 0u) << same.first_difference;
}

}  // namespace
}  // namespace local_light_shadow_test
}  // namespace tilelight::test
