// The forward pass for alpha-blended materials (issue 38 item 5; docs/local-lights.md, "Forward
// pass for blended materials"): golden-image checks on a file the test builds (gltf_builder.h),
// on lavapipe under the validation layer (any message fails), at 4x and 1x MSAA (compute light
// pass) and 4x with the raster light pass.
//
// The scene, in the file's coordinates, seen straight down the z axis: an opaque green wall at
// z = -1 (4 x 4), an opaque white blocker at z = 0.8 over x 1.1..1.9, y -0.5..0.5, and two
// blended quads: A, red, alpha 0.6, at z = 0 over x -1.8..0.5; B, blue, alpha 0.5, at z = 0.3
// (nearer) over x -0.5..1.5, so that B is partly behind the blocker and A and B overlap over
// x -0.5..0.5. Every render has the same bounds (the wall and blocker), so the loader frames
// them alike. Pixels are read from the classified light target (RGBA16F, read as float).
//
// What it asserts:
//  1. Behind one glass the pixel is the documented blend, glass * alpha + background *
//     (1 - alpha), where "glass" is the same quad's colour drawn OPAQUE by the deferred passes
//     (the shading library's other technique) and "background" the render without the glasses:
//     within 0.01 + 1% (16-bit float targets; the G-buffer stores the albedo and specular amount
//     in 8 bits and the prelit colour in 16-bit floats, the forward shader uses them unrounded).
//  2. Where A and B overlap the pixel is B over (A over background), the back-to-front result,
//     within the same tolerance, and not the front-to-back one; the file written in the other
//     order (B before A) gives the same image, bit for bit.
//  3. Where the blocker lies in front of B the pixel equals the render without glasses exactly.
//  4. classified == naive == dynamic per pixel with the blended quads present (and with a local light).
//  5. A point light in front of A brightens it: with the light, A's pixel is again the blend of the
//     opaque A and the background, both lit by the light, and brighter than without it: the light
//     (one of the K chosen on the CPU) reaches the forward shader.
//  6. With a thin opaque caster between that light and A (its shadow on A away from where the
//     camera sees the caster), a pixel of A in the shadow is again that blend, where the opaque A
//     is darker there than without the caster: the light's shadow map reaches the forward shader
//     (LOCAL_SHADOWS), read as the deferred local-light pass reads it.
// And tilelight's report.json: `forward` counts the blended instances (and K), timings_ms.forward
// is the pass's time, present (0) without blended materials.
#include "frame_support.h"
#include "gltf_builder.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight_testing/test_support.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tilelight::test {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace forward_pass_test {
namespace {

constexpr std::uint32_t kWidth = 128, kHeight = 96;
constexpr float kAlphaA = 0.6f, kAlphaB = 0.5f;

// Which quads a render has, and how A and B are drawn.
enum class Glass { none, opaque_a, opaque_b, blended, blended_reversed };

std::string material(glm::vec3 colour, float alpha, bool blended) {
  return fmt::format(R"("alphaMode": "{}", "doubleSided": true, "pbrMetallicRoughness": {{"baseColorFactor":
      [{}, {}, {}, {}]}})",
                     blended ? "BLEND" : "OPAQUE", colour.r, colour.g, colour.b, blended ? alpha : 1.0f);
}

// A's pixel in the caster's shadow (test 6): the light at x -1.2, z 0.6 and the caster at z 0.5
// over x -1.3..-1.25 throw its shadow on A (z 0) over x -1.8..-1.5.
constexpr glm::vec3 kInCastersShadow{-1.65f, 0.2f, 0};

Scene build_scene(Glass glass, bool with_light, bool with_caster = false) {
  GltfBuilder file;
  file.add_quad({-2, -2}, {2, 2}, -1, file.add_material(material({0, 1, 0}, 1, false)));
  if (with_caster)
    file.add_quad({-1.3f, -0.1f}, {-1.25f, 0.1f}, 0.5f, file.add_material(material({1, 1, 1}, 1, false)));
  file.add_quad({1.1f, -0.5f}, {1.9f, 0.5f}, 0.8f, file.add_material(material({1, 1, 1}, 1, false)));
  const auto add_a = [&](bool blended) {
    file.add_quad({-1.8f, -1}, {0.5f, 1}, 0, file.add_material(material({1, 0, 0}, kAlphaA, blended)));
  };
  const auto add_b = [&](bool blended) {
    file.add_quad({-0.5f, -1}, {1.5f, 1}, 0.3f, file.add_material(material({0, 0, 1}, kAlphaB, blended)));
  };
  switch (glass) {
    case Glass::none: break;
    case Glass::opaque_a: add_a(false); break;
    case Glass::opaque_b: add_b(false); break;
    case Glass::blended: add_a(true), add_b(true); break;
    case Glass::blended_reversed: add_b(true), add_a(true); break;
  }
  Scene scene = load_gltf_scene_from_memory(file.bytes(), "glass.gltf", {});
  Camera& camera = scene.cameras.at(0);
  camera.position = glm::vec3(0, 0, 40);
  camera.target = glm::vec3(0);
  camera.up = glm::vec3(0, 1, 0);
  camera.vertical_fov_degrees = 30.0f;
  if (with_light) {
    // In front of A's left part, reaching it and the wall behind it.
    const glm::mat4 fit = scene.world_from_file;
    LocalLight light;
    light.type = LocalLightType::point;
    light.position = glm::vec3(fit * glm::vec4(-1.2f, 0, 0.6f, 1));
    light.color = glm::vec3(1.0f);
    light.intensity = 4.0f;
    light.range = 3.0f * fit[0][0];  // 3 file units
    scene.local_lights.push_back(light);
  }
  return scene;
}

// The pixel a point of the file lands on.
glm::uvec2 pixel_of(const Scene& scene, glm::vec3 file_point) {
  const glm::vec3 point = glm::vec3(scene.world_from_file * glm::vec4(file_point, 1));
  const glm::vec4 clip =
      camera_matrices(scene.cameras[0], float(kWidth) / float(kHeight)).view_proj * glm::vec4(point, 1);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return glm::uvec2((ndc * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight));
}

glm::vec3 rgb_at(const RgbaImage& image, glm::uvec2 pixel) {
  const std::array<float, 4> v = image.at(pixel.x, pixel.y);
  return {v[0], v[1], v[2]};
}

// Glass of colour `glass` and `alpha` over `background`: the pipeline's SRC_ALPHA,
// ONE_MINUS_SRC_ALPHA.
glm::vec3 over(glm::vec3 glass, float alpha, glm::vec3 background) { return glass * alpha + background * (1 - alpha); }

::testing::AssertionResult near(glm::vec3 got, glm::vec3 expected, const char* where) {
  for (int c = 0; c < 3; ++c) {
    if (!(std::fabs(got[c] - expected[c]) <= 0.01f + 0.01f * std::fabs(expected[c]))) {
      return ::testing::AssertionFailure() << fmt::format("{}: got ({}, {}, {}), expected ({}, {}, {})", where, got.r,
                                                          got.g, got.b, expected.r, expected.g, expected.b);
    }
  }
  return ::testing::AssertionSuccess();
}

struct FrameCase {
  std::uint32_t msaa;
  LightPass light_pass;
};

void PrintTo(const FrameCase& c, std::ostream* os) {
  *os << "msaa " << c.msaa << (c.light_pass == LightPass::compute ? ", compute" : ", raster");
}

class ForwardPassFrame : public VulkanTest, public ::testing::WithParamInterface<FrameCase> {
 protected:
  // The classified light target of one frame of `scene`; with the blended quads, also checks
  // that it equals the naive and dynamic targets per pixel.
  RgbaImage render(const Scene& scene, std::size_t expected_blended = 0) {
    RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.msaa = GetParam().msaa;
    options.light_pass = GetParam().light_pass;
    TileRenderer renderer(context(), scene, options);
    (void)renderer.render_frame();
    EXPECT_EQ(renderer.forward_instances(), expected_blended);
    expect_classified_and_dynamic_equal_naive(renderer);
    return renderer.read_classified();
  }
};

TEST_P(ForwardPassFrame, BlendsBackToFrontOverTheOpaqueScene) {
  const Scene blended = build_scene(Glass::blended, false);
  const RgbaImage background = render(build_scene(Glass::none, false));
  const RgbaImage lit_a = render(build_scene(Glass::opaque_a, false));
  const RgbaImage lit_b = render(build_scene(Glass::opaque_b, false));
  const RgbaImage glass = render(blended, 2);
  const RgbaImage reversed = render(build_scene(Glass::blended_reversed, false), 2);

  // 1. One glass over the wall (drawn opaque, each quad shows, red or blue, not the wall).
  const glm::uvec2 only_a = pixel_of(blended, {-1.2f, 0.2f, 0}), only_b = pixel_of(blended, {0.9f, 0.2f, 0});
  ASSERT_GT(rgb_at(lit_a, only_a).r, rgb_at(lit_a, only_a).g) << "the opaque A is drawn";
  ASSERT_GT(rgb_at(lit_b, only_b).b, rgb_at(lit_b, only_b).g) << "the opaque B is drawn";
  ASSERT_GT(rgb_at(background, only_a).g, rgb_at(background, only_a).r) << "the wall is behind A";
  EXPECT_TRUE(near(rgb_at(glass, only_a), over(rgb_at(lit_a, only_a), kAlphaA, rgb_at(background, only_a)), "A"));
  EXPECT_TRUE(near(rgb_at(glass, only_b), over(rgb_at(lit_b, only_b), kAlphaB, rgb_at(background, only_b)), "B"));

  // 2. B (nearer) over A over the wall, whatever the file's order.
  const glm::uvec2 both = pixel_of(blended, {0, 0.2f, 0});
  const glm::vec3 a = rgb_at(lit_a, both), b = rgb_at(lit_b, both), wall = rgb_at(background, both);
  const glm::vec3 back_to_front = over(b, kAlphaB, over(a, kAlphaA, wall));
  const glm::vec3 front_to_back = over(a, kAlphaA, over(b, kAlphaB, wall));
  EXPECT_TRUE(near(rgb_at(glass, both), back_to_front, "A and B"));
  EXPECT_FALSE(near(rgb_at(glass, both), front_to_back, "A and B, the wrong order"));
  EXPECT_GT(rgb_at(glass, both).b, rgb_at(glass, both).r) << "the nearer (blue) quad dominates";
  EXPECT_EQ(reversed.pixels, glass.pixels) << "the file's order changes nothing";

  // 3. The blocker in front of B: exactly the opaque render, over a 3 x 3 neighbourhood.
  const glm::uvec2 blocked = pixel_of(blended, {1.3f, 0, 0});
  for (std::uint32_t y = blocked.y - 1; y <= blocked.y + 1; ++y) {
    for (std::uint32_t x = blocked.x - 1; x <= blocked.x + 1; ++x) {
      EXPECT_EQ(glass.at(x, y), background.at(x, y)) << "pixel (" << x << ", " << y << ")";
    }
  }
}

TEST_P(ForwardPassFrame, ALocalLightReachesTheGlass) {
  const Scene blended = build_scene(Glass::blended, true);
  const RgbaImage background = render(build_scene(Glass::none, true));
  const RgbaImage lit_a = render(build_scene(Glass::opaque_a, true));
  const RgbaImage glass = render(blended, 2);
  const RgbaImage unlit_glass = render(build_scene(Glass::blended, false), 2);

  const glm::uvec2 only_a = pixel_of(blended, {-1.2f, 0.2f, 0});
  EXPECT_TRUE(near(rgb_at(glass, only_a), over(rgb_at(lit_a, only_a), kAlphaA, rgb_at(background, only_a)), "A, lit"));
  EXPECT_GT(rgb_at(glass, only_a).r, rgb_at(unlit_glass, only_a).r + 0.05f) << "the light brightens the glass";
}

TEST_P(ForwardPassFrame, ALocalLightsShadowFallsOnTheGlass) {
  const Scene blended = build_scene(Glass::blended, true, true);
  const RgbaImage background = render(build_scene(Glass::none, true, true));
  const RgbaImage lit_a = render(build_scene(Glass::opaque_a, true, true));
  const RgbaImage lit_a_uncast = render(build_scene(Glass::opaque_a, true, false));
  const RgbaImage glass = render(blended, 2);

  const glm::uvec2 shadowed = pixel_of(blended, kInCastersShadow);
  ASSERT_LT(rgb_at(lit_a, shadowed).r + 0.05f, rgb_at(lit_a_uncast, shadowed).r)
      << "the caster shadows the opaque A there (the deferred local-light pass)";
  EXPECT_TRUE(near(rgb_at(glass, shadowed), over(rgb_at(lit_a, shadowed), kAlphaA, rgb_at(background, shadowed)),
                   "A, in the caster's shadow"));
}

// report.json of one tilelight run on `scene_args` (none: the procedural scene), written to `out`.
nlohmann::json report_of(const std::filesystem::path& out, std::vector<std::string> scene_args) {
  std::vector<std::string> args{"--width", "64",           "--height", "48",        "--frames",
                                "1",       "--validation", "--out",    out.string()};
  args.insert(args.end(), scene_args.begin(), scene_args.end());
  const CliResult r = run_cli(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::ifstream file(out / "report.json");
  return nlohmann::json::parse(file);
}

TEST(ForwardPassCli, TheReportCountsTheBlendedInstancesAndTimesThePass) {
  GltfBuilder file;
  file.add_quad({-2, -2}, {2, 2}, -1, file.add_material(material({0, 1, 0}, 1, false)));
  file.add_quad({-1, -1}, {1, 1}, 0, file.add_material(material({1, 0, 0}, 0.5f, true)));
  const std::filesystem::path dir = scratch_dir();  // emptied by each call
  const std::filesystem::path path = dir / "glass.gltf";
  std::ofstream(path) << file.json();
  const nlohmann::json report = report_of(dir / "with_glass", {"--scene", path.string()});
  EXPECT_EQ(report["forward"], nlohmann::json({{"instances", 1}, {"max_lights", 8}}));
  EXPECT_GT(report["timings_ms"]["forward"].get<double>(), 0.0);
  EXPECT_EQ(report["equivalence"]["pixels_different"], 0) << report["equivalence"];

  const nlohmann::json none = report_of(dir / "procedural", {});
  EXPECT_EQ(none["forward"]["instances"], 0);
  EXPECT_EQ(none["timings_ms"]["forward"].get<double>(), 0.0);
}

std::string case_name(const ::testing::TestParamInfo<FrameCase>& param_info) {
  return fmt::format("msaa{}_{}", param_info.param.msaa,
                     param_info.param.light_pass == LightPass::compute ? "compute" : "raster");
}

INSTANTIATE_TEST_SUITE_P(Modes, ForwardPassFrame,
                         ::testing::Values(FrameCase{4, LightPass::compute}, FrameCase{1, LightPass::compute},
                                           FrameCase{4, LightPass::raster}),
                         case_name);

}  // namespace
}  // namespace forward_pass_test
}  // namespace tilelight::test
