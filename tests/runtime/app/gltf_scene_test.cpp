// Real glTF 2.0 models (Debian's assimp-testmodels) through the whole frame: classified ==
// naive and dynamic == naive per pixel under the validation layer, on both index paths, with
// and without MSAA, as points and as triangle pairs, optimised and raw permutations, tile sizes
// 4 and 8, coalesced and not, raster and compute light passes, every tile drawn once.
#include "frame_support.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include <split_second_shaders.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>

namespace tilelight::test {
namespace {

const std::filesystem::path kModels = TILELIGHT_ASSIMP_GLTF2_MODELS;
const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;

struct GltfCase {
  const char* name;
  const char* file;  // under kModels
  IndexPath path;
  std::uint32_t msaa;  // 0: auto (4x on lavapipe)
  std::optional<TilePrimitive> primitive = std::nullopt;
  bool raw = false;  // the 96 raw permutations instead of the 32 optimised ones
  std::uint32_t tile_size = 4;
  bool coalesce = true;
  LightPass light_pass = LightPass::raster;
};

void PrintTo(const GltfCase& c, std::ostream* os) { *os << c.name; }

std::string case_name(const ::testing::TestParamInfo<GltfCase>& info) { return info.param.name; }

class GltfFrames : public VulkanTest, public ::testing::WithParamInterface<GltfCase> {};

TEST_P(GltfFrames, ClassifiedEqualsNaivePerPixel) {
  const GltfCase& c = GetParam();
  ASSERT_TRUE(std::filesystem::is_directory(kModels))
      << kModels << " is missing: install Debian's assimp-testmodels (scripts/install-deps.sh --tests)";
  const Scene scene = load_gltf_scene(kModels / c.file);
  RendererOptions options;
  options.width = 256;
  options.height = 192;
  options.path = c.path;
  options.msaa = c.msaa;
  options.primitive = c.primitive;
  options.raw_permutations = c.raw;
  options.tile_size = c.tile_size;
  options.coalesce = c.coalesce;
  options.light_pass = c.light_pass;
  TileRenderer renderer(context(), scene, options);
  render_equivalent_frame(renderer);

  // The camera frames the model: it covers part of the frame, and the sky the rest.
  const std::vector<std::uint8_t> ids = renderer.raw_tile_ids();
  const auto sky = std::count_if(ids.begin(), ids.end(),
                                 [](std::uint8_t id) { return (id & split_second::raw_bit::SKY.value()) != 0; });
  const auto lit = std::count_if(ids.begin(), ids.end(),
                                 [](std::uint8_t id) { return (id & split_second::raw_bit::SUN_LIGHT.value()) != 0; });
  EXPECT_GT(sky, 0);
  EXPECT_LT(sky, static_cast<std::ptrdiff_t>(ids.size()) * 9 / 10) << "the model covers under a tenth of the frame";
  EXPECT_GT(lit, 0) << "no tile faces the sun";
  if (renderer.msaa_samples() == 1) {
    EXPECT_TRUE(std::none_of(ids.begin(), ids.end(),
                             [](std::uint8_t id) { return (id & split_second::raw_bit::MSAA_EDGE.value()) != 0; }));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, GltfFrames,
    ::testing::Values(
        // 121,496 triangles in 115 nodes: shadows cast by the model on itself.
        GltfCase{"engine_glb_cpu", "2CylinderEngine-glTF-Binary/2CylinderEngine.glb", IndexPath::cpu, 0},
        GltfCase{"engine_glb_gpu_no_msaa", "2CylinderEngine-glTF-Binary/2CylinderEngine.glb", IndexPath::gpu, 1},
        // 27 meshes of spheres and boxes.
        GltfCase{"clearcoat_gpu", "ClearCoat-glTF/ClearCoatTest.gltf", IndexPath::gpu, 0},
        GltfCase{"engine_glb_raw_tile8_uncoalesced", "2CylinderEngine-glTF-Binary/2CylinderEngine.glb", IndexPath::cpu,
                 0, std::nullopt, true, 8, false},
        GltfCase{"engine_glb_compute_light_pass", "2CylinderEngine-glTF-Binary/2CylinderEngine.glb", IndexPath::gpu, 0,
                 std::nullopt, false, 4, true, LightPass::compute},
        GltfCase{"box_textured_embedded_cpu_triangles", "BoxTextured-glTF-Embedded/BoxTextured.gltf", IndexPath::cpu, 0,
                 TilePrimitive::triangles},
        // KHR_texture_transform's test plates, and a spec-gloss box (its diffuse texture).
        GltfCase{"texture_transform_gpu", "textureTransform/TextureTransformTest.gltf", IndexPath::gpu, 0},
        GltfCase{"spec_gloss_box_cpu", "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", IndexPath::cpu, 0},
        // The engine again, its 34 primitives KHR_draco_mesh_compression streams (65,311 triangles).
        GltfCase{"engine_draco_gpu", "draco/2CylinderEngine.gltf", IndexPath::gpu, 0}),
    case_name);

// The textured quad of tests/fixtures/gltf: a 2x2 texture (red, green / blue, white) read
// with nearest filtering. Every G-buffer sample the quad covers stores one of the four texel
// colours as its albedo (sRGB 255 decoded to exactly 1.0; the factor is white), all four
// appear, and the image's top-left texel (uv 0,0) lands at the quad's top left on screen.
class GltfTexturedFrame : public VulkanTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(GltfTexturedFrame, EveryCoveredSampleStoresATexelOfTheBaseColourTexture) {
  const Scene scene = load_gltf_scene(kFixtures / GetParam());
  RendererOptions options;
  options.light_pass = LightPass::raster;
  options.width = 256;
  options.height = 192;
  options.msaa = 4;
  TileRenderer renderer(context(), scene, options);
  (void)renderer.render_frame();
  const FrameComparison classified = compare(renderer.read_classified(), renderer.read_naive(), kEquivalenceTolerance);
  EXPECT_EQ(classified.pixels_over_tolerance, 0u) << classified.first_difference;

  const GBufferSamples g = TileRendererTestSeam::read_gbuffer(renderer);
  const std::array<glm::vec3, 4> texels{glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(1)};
  std::array<std::size_t, 4> count{};
  std::array<glm::dvec2, 4> centroid{};
  std::size_t other = 0;
  for (std::uint32_t y = 0; y < g.height; ++y) {
    for (std::uint32_t x = 0; x < g.width; ++x) {
      for (std::uint32_t s = 0; s < g.samples; ++s) {
        const float* sample = g.at(x, y, s);
        const auto motion_byte = static_cast<unsigned>(std::lround(sample[7] * 255.0f));
        if ((motion_byte & 0x7Fu) == 0) continue;  // sky
        const glm::vec3 albedo(sample[0], sample[1], sample[2]);
        const auto texel = std::find(texels.begin(), texels.end(), albedo);
        if (texel == texels.end()) {
          ++other;
          continue;
        }
        const auto k = static_cast<std::size_t>(texel - texels.begin());
        ++count[k];
        centroid[k] += glm::dvec2(x, y);
      }
    }
  }
  EXPECT_EQ(other, 0u) << "samples whose albedo is no texel of the texture";
  for (std::size_t k = 0; k < 4; ++k) {
    ASSERT_GT(count[k], 100u) << "texel " << k << " is (almost) nowhere in the frame";
    centroid[k] /= static_cast<double>(count[k]);
  }
  // Red (top left of the image) above blue (bottom left), left of green (top right).
  EXPECT_LT(centroid[0].y, centroid[2].y);
  EXPECT_LT(centroid[0].x, centroid[1].x);
}

INSTANTIATE_TEST_SUITE_P(Fixtures, GltfTexturedFrame,
                         ::testing::Values("textured_quad.glb", "textured_quad_texcoord1.gltf",
                                           "textured_quad_quantized.gltf", "textured_quad_quantized_bytes.gltf"));

// The geometry real files use (sparse accessors, KHR_mesh_quantization,
// EXT_meshopt_compression, KHR_draco_mesh_compression) through the whole frame: classified ==
// naive and dynamic == naive, every tile drawn once, under validation.
class GltfGeometryFrame : public VulkanTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(GltfGeometryFrame, ClassifiedEqualsNaivePerPixel) {
  const Scene scene = load_gltf_scene(kFixtures / GetParam());
  RendererOptions options;
  options.width = 128;
  options.height = 96;
  TileRenderer renderer(context(), scene, options);
  render_equivalent_frame(renderer);
  const std::vector<std::uint8_t> ids = renderer.raw_tile_ids();
  EXPECT_TRUE(std::any_of(ids.begin(), ids.end(), [](std::uint8_t id) {
    return (id & split_second::raw_bit::SKY.value()) == 0;
  })) << "the model covers no tile";
}

INSTANTIATE_TEST_SUITE_P(Fixtures, GltfGeometryFrame,
                         ::testing::Values("box_sparse.gltf", "textured_quad_quantized.gltf", "box_meshopt.gltf",
                                           "box_draco.gltf"));

}  // namespace
}  // namespace tilelight::test
