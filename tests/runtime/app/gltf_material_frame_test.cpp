// glTF materials through the whole frame, on files the tests build (tests/runtime/gltf/gltf_builder.h):
// an alpha-masked quad in front of a green wall, whose masked half shows the wall in the G-buffer
// and lets the sun through in the shadow map, and single- and double-sided quads seen from
// behind. Every frame: classified == naive and dynamic == naive per pixel, bit-exact, under the
// validation layer (any message fails), and the plain G-buffer equal to the classified one.
#include "frame_support.h"
#include "gltf_builder.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include <fmt/format.h>

#include <glm/gtc/matrix_transform.hpp>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace tilelight::test {
namespace {

constexpr std::uint32_t kWidth = 192, kHeight = 144;

// A green wall (double-sided, 4 x 4) at z = -1 behind `front`'s quads, the camera straight down
// the z axis onto both.
Scene scene_with_wall(GltfBuilder& front) {
  front.add_quad(
      {-2, -2}, {2, 2}, -1,
      front.add_material(R"("doubleSided": true, "pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 1]})"));
  Scene scene = load_gltf_scene_from_memory(front.bytes(), "materials.gltf", {});
  Camera& camera = scene.cameras.at(0);
  camera.position = glm::vec3(0, 0, 40);
  camera.target = glm::vec3(0);
  camera.up = glm::vec3(0, 1, 0);
  camera.vertical_fov_degrees = 40.0f;
  return scene;
}

// The world point of local (file) coordinates: every node of these files has the same transform,
// the loader's fit of the scene into 10 m.
glm::vec3 world(const Scene& scene, glm::vec3 local) {
  return glm::vec3(scene.instances.at(0).model * glm::vec4(local, 1));
}

// The pixel (x, y) a world point lands on.
glm::uvec2 pixel_of(const Scene& scene, glm::vec3 point) {
  const glm::vec4 clip =
      camera_matrices(scene.cameras[0], float(kWidth) / float(kHeight)).view_proj * glm::vec4(point, 1);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return glm::uvec2((ndc * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight));
}

// Every sample of `pixel` stores `albedo` (RT0.rgb).
::testing::AssertionResult stores_albedo(const GBufferSamples& g, glm::uvec2 pixel, glm::vec3 albedo) {
  for (std::uint32_t s = 0; s < g.samples; ++s) {
    const float* v = g.at(pixel.x, pixel.y, s);
    if (glm::vec3(v[0], v[1], v[2]) != albedo) {
      return ::testing::AssertionFailure() << fmt::format("pixel ({}, {}) sample {} stores albedo ({}, {}, {})",
                                                          pixel.x, pixel.y, s, v[0], v[1], v[2]);
    }
  }
  return ::testing::AssertionSuccess();
}

// The classified frame equals the naive one, and so does the dynamic; the plain G-buffer stores
// what the classified one does in RT0..RT3, bit for bit.
void expect_equivalent_frames(TileRenderer& renderer) {
  expect_classified_and_dynamic_equal_naive(renderer);
  const GBufferSamples flagged = TileRendererTestSeam::read_gbuffer(renderer, GBufferKind::classified);
  const GBufferSamples plain = TileRendererTestSeam::read_gbuffer(renderer, GBufferKind::plain);
  ASSERT_EQ(flagged.values.size(), plain.values.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < flagged.values.size(); ++i) {
    if (i % GBufferSamples::kFloatsPerSample >= 13) continue;  // RT0..RT3 only: 13 floats
    differing += std::bit_cast<std::uint32_t>(flagged.values[i]) != std::bit_cast<std::uint32_t>(plain.values[i]);
  }
  EXPECT_EQ(differing, 0u) << "plain and classified G-buffers differ";
}

// The coverage flags' invariant (uber/include/gbuffer.glsl): a pixel whose samples differ in
// RT0..RT3 has a flag on some sample. Counts the pixels that break it.
std::size_t unflagged_differing_pixels(const GBufferSamples& g) {
  std::size_t unflagged = 0;
  for (std::uint32_t y = 0; y < g.height; ++y) {
    for (std::uint32_t x = 0; x < g.width; ++x) {
      bool differ = false, flagged = false;
      for (std::uint32_t s = 0; s < g.samples; ++s) {
        flagged = flagged || g.at(x, y, s)[13] != 0.0f;
        for (std::size_t i = 0; i < 13; ++i) {
          differ = differ ||
                   std::bit_cast<std::uint32_t>(g.at(x, y, s)[i]) != std::bit_cast<std::uint32_t>(g.at(x, y, 0)[i]);
        }
      }
      unflagged += differ && !flagged;
    }
  }
  return unflagged;
}

// Pixels where some samples store `a` as albedo and others `b`.
std::size_t pixels_mixing(const GBufferSamples& g, glm::vec3 a, glm::vec3 b) {
  std::size_t mixed = 0;
  for (std::uint32_t y = 0; y < g.height; ++y) {
    for (std::uint32_t x = 0; x < g.width; ++x) {
      bool has_a = false, has_b = false;
      for (std::uint32_t s = 0; s < g.samples; ++s) {
        const float* v = g.at(x, y, s);
        has_a = has_a || glm::vec3(v[0], v[1], v[2]) == a;
        has_b = has_b || glm::vec3(v[0], v[1], v[2]) == b;
      }
      mixed += has_a && has_b;
    }
  }
  return mixed;
}

struct MaskCase {
  const char* name;
  std::uint32_t msaa;
  LightPass light_pass;
  IndexPath path;
};

void PrintTo(const MaskCase& c, std::ostream* os) { *os << c.name; }

class GltfAlphaMask : public VulkanTest, public ::testing::WithParamInterface<MaskCase> {
 protected:
  static RendererOptions options() {
    RendererOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.msaa = GetParam().msaa;
    o.light_pass = GetParam().light_pass;
    o.path = GetParam().path;
    return o;
  }
};

// A 2 x 2 quad textured with a 2 x 1 image: its left texel red and opaque, its right one alpha 0.
TEST_P(GltfAlphaMask, TheMaskedHalfShowsWhatLiesBehindIt) {
  GltfBuilder file;
  const int texture = file.add_texture(2, 1, {255, 0, 0, 255, 255, 255, 255, 0});
  file.add_quad({-1, -1}, {1, 1}, 0,
                file.add_material(fmt::format(R"("alphaMode": "MASK", "pbrMetallicRoughness": {{"baseColorTexture":
                    {{"index": {}}}}})",
                                              texture)));
  const Scene scene = scene_with_wall(file);
  TileRenderer renderer(context(), scene, options());
  (void)renderer.render_frame();
  expect_equivalent_frames(renderer);

  const glm::vec3 kept = world(scene, {-0.5f, 0, 0}), hole = world(scene, {0.5f, 0, 0});
  const GBufferSamples g = TileRendererTestSeam::read_gbuffer(renderer);
  EXPECT_TRUE(stores_albedo(g, pixel_of(scene, kept), glm::vec3(1, 0, 0))) << "the opaque half shows the quad";
  EXPECT_TRUE(stores_albedo(g, pixel_of(scene, hole), glm::vec3(0, 1, 0))) << "the masked half shows the wall";
  if (renderer.msaa_samples() > 1) {
    EXPECT_EQ(unflagged_differing_pixels(g), 0u);
  }

  // The sun sees the quad's opaque half, and through its masked half something farther.
  const std::vector<float> shadow = TileRendererTestSeam::read_shadow_map(renderer);
  const std::uint32_t size = scene.sun.shadow_map_size;
  ASSERT_EQ(shadow.size(), std::size_t{size} * size);
  const glm::mat4 sun = sun_view_proj(scene.sun, scene.cameras[0]);
  const auto stored_and_own_depth = [&](glm::vec3 point) {
    const glm::vec3 ndc = glm::vec3(sun * glm::vec4(point, 1));
    const glm::uvec2 texel((glm::vec2(ndc) * 0.5f + 0.5f) * float(size));
    return std::pair(shadow.at(std::size_t{texel.y} * size + texel.x), ndc.z);
  };
  const auto [kept_stored, kept_depth] = stored_and_own_depth(kept);
  const auto [hole_stored, hole_depth] = stored_and_own_depth(hole);
  // The stored depth carries the shadow map's bias (constant and slope: the quad is steep to the sun).
  EXPECT_GE(kept_stored, kept_depth) << "the opaque half casts its shadow";
  EXPECT_LT(kept_stored, kept_depth + 0.02f) << "the opaque half casts its shadow";
  EXPECT_GT(hole_stored, hole_depth + 0.05f) << "the masked half lets the sun through";
}

// A masked quad (2 x 2 texels, the bottom right one alpha 0) turned 30 degrees about y through the
// wall: along the line where they meet, masked fragments cover every sample of a pixel but win only
// some in the depth test (no post-depth coverage tells them), the case the masked coverage flags
// exist for (gbuffer_encode_masked_flags()).
TEST_P(GltfAlphaMask, AMaskPiercingTheWallLeavesNoDifferingPixelUnflagged) {
  GltfBuilder file;
  const int texture = file.add_texture(2, 2, {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 255, 255, 0});
  const glm::mat4 node =
      glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -1)), glm::radians(30.0f), glm::vec3(0, 1, 0));
  file.add_quad({-1, -1}, {1, 1}, 0,
                file.add_material(fmt::format(R"("alphaMode": "MASK", "doubleSided": true, "pbrMetallicRoughness":
                    {{"baseColorTexture": {{"index": {}}}}})",
                                              texture)),
                false, node);
  const Scene scene = scene_with_wall(file);
  TileRenderer renderer(context(), scene, options());
  (void)renderer.render_frame();
  expect_equivalent_frames(renderer);
  if (renderer.msaa_samples() == 1) return;
  const GBufferSamples g = TileRendererTestSeam::read_gbuffer(renderer);
  EXPECT_GT(pixels_mixing(g, glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)), 20u) << "the quad does not pierce the wall";
  EXPECT_EQ(unflagged_differing_pixels(g), 0u);
}

std::string mask_case_name(const ::testing::TestParamInfo<MaskCase>& param_info) { return param_info.param.name; }

INSTANTIATE_TEST_SUITE_P(Modes, GltfAlphaMask,
                         ::testing::Values(MaskCase{"msaa4_raster", 4, LightPass::raster, IndexPath::cpu},
                                           MaskCase{"msaa4_compute_gpu", 4, LightPass::compute, IndexPath::gpu},
                                           MaskCase{"msaa1_raster_gpu", 1, LightPass::raster, IndexPath::gpu},
                                           MaskCase{"msaa1_compute", 1, LightPass::compute, IndexPath::cpu}),
                         mask_case_name);

class GltfDoubleSided : public VulkanTest, public ::testing::WithParamInterface<bool> {};

// A red quad facing away from the camera, in front of the wall: culled when single-sided; drawn
// when double-sided, with its normal flipped to face the camera (glTF: back faces are lit as
// front faces).
TEST_P(GltfDoubleSided, ABackFaceIsCulledOnlyOnASingleSidedMaterial) {
  const bool double_sided = GetParam();
  GltfBuilder file;
  file.add_quad({-1, -1}, {1, 1}, 0,
                file.add_material(fmt::format(R"("doubleSided": {}, "pbrMetallicRoughness": {{"baseColorFactor":
                    [1, 0, 0, 1]}})",
                                              double_sided)),
                true);
  const Scene scene = scene_with_wall(file);
  RendererOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.msaa = 4;
  TileRenderer renderer(context(), scene, options);
  (void)renderer.render_frame();
  expect_equivalent_frames(renderer);

  const GBufferSamples g = TileRendererTestSeam::read_gbuffer(renderer);
  const glm::uvec2 centre = pixel_of(scene, world(scene, {0, 0, 0}));
  EXPECT_TRUE(stores_albedo(g, centre, double_sided ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  EXPECT_GT(g.at(centre.x, centre.y, 0)[6], 0.99f) << "the stored normal faces the camera (+z)";
}

std::string sides_name(const ::testing::TestParamInfo<bool>& param_info) {
  return param_info.param ? "double_sided" : "single_sided";
}

INSTANTIATE_TEST_SUITE_P(Sides, GltfDoubleSided, ::testing::Bool(), sides_name);

// BLEND is drawn (the forward pass): nothing about it on stderr.
TEST(TilelightSceneWarnings, BlendIsNotWarnedAbout) {
  GltfBuilder builder;
  builder.add_quad({-1, -1}, {1, 1}, 0, builder.add_material(R"("alphaMode": "BLEND")"));
  const std::filesystem::path file = scratch_dir() / "blend.gltf";
  std::ofstream(file) << builder.json();
  const CliResult r = run_cli({"--scene", file.string(), "--list-cameras"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

}  // namespace
}  // namespace tilelight::test
