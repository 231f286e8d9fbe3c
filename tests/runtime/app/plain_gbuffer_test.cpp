// The two G-buffers of a frame (uber/include/gbuffer.glsl): the classified path's and the
// baselines' plain one must store the same bits in every target lighting reads (RT0..RT3), so
// that the baselines light exactly what the classified path lights and pay for nothing else;
// only the classified one has coverage flags. And no scene G-buffer shader writes gl_FragDepth,
// which would turn off early and hierarchical depth testing.
#include "frame_support.h"
#include "tilelight/scene/scene.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

#include <split_second_1x_shaders.h>
#include <split_second_shaders.h>

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <string>
#include <tuple>

namespace tilelight::test {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace plain_gbuffer_test {
namespace {

// GBufferSamples: rt0[4], rt1[4], rt2[4], rt3, then the tag's bits.
constexpr std::size_t kLitFloats = 13;

struct Mismatch {
  std::size_t samples = 0;
  std::string first;
};

Mismatch compare_lit_targets(const GBufferSamples& classified, const GBufferSamples& plain) {
  Mismatch m;
  for (std::uint32_t y = 0; y < classified.height; ++y) {
    for (std::uint32_t x = 0; x < classified.width; ++x) {
      for (std::uint32_t s = 0; s < classified.samples; ++s) {
        const float* a = classified.at(x, y, s);
        const float* b = plain.at(x, y, s);
        for (std::size_t i = 0; i < kLitFloats; ++i) {
          if (std::bit_cast<std::uint32_t>(a[i]) == std::bit_cast<std::uint32_t>(b[i])) continue;
          if (m.samples++ == 0)
            m.first = fmt::format("pixel ({}, {}) sample {} float {}: {} vs {}", x, y, s, i, a[i], b[i]);
          break;
        }
      }
    }
  }
  return m;
}

using Case = std::tuple<std::string, std::uint32_t>;  // camera, MSAA (0: automatic)

class PlainGBuffer : public VulkanTest, public ::testing::WithParamInterface<Case> {};

TEST_P(PlainGBuffer, StoresWhatTheClassifiedOneStoresInEveryTargetLightingReads) {
  const auto& [camera, msaa] = GetParam();
  RendererOptions options;
  options.width = 256;
  options.height = 144;
  options.camera = camera;
  options.msaa = msaa;
  options.baselines = Baselines::none;
  TileRenderer renderer(context(), make_demo_scene(), options);
  renderer.render_frame();
  const GBufferSamples classified = TileRendererTestSeam::read_gbuffer(renderer, GBufferKind::classified);
  const GBufferSamples plain = TileRendererTestSeam::read_gbuffer(renderer, GBufferKind::plain);
  ASSERT_EQ(classified.values.size(), plain.values.size());
  const Mismatch m = compare_lit_targets(classified, plain);
  EXPECT_EQ(m.samples, 0u) << m.first;
}

std::string case_name(const ::testing::TestParamInfo<Case>& param_info) {
  return std::get<0>(param_info.param) + (std::get<1>(param_info.param) == 1 ? "_1x" : "_msaa");
}

INSTANTIATE_TEST_SUITE_P(Cameras, PlainGBuffer,
                         ::testing::Values(Case{"default", 0}, Case{"street", 0}, Case{"closeup", 0}, Case{"low", 1},
                                           Case{"default", 1}),
                         case_name);

// SPIR-V: OpDecorate (opcode 71) <id> BuiltIn (11) FragDepth (22).
bool writes_frag_depth(std::span<const std::uint32_t> words) {
  for (std::size_t i = 5; i < words.size();) {
    const std::uint32_t count = words[i] >> 16, opcode = words[i] & 0xFFFFu;
    if (count == 0) return false;  // malformed: not this test's question
    if (opcode == 71 && count >= 4 && words[i + 2] == 11 && words[i + 3] == 22) return true;
    i += count;
  }
  return false;
}

TEST(SceneShaders, NoGBufferShaderWritesFragDepth) {
  for (const shadergen::Registry* registry :
       {&split_second::raster::registry(), &split_second_1x::raster::registry()}) {
    int checked = 0;
    for (const char* name : {"gbuffer", "gbuffer_flagged", "sky", "sky_flagged"}) {
      const shadergen::CompanionShader* shader = registry->companion(name);
      ASSERT_NE(shader, nullptr) << name;
      EXPECT_FALSE(writes_frag_depth(shader->shader.spirv)) << registry->name << " " << name;
      ++checked;
    }
    EXPECT_EQ(checked, 4);
  }
  // The check can fail: a module holding only that decoration is found.
  const std::uint32_t decorated[] = {0x07230203u, 0x00010000u, 0u, 2u, 0u, (4u << 16) | 71u, 1u, 11u, 22u};
  EXPECT_TRUE(writes_frag_depth(decorated));
}

}  // namespace
}  // namespace plain_gbuffer_test
}  // namespace tilelight::test
