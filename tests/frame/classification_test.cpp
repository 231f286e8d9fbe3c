// GPU classification against the CPU reference classifier, and the properties each camera's
// frame is built to have.
#include "frame_support.h"
#include "test_support.h"
#include "tilelight/cpu_classifier.h"
#include "tilelight/scene.h"

#include <split_second_shaders.h>

#include <fmt/format.h>

namespace tilelight::test {
namespace {

namespace bit = split_second::raw_bit;

class Classification : public VulkanTest {
 protected:
  std::unique_ptr<TileRenderer> render(const char* camera, std::uint32_t width, std::uint32_t height) {
    RendererOptions options;
    options.width = width;
    options.height = height;
    options.camera = camera;
    auto renderer = std::make_unique<TileRenderer>(context(), scene_, options);
    renderer->render_frame();
    return renderer;
  }
  Scene scene_ = make_demo_scene();
};

// Differences are allowed only in bits the reference marks as near a threshold, and such tiles
// must be rare (the margins are tiny).
void expect_matches_reference(TileRenderer& renderer) {
  const std::vector<std::uint8_t> gpu = renderer.raw_tile_ids();
  const ReferenceClassification cpu = classify_on_cpu(renderer.grid(), renderer.read_gbuffer(),
                                                      renderer.read_shadow_map(), renderer.lighting_params(),
                                                      registry_raw_bits());
  ASSERT_EQ(gpu.size(), cpu.raw_ids.size());
  std::size_t mismatches = 0, uncertain = 0;
  std::string first;
  for (std::size_t i = 0; i < gpu.size(); ++i) {
    if (cpu.uncertain_bits[i] != 0) ++uncertain;
    if (((gpu[i] ^ cpu.raw_ids[i]) & ~cpu.uncertain_bits[i]) != 0) {
      if (mismatches++ == 0) {
        first = fmt::format("tile ({}, {}): GPU raw ID {:#04x}, CPU {:#04x} (uncertain bits {:#04x})",
                            i % renderer.grid().tiles_x, i / renderer.grid().tiles_x, gpu[i], cpu.raw_ids[i],
                            cpu.uncertain_bits[i]);
      }
    }
  }
  EXPECT_EQ(mismatches, 0u) << first;
  EXPECT_LE(uncertain, gpu.size() / 100) << "too many tiles near a threshold for the comparison to mean much";
}

TEST_F(Classification, GpuMatchesCpuReferenceOnTheDefaultCamera) {
  auto renderer = render("default", 320, 180);
  expect_matches_reference(*renderer);
}

TEST_F(Classification, GpuMatchesCpuReferenceWithPartialTiles) {
  auto renderer = render("low", 203, 117);
  expect_matches_reference(*renderer);
}

TEST_F(Classification, DefaultCameraHasAllSevenProperties) {
  auto renderer = render("default", 320, 180);
  std::uint32_t seen = 0;
  for (std::uint8_t id : renderer->raw_tile_ids()) seen |= id;
  for (const auto& [name, mask] : {std::pair{"SHADOW_SOLID", bit::SHADOW_SOLID}, {"SHADOW_SOFT", bit::SHADOW_SOFT},
                                   {"SHADOW_FADE", bit::SHADOW_FADE}, {"LIGHT_SCATTERING", bit::LIGHT_SCATTERING},
                                   {"MSAA_EDGE", bit::MSAA_EDGE}, {"SKY", bit::SKY}, {"SUN_LIGHT", bit::SUN_LIGHT}}) {
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
