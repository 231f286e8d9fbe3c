// Real glTF 2.0 models (Debian's assimp-testmodels) through the whole frame: classified ==
// naive and dynamic == naive per pixel under the validation layer, on both index paths, with
// and without MSAA, as points and as triangle pairs, optimised and raw permutations, tile sizes
// 4 and 8, coalesced and not, raster and compute light passes, every tile drawn once.
#include "frame_support.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight_testing/test_support.h"

#include <split_second_shaders.h>

#include <algorithm>
#include <numeric>
#include <optional>

namespace tilelight::test {
namespace {

const std::filesystem::path kModels = TILELIGHT_ASSIMP_GLTF2_MODELS;

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
  const FrameResult frame = renderer.render_frame();

  const RgbaImage naive = renderer.read_naive();
  const FrameComparison classified = compare(renderer.read_classified(), naive, kEquivalenceTolerance);
  EXPECT_EQ(classified.magenta_pixels, 0u) << "tiles left undrawn";
  EXPECT_EQ(classified.pixels_over_tolerance, 0u)
      << classified.first_difference << " (max difference " << classified.max_abs_difference << ")";
  const FrameComparison dynamic = compare(renderer.read_dynamic(), naive, kEquivalenceTolerance);
  EXPECT_EQ(dynamic.pixels_over_tolerance, 0u) << "dynamic vs naive: " << dynamic.first_difference;
  EXPECT_EQ(std::accumulate(frame.stats.class_tiles.begin(), frame.stats.class_tiles.end(), 0u),
            renderer.grid().tile_count());

  // The camera frames the model: it covers part of the frame, and the sky the rest.
  const std::vector<std::uint8_t> ids = renderer.raw_tile_ids();
  const auto sky =
      std::count_if(ids.begin(), ids.end(), [](std::uint8_t id) { return (id & split_second::raw_bit::SKY) != 0; });
  const auto lit = std::count_if(ids.begin(), ids.end(),
                                 [](std::uint8_t id) { return (id & split_second::raw_bit::SUN_LIGHT) != 0; });
  EXPECT_GT(sky, 0);
  EXPECT_LT(sky, static_cast<std::ptrdiff_t>(ids.size()) * 9 / 10) << "the model covers under a tenth of the frame";
  EXPECT_GT(lit, 0) << "no tile faces the sun";
  if (renderer.msaa_samples() == 1) {
    EXPECT_TRUE(std::none_of(ids.begin(), ids.end(),
                             [](std::uint8_t id) { return (id & split_second::raw_bit::MSAA_EDGE) != 0; }));
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
                 TilePrimitive::triangles}),
    case_name);

}  // namespace
}  // namespace tilelight::test
