// Local lights (issue 38; docs/local-lights.md): frames of the demo scene with lights added, on
// lavapipe under validation. Each light must light pixels inside its range, leave every pixel
// beyond it and every sky pixel exactly as the global pass wrote it, and go into the classified and the baselines' light targets alike (classified ==
// naive == dynamic per pixel, as without lights).
#include "frame_support.h"
#include "tilelight/scene/scene.h"
#include "tilelight_testing/gbuffer_samples.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include <glm/glm.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace tilelight::test {
namespace {

// ---------------------------------------------------------------------------------------------
// Frames.

constexpr std::uint32_t kWidth = 96, kHeight = 64;

// A 4x4 checker of red and green, sampled nearest: where a globe map falls, the lit colour
// varies in a pattern.
Texture checker_texture() {
  Texture t;
  t.name = "globe checker";
  t.width = t.height = 4;
  for (std::uint32_t y = 0; y < 4; ++y) {
    for (std::uint32_t x = 0; x < 4; ++x) {
      const bool red = ((x + y) & 1u) == 0;
      t.rgba.insert(t.rgba.end(),
                    {static_cast<std::uint8_t>(red ? 255 : 0), static_cast<std::uint8_t>(red ? 0 : 255), 0, 255});
    }
  }
  t.sampling.magnify = t.sampling.minify = TextureFilter::nearest;
  t.sampling.mipmapped = false;
  return t;
}

struct LightCase {
  const char* name;
  LocalLight light;
  bool globe = false;
};

void PrintTo(const LightCase& c, std::ostream* os) { *os << c.name; }

// Lights in front of the default camera (at (0, 7, 22), looking towards -z over the boxes).
LocalLight point_light(glm::vec3 position, float range) {
  LocalLight l;
  l.type = LocalLightType::point;
  l.position = position;
  l.color = {1.0f, 0.6f, 0.3f};
  l.intensity = 40.0f;
  l.range = range;
  return l;
}

LocalLight spot_light() {
  LocalLight l;
  l.type = LocalLightType::spot;
  l.position = {0.0f, 6.0f, 8.0f};
  l.direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.3f));
  l.color = {0.4f, 0.7f, 1.0f};
  l.intensity = 60.0f;
  l.range = 12.0f;
  l.inner_cone_cos = std::cos(glm::radians(20.0f));
  l.outer_cone_cos = std::cos(glm::radians(35.0f));
  return l;
}

LocalLight box_light(bool back) {
  LocalLight l;
  l.type = LocalLightType::box;
  l.position = {0.0f, 1.0f, 6.0f};
  l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
  l.color = {0.8f, 1.0f, 0.5f};
  l.intensity = 1.5f;
  l.box_half_extent = {4.0f, 3.0f, 3.0f};
  l.box_falloff = 1.0f;
  if (back) l.extras.back_color = glm::vec3(0.2f, 0.1f, 0.9f);
  return l;
}

const LightCase kLightCases[] = {
    {"point", point_light({0.0f, 2.0f, 8.0f}, 8.0f)},
    {"point_globe", point_light({0.0f, 2.0f, 8.0f}, 8.0f), true},
    {"point_around_camera", point_light({0.0f, 7.0f, 20.0f}, 14.0f)},
    {"spot", spot_light()},
    {"spot_globe", spot_light(), true},
    {"box", box_light(false)},
    {"box_back_colour", box_light(true)},
    {"box_back_colour_globe", box_light(true), true},
};

Scene scene_with(const LightCase& c) {
  Scene scene = make_demo_scene();
  LocalLight light = c.light;
  if (c.globe) {
    scene.textures.push_back(checker_texture());
    light.extras.globe_texture = static_cast<std::uint32_t>(scene.textures.size() - 1);
  }
  scene.local_lights.push_back(light);
  return scene;
}

RendererOptions small_options(std::uint32_t msaa) {
  RendererOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.msaa = msaa;
  return options;
}

// The world position of a pixel's sample as the shaders reconstruct it (world_position.glsl).
glm::vec3 world_position(const LightingParamsBlock& params, std::uint32_t x, std::uint32_t y, float depth) {
  const glm::vec2 ndc = (glm::vec2(static_cast<float>(x), static_cast<float>(y)) + 0.5f) *
                            glm::vec2(params.viewport.z, params.viewport.w) * 2.0f -
                        1.0f;
  const glm::vec4 world = params.inv_view_proj * glm::vec4(ndc, depth, 1.0f);
  return glm::vec3(world) / world.w;
}

// Whether some sample of the pixel may lie in the light's volume (with a margin for the CPU's
// rounding): false means the light must add exactly nothing there.
bool may_be_lit(const LocalLight& light, glm::vec3 p) {
  constexpr float kMargin = 1.01f;
  if (light.type == LocalLightType::box) {
    return glm::length(p - light.position) <= glm::length(light.box_half_extent) * kMargin;
  }
  return glm::length(p - light.position) <= light.range * kMargin;
}

struct PixelCounts {
  std::uint32_t sky_changed = 0, beyond_changed = 0, lit = 0;
  std::string first_wrong;
};

PixelCounts compare_unlit_and_lit(const LocalLight& light, const GBufferSamples& g, const LightingParamsBlock& params,
                                  const RgbaImage& unlit, const RgbaImage& lit) {
  PixelCounts counts;
  for (std::uint32_t y = 0; y < g.height; ++y) {
    for (std::uint32_t x = 0; x < g.width; ++x) {
      bool all_sky = true, any_in_range = false;
      for (std::uint32_t s = 0; s < g.samples; ++s) {
        const float depth = g.at(x, y, s)[12];
        if (depth == 1.0f) continue;
        all_sky = false;
        any_in_range = any_in_range || may_be_lit(light, world_position(params, x, y, depth));
      }
      const bool changed = unlit.at(x, y) != lit.at(x, y);
      counts.lit += changed ? 1 : 0;
      const bool wrong = changed && (all_sky || !any_in_range);
      if (changed && all_sky) ++counts.sky_changed;
      if (changed && !all_sky && !any_in_range) ++counts.beyond_changed;
      if (wrong && counts.first_wrong.empty()) counts.first_wrong = std::to_string(x) + ", " + std::to_string(y);
    }
  }
  return counts;
}

using FrameCase = std::tuple<LightCase, std::uint32_t>;  // light, MSAA

class LocalLightFrame : public VulkanTest, public ::testing::WithParamInterface<FrameCase> {};

TEST_P(LocalLightFrame, LightsItsRangeOnlyAndEveryTargetAlike) {
  const auto& [c, msaa] = GetParam();
  const Scene unlit_scene = make_demo_scene();
  const Scene lit_scene = scene_with(c);
  TileRenderer unlit(context(), unlit_scene, small_options(msaa));
  unlit.render_frame();
  const RgbaImage unlit_image = unlit.read_classified();

  TileRenderer renderer(context(), lit_scene, small_options(msaa));
  const FrameResult result = render_equivalent_frame(renderer);  // classified == naive == dynamic
  EXPECT_GT(result.timings.local_lights, 0.0);
  const RgbaImage lit_image = renderer.read_classified();
  const GBufferSamples g = TileRendererTestSeam::read_gbuffer(renderer);
  const PixelCounts counts =
      compare_unlit_and_lit(c.light, g, TileRendererTestSeam::lighting_params(renderer), unlit_image, lit_image);
  EXPECT_EQ(counts.sky_changed, 0u) << "first: " << counts.first_wrong;
  EXPECT_EQ(counts.beyond_changed, 0u) << "first: " << counts.first_wrong;
  EXPECT_GT(counts.lit, 20u) << "the light lit (almost) nothing";
}

std::string frame_case_name(const ::testing::TestParamInfo<FrameCase>& info) {
  return std::string(std::get<0>(info.param).name) + "_msaa" + std::to_string(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(Lights, LocalLightFrame,
                         ::testing::Combine(::testing::ValuesIn(kLightCases), ::testing::Values(4u, 1u)),
                         frame_case_name);

// Many lights of every kind at once, with the raster light pass too: still classified == naive.
class LocalLightsEquivalence : public VulkanTest, public ::testing::WithParamInterface<LightPass> {};

TEST_P(LocalLightsEquivalence, ClassifiedEqualsNaiveWithLightsOn) {
  Scene scene = make_demo_scene();
  for (const LightCase& c : kLightCases) {
    if (!c.globe) scene.local_lights.push_back(c.light);
  }
  RendererOptions options = small_options(0);
  options.light_pass = GetParam();
  TileRenderer renderer(context(), scene, options);
  render_equivalent_frame(renderer);
  render_equivalent_frame(renderer);  // the pre-recorded passes again
}

INSTANTIATE_TEST_SUITE_P(Passes, LocalLightsEquivalence, ::testing::Values(LightPass::compute, LightPass::raster),
                         [](const ::testing::TestParamInfo<LightPass>& pass) {
                           return std::string(to_string(pass.param));
                         });

// ---------------------------------------------------------------------------------------------
// The volume pass (the default) against the full-screen reference: the same final light
// targets, bit for bit, for every light, at 4x and 1x.

struct VolumeCase {
  const char* name;
  LightCase light;
  std::optional<Camera> camera;  // empty: the default camera
};

void PrintTo(const VolumeCase& c, std::ostream* os) { *os << c.name; }

// The default camera with its far plane at 18 m: the point light 16 m ahead reaches 24 m, so its
// volume crosses the far plane (depth clamp, or no depth test for it).
Camera short_sighted_camera() {
  Camera camera = make_demo_scene().camera("default");
  camera.far_plane = 18.0f;
  return camera;
}

std::vector<VolumeCase> volume_cases() {
  std::vector<VolumeCase> cases;
  for (const LightCase& c : kLightCases) cases.push_back({c.name, c, std::nullopt});
  cases.push_back({"point_beyond_far_plane", {"point", point_light({0.0f, 2.0f, 6.0f}, 8.0f)}, short_sighted_camera()});
  return cases;
}

using VolumeFrameCase = std::tuple<VolumeCase, std::uint32_t>;  // case, MSAA

class LocalLightVolumes : public VulkanTest, public ::testing::WithParamInterface<VolumeFrameCase> {};

TEST_P(LocalLightVolumes, EqualTheFullScreenReferencePerPixel) {
  const auto& [c, msaa] = GetParam();
  const Scene scene = scene_with(c.light);
  RendererOptions options = small_options(msaa);
  options.camera_pose = c.camera;
  (void)expect_volumes_equal_full_screen(context(), scene, options);
}

std::string volume_case_name(const ::testing::TestParamInfo<VolumeFrameCase>& info) {
  return std::string(std::get<0>(info.param).name) + "_msaa" + std::to_string(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(Lights, LocalLightVolumes,
                         ::testing::Combine(::testing::ValuesIn(volume_cases()), ::testing::Values(4u, 1u)),
                         volume_case_name);

}  // namespace
}  // namespace tilelight::test
