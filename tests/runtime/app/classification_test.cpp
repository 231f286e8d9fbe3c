// GPU classification against the CPU reference classifier, and the properties each camera's
// frame is built to have.
#include "frame_support.h"
#include "tilelight/scene/scene.h"
#include "tilelight_testing/cpu_classifier.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include "tilelight_testing/raw_bit_masks.h"

#include <split_second_shaders.h>

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace tilelight::test {
namespace {

namespace bit = tilelight::raw_bit_masks;

class Classification : public VulkanTest {
 protected:
  std::unique_ptr<TileRenderer> render(const char* camera, std::uint32_t width, std::uint32_t height) {
    RendererOptions options;
    options.light_pass = LightPass::raster;
    options.width = width;
    options.height = height;
    options.camera = camera;
    auto renderer = std::make_unique<TileRenderer>(context(), scene_, options);
    renderer->render_frame();
    return renderer;
  }
  Scene scene_ = make_demo_scene();
};

// See compare_with_reference(); both kinds of allowed difference must stay rare enough for the
// comparison to mean something.
void expect_matches_reference(TileRenderer& renderer) {
  const std::vector<std::uint8_t> gpu = renderer.raw_tile_ids();
  const ReferenceClassification cpu = classify_on_cpu(
      renderer.grid(), TileRendererTestSeam::read_gbuffer(renderer), TileRendererTestSeam::read_shadow_map(renderer),
      TileRendererTestSeam::lighting_params(renderer), registry_raw_bits());
  const ReferenceComparison cmp = compare_with_reference(gpu, cpu, renderer.grid().tiles_x);
  EXPECT_EQ(cmp.mismatches, 0u) << cmp.first_mismatch;
  EXPECT_LE(cmp.uncertain_tiles, gpu.size() / 100) << "too many tiles near a threshold for the comparison to mean much";
  EXPECT_GT(cmp.settled_by_bounds, 0u) << "the shadow bounds settled no tile: every check of SOLID and lit is void";
}

TEST_F(Classification, GpuMatchesCpuReferenceOnTheDefaultCamera) {
  auto renderer = render("default", 320, 180);
  expect_matches_reference(*renderer);
}

TEST_F(Classification, GpuMatchesCpuReferenceThroughATelephotoLens) {
  scene_.cameras.push_back(telephoto_camera());
  auto renderer = render("telephoto", 320, 180);
  expect_matches_reference(*renderer);
}

TEST_F(Classification, GpuMatchesCpuReferenceWithPartialTiles) {
  auto renderer = render("low", 203, 117);
  expect_matches_reference(*renderer);
}

// The classifier trusts the coverage flags instead of comparing samples (gbuffer.glsl): it
// compares values only where a sample has the shared flag. That is sound only if every pixel
// whose samples differ in any stored value has a flag on some sample; check it on every pixel of
// real frames. The converse need not hold (a mesh's inner edges give partial fragments with
// equal values), which costs only time.
struct EdgeBitCount {
  std::size_t differing = 0, flagged = 0, missed = 0;
  std::string first_missed;
};

EdgeBitCount count_edge_bits(const GBufferSamples& g) {
  const auto flagged = [](const float* sample) { return std::bit_cast<std::uint32_t>(sample[13]) != 0; };
  EdgeBitCount count;
  for (std::uint32_t y = 0; y < g.height; ++y) {
    for (std::uint32_t x = 0; x < g.width; ++x) {
      bool differ = false, bit = flagged(g.at(x, y, 0));
      for (std::uint32_t s = 1; s < g.samples; ++s) {
        bit = bit || flagged(g.at(x, y, s));
        for (int i = 0; i < 13; ++i) differ = differ || !(g.at(x, y, 0)[i] == g.at(x, y, s)[i]);
      }
      count.differing += differ;
      count.flagged += bit;
      if (differ && !bit && count.missed++ == 0) count.first_missed = fmt::format("pixel ({}, {})", x, y);
    }
  }
  return count;
}

TEST_F(Classification, CoverageFlagsCoverEveryPixelWithDifferingSamples) {
  std::size_t differing = 0;
  for (const char* camera : {"default", "low", "shadow"}) {
    const EdgeBitCount count = count_edge_bits(TileRendererTestSeam::read_gbuffer(*render(camera, 320, 180)));
    EXPECT_EQ(count.missed, 0u) << camera << ": " << count.first_missed
                                << " has differing samples but no coverage flag";
    differing += count.differing;
  }
  EXPECT_GT(differing, 0u) << "no frame has an MSAA edge: the check proves nothing";
}

// Only real discontinuities are MSAA edges: the two triangles of one flat face (the ground's one
// quad here, seen from above so that its diagonal crosses the view and no horizon does) store the
// same values where they share a pixel (gbuffer.frag: the face's depth plane and normal), so no
// tile of the frame is an edge. The same frame with flat faces switched off (material.w = 0)
// has its diagonal classified as an edge: the check can fail.
std::uint32_t edge_tiles_over_ground(const Context& context, float flat_faces) {
  Scene scene = make_demo_scene();
  scene.batches = {scene.batches.front()};  // the ground alone
  scene.instances.front().material.w = flat_faces;
  Camera above;
  above.name = "above";
  above.position = {0.0f, 40.0f, 0.0f};
  above.target = {8.0f, 0.0f, 6.0f};
  above.shadow_focus = above.target;
  scene.cameras.push_back(above);
  RendererOptions options;
  options.light_pass = LightPass::raster;
  options.width = 320;
  options.height = 180;
  options.camera = "above";
  TileRenderer renderer(context, scene, options);
  renderer.render_frame();
  const std::vector<std::uint8_t> ids = renderer.raw_tile_ids();
  return static_cast<std::uint32_t>(
      std::count_if(ids.begin(), ids.end(), [](std::uint8_t id) { return (id & bit::MSAA_EDGE) != 0; }));
}

TEST_F(Classification, AFlatFacesInnerDiagonalIsNoMsaaEdge) {
  EXPECT_EQ(edge_tiles_over_ground(context(), 1.0f), 0u);
  EXPECT_GT(edge_tiles_over_ground(context(), 0.0f), 0u) << "the diagonal is not in view: the check proves nothing";
}

// The classifier reads the surface depth (gbuffer.glsl): the sky is depth 1.0, and the sun-facing
// bit is the material's N.L > 0 on the normal as RT1 stores it. Check both on every sample of
// real frames against what the other targets hold.
struct DepthBitCount {
  std::size_t sky = 0, facing = 0, away = 0, wrong = 0;
  std::string first_wrong;
};

DepthBitCount count_depth_bits(const GBufferSamples& g, const glm::vec4& sun) {
  DepthBitCount count;
  for (std::uint32_t y = 0; y < g.height; ++y) {
    for (std::uint32_t x = 0; x < g.width; ++x) {
      for (std::uint32_t s = 0; s < g.samples; ++s) {
        const float* v = g.at(x, y, s);
        const bool sky = v[12] == 1.0f;
        const bool sky_motion = std::nearbyint(v[7] * 255.0f) == 0.0f;
        const float n_dot_l = v[4] * sun.x + v[5] * sun.y + v[6] * sun.z;  // precise_dot()'s order
        const bool bit = (std::bit_cast<std::uint32_t>(v[12]) & 1u) != 0;
        bool wrong = sky != sky_motion;
        if (!sky) wrong = wrong || (bit != (n_dot_l > 0.0f) && std::fabs(n_dot_l) > 1e-6f);
        count.sky += sky;
        count.facing += !sky && bit;
        count.away += !sky && !bit;
        if (wrong && count.wrong++ == 0) {
          count.first_wrong = fmt::format("pixel ({}, {}) sample {}: depth {:a}, motion byte {}, N.L {}", x, y, s,
                                          v[12], v[7] * 255.0f, n_dot_l);
        }
      }
    }
  }
  return count;
}

TEST_F(Classification, DepthBitsAgreeWithTheOtherTargets) {
  DepthBitCount total;
  for (const char* camera : {"default", "low", "shadow"}) {
    auto renderer = render(camera, 320, 180);
    const DepthBitCount count = count_depth_bits(TileRendererTestSeam::read_gbuffer(*renderer),
                                                 TileRendererTestSeam::lighting_params(*renderer).sun_direction);
    EXPECT_EQ(count.wrong, 0u) << camera << ": " << count.first_wrong;
    total.sky += count.sky;
    total.facing += count.facing;
    total.away += count.away;
  }
  EXPECT_GT(total.sky, 0u);
  EXPECT_GT(total.facing, 0u);
  EXPECT_GT(total.away, 0u);
}

// SOLID needs a tile whose samples' tap rectangle lies inside one occluder's shadow; at 320x180
// the default view's tiles are too large for that (classify_tiles.comp bounds a tile, not each
// sample), at 640x360 about 20 tiles are.
TEST_F(Classification, DefaultCameraHasAllSevenProperties) {
  auto renderer = render("default", 640, 360);
  std::uint32_t seen = 0;
  for (std::uint8_t id : renderer->raw_tile_ids()) seen |= id;
  for (const auto& [name, mask] : {std::pair{"SHADOW_SOLID", bit::SHADOW_SOLID},
                                   {"SHADOW_SOFT", bit::SHADOW_SOFT},
                                   {"SHADOW_FADE", bit::SHADOW_FADE},
                                   {"LIGHT_SCATTERING", bit::LIGHT_SCATTERING},
                                   {"MSAA_EDGE", bit::MSAA_EDGE},
                                   {"SKY", bit::SKY},
                                   {"SUN_LIGHT", bit::SUN_LIGHT}}) {
    EXPECT_NE(seen & mask, 0u) << name << " does not occur in the default frame";
  }
}

TEST_F(Classification, SkyCameraSeesOnlySky) {
  auto renderer = render("sky", 160, 90);
  for (std::uint8_t id : renderer->raw_tile_ids()) ASSERT_EQ(id, bit::SKY);
}

TEST_F(Classification, ShadowCameraSeesOnlySolidShadow) {
  auto renderer = render("shadow", 160, 90);
  for (std::uint8_t id : renderer->raw_tile_ids()) {
    ASSERT_EQ(id & (bit::SHADOW_SOLID | bit::SHADOW_SOFT | bit::SKY), bit::SHADOW_SOLID) << int(id);
  }
}

}  // namespace
}  // namespace tilelight::test
