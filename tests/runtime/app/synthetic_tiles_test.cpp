// Every optimised ID, including those the demo scene does not produce, drawn and checked.
//
// The scene's G-buffer is read back and edited tile by tile, keeping each pixel where it was
// (so its world position, and with it its shadow, stays meaningful): one pixel may become sky,
// one may be pushed beyond the shadow-fade or the scattering distance (facing away from the
// sun, so it adds only its depth bits), and one may get differing MSAA samples. Each tile
// takes the next of the 16 combinations for its original class, so every class of the scene
// is combined with every edit. The edited G-buffer is uploaded and the frame rendered again.
#include "frame_support.h"
#include "tilelight/scene/scene.h"
#include "tilelight_testing/cpu_classifier.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include <split_second_shaders.h>

#include <glm/glm.hpp>

#include <bit>
#include <cmath>
#include <map>
#include <numeric>

namespace tilelight::test {
namespace {

enum Edit : unsigned { kSky = 1, kFadeDepth = 2, kScatterDepth = 4, kEdge = 8, kEditCombinations = 16 };

void set_pixel(GBufferSamples& g, std::uint32_t x, std::uint32_t y, const std::array<float, 16>& values) {
  for (std::uint32_t s = 0; s < g.samples; ++s) {
    float* v = g.values.data() + ((static_cast<std::size_t>(y) * g.width + x) * g.samples + s) * 16;
    std::copy(values.begin(), values.end(), v);
  }
}

std::array<float, 16> read_pixel(const GBufferSamples& g, std::uint32_t x, std::uint32_t y) {
  std::array<float, 16> out{};
  std::copy_n(g.at(x, y, 0), 16, out.begin());
  return out;
}

// A geometry pixel at view depth `depth` along the pixel's own ray, facing away from the sun.
std::array<float, 16> far_pixel(const GBufferSamples& g, const LightingParamsBlock& p, std::uint32_t x, std::uint32_t y,
                                float view_depth) {
  const glm::mat4 view_proj = glm::inverse(p.inv_view_proj);
  const glm::vec2 ndc{(static_cast<float>(x) + 0.5f) * p.viewport.z * 2.0f - 1.0f,
                      (static_cast<float>(y) + 0.5f) * p.viewport.w * 2.0f - 1.0f};
  const glm::vec4 far_point = p.inv_view_proj * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 camera = glm::vec3(p.camera_pos);
  const glm::vec3 direction = glm::normalize(glm::vec3(far_point) / far_point.w - camera);
  const glm::vec3 point = camera + direction * (view_depth / glm::dot(direction, glm::vec3(p.camera_forward)));
  const glm::vec4 clip = view_proj * glm::vec4(point, 1.0f);
  std::array<float, 16> v = read_pixel(g, x, y);
  v[0] = 0.6f;                // albedo, so the pixel is not black
  v[4] = -p.sun_direction.x;  // normal away from the sun
  v[5] = -p.sun_direction.y;
  v[6] = -p.sun_direction.z;
  v[7] = 9.0f / 255.0f;  // a geometry motion ID
  // As a material stores it (gbuffer.glsl): facing away, so the surface depth's sun-facing bit
  // is clear (the upload would clear it anyway). Every sample keeps its coverage flags.
  v[12] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(clip.z / clip.w) & ~1u);
  return v;
}

std::array<float, 16> sky_pixel() {
  std::array<float, 16> v{};
  v[8] = 0.5f, v[9] = 0.6f, v[10] = 0.8f;  // prelit = the sky colour; motion ID 0
  v[12] = 1.0f;
  return v;
}

// What a partially covering fragment leaves (gbuffer.glsl): the partial flag on its samples.
void mark_msaa_edge(GBufferSamples& g, std::uint32_t x, std::uint32_t y) {
  for (std::uint32_t s = 0; s < g.samples; ++s) {
    float* v = g.values.data() + ((static_cast<std::size_t>(y) * g.width + x) * g.samples + s) * 16;
    v[13] = std::bit_cast<float>(1u);  // GBUFFER_FLAG_PARTIAL
  }
}

GBufferSamples edit_tiles(const GBufferSamples& source, const TileGrid& grid, const LightingParamsBlock& params,
                          const std::vector<std::uint8_t>& raw_ids) {
  GBufferSamples g = source;
  std::map<std::uint8_t, unsigned> next_edit;
  for (std::uint32_t ty = 0; ty + 1 < grid.tiles_y; ++ty) {  // full tiles only
    for (std::uint32_t tx = 0; tx + 1 < grid.tiles_x; ++tx) {
      const unsigned edit = next_edit[raw_ids[ty * grid.tiles_x + tx]]++ % kEditCombinations;
      const std::uint32_t x = tx * grid.tile_size, y = ty * grid.tile_size;
      if (edit & kSky) set_pixel(g, x, y, sky_pixel());
      if (edit & kFadeDepth) set_pixel(g, x + 1, y, far_pixel(g, params, x + 1, y, 65.0f));
      if (edit & kScatterDepth) set_pixel(g, x + 2, y, far_pixel(g, params, x + 2, y, 150.0f));
      if (edit & kEdge) {  // sample 1 of one pixel gets a different albedo: an MSAA edge
        float* v = g.values.data() + ((static_cast<std::size_t>(y + 1) * g.width + x) * g.samples + 1) * 16;
        v[1] = v[1] >= 0.5f ? v[1] - 40.0f / 255.0f : v[1] + 40.0f / 255.0f;
        mark_msaa_edge(g, x, y + 1);
      }
    }
  }
  return g;
}

}  // namespace
}  // namespace tilelight::test

namespace tilelight {
// Readable test names in CTest (gtest would print the enum's bytes).
inline void PrintTo(IndexPath path, std::ostream* os) { *os << (path == IndexPath::cpu ? "cpu" : "gpu"); }
}  // namespace tilelight

namespace tilelight::test {
namespace {

class SyntheticTiles : public VulkanTest, public ::testing::WithParamInterface<IndexPath> {};

// Renders `camera`, edits its G-buffer, renders the edited one and checks it; returns the
// optimised IDs the edited frame used.
std::set<std::uint32_t> check_edited_frame(const Context& context, const Scene& scene, IndexPath path,
                                           const char* camera) {
  RendererOptions options;
  options.light_pass = LightPass::raster;
  options.width = 320;
  options.height = 180;
  options.path = path;
  options.camera = camera;
  TileRenderer renderer(context, scene, options);
  renderer.render_frame();
  const GBufferSamples edited = edit_tiles(TileRendererTestSeam::read_gbuffer(renderer), renderer.grid(),
                                           TileRendererTestSeam::lighting_params(renderer), renderer.raw_tile_ids());
  TileRendererTestSeam::set_gbuffer_override(renderer, edited);
  const FrameResult frame = renderer.render_frame();

  // The upload reproduced the edited G-buffer (up to the targets' 8-bit and half precision).
  const GBufferSamples uploaded = TileRendererTestSeam::read_gbuffer(renderer);
  EXPECT_EQ(uploaded.values.size(), edited.values.size());
  std::size_t off = 0;
  for (std::size_t i = 0; i < std::min(uploaded.values.size(), edited.values.size()); ++i) {
    off += std::fabs(uploaded.values[i] - edited.values[i]) > 2e-3f * std::max(1.0f, std::fabs(edited.values[i]));
  }
  EXPECT_EQ(off, 0u) << camera << ": uploaded G-buffer values differ from the edited ones";
  // The GPU classified the synthetic tiles as the reference does (shadow types up to SOFT).
  const std::vector<std::uint8_t> raw = renderer.raw_tile_ids();
  const ReferenceClassification cpu =
      classify_on_cpu(renderer.grid(), uploaded, TileRendererTestSeam::read_shadow_map(renderer),
                      TileRendererTestSeam::lighting_params(renderer), registry_raw_bits());
  const ReferenceComparison reference = compare_with_reference(raw, cpu, renderer.grid().tiles_x);
  EXPECT_EQ(reference.mismatches, 0u) << camera << ": " << reference.first_mismatch;

  const FrameComparison cmp = compare(renderer.read_classified(), renderer.read_naive(), kEquivalenceTolerance);
  EXPECT_EQ(cmp.magenta_pixels, 0u) << camera;
  EXPECT_EQ(cmp.pixels_over_tolerance, 0u) << camera << ": " << cmp.first_difference;
  EXPECT_EQ(std::accumulate(frame.stats.class_tiles.begin(), frame.stats.class_tiles.end(), 0u),
            renderer.grid().tile_count());
  return optimised_ids_of(raw);
}

TEST_P(SyntheticTiles, EveryOptimisedIdIsDrawnAndEqualsNaive) {
  if (!context().features().sample_rate_shading) GTEST_SKIP() << "needs sample-rate shading";
  const Scene scene = make_demo_scene();
  // The default view supplies the sunlit and soft-shadow classes, the canopy's shadow the solid ones.
  std::set<std::uint32_t> ids = check_edited_frame(context(), scene, GetParam(), "default");
  const std::set<std::uint32_t> shadow_ids = check_edited_frame(context(), scene, GetParam(), "shadow");
  ids.insert(shadow_ids.begin(), shadow_ids.end());
  for (std::uint32_t id = 0; id < split_second::kOptimisedCount; ++id) {
    EXPECT_TRUE(ids.count(id)) << "optimised ID " << id << " not exercised";
  }
}

INSTANTIATE_TEST_SUITE_P(Paths, SyntheticTiles, ::testing::Values(IndexPath::cpu, IndexPath::gpu),
                         [](const ::testing::TestParamInfo<IndexPath>& param_info) {
                           return std::string(param_info.param == IndexPath::cpu ? "cpu" : "gpu");
                         });

}  // namespace
}  // namespace tilelight::test
