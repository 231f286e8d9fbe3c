#include "frame_support.h"

#include "tilelight/app/cli.h"

#include <gtest/gtest.h>

#include "tilelight_testing/raw_bit_masks.h"

#include <split_second_shaders.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tilelight::test {

void expect_classified_and_dynamic_equal_naive(const TileRenderer& renderer) {
  const RgbaImage naive = renderer.read_naive();
  const FrameComparison classified = compare(renderer.read_classified(), naive, kEquivalenceTolerance);
  EXPECT_EQ(classified.magenta_pixels, 0u) << "tiles left undrawn";
  EXPECT_EQ(classified.pixels_over_tolerance, 0u)
      << classified.first_difference << " (max difference " << classified.max_abs_difference << ")";
  const FrameComparison dynamic = compare(renderer.read_dynamic(), naive, kEquivalenceTolerance);
  EXPECT_EQ(dynamic.magenta_pixels, 0u) << "dynamic pass left pixels undrawn";
  EXPECT_EQ(dynamic.pixels_over_tolerance, 0u)
      << "dynamic vs naive: " << dynamic.first_difference << " (max difference " << dynamic.max_abs_difference << ")";
}

FrameResult render_equivalent_frame(TileRenderer& renderer) {
  FrameResult frame = renderer.render_frame();
  expect_classified_and_dynamic_equal_naive(renderer);
  EXPECT_EQ(std::accumulate(frame.stats.class_tiles.begin(), frame.stats.class_tiles.end(), 0u),
            renderer.grid().tile_count());
  return frame;
}

LocalLightShadowPool expect_volumes_equal_full_screen(const Context& context, const Scene& scene,
                                                      RendererOptions options) {
  options.local_light_pass = LocalLightPass::fullscreen;
  TileRenderer reference(context, scene, options);
  render_equivalent_frame(reference);
  options.local_light_pass = LocalLightPass::volumes;
  TileRenderer volumes(context, scene, options);
  render_equivalent_frame(volumes);
  const FrameComparison classified = compare(volumes.read_classified(), reference.read_classified(), 0.0);
  EXPECT_EQ(classified.pixels_over_tolerance, 0u) << "classified target: " << classified.first_difference;
  const FrameComparison naive = compare(volumes.read_naive(), reference.read_naive(), 0.0);
  EXPECT_EQ(naive.pixels_over_tolerance, 0u) << "naive target: " << naive.first_difference;
  return volumes.local_light_shadow_pool();
}

FrameComparison compare(const RgbaImage& classified, const RgbaImage& naive, double tolerance) {
  FrameComparison result;
  for (std::uint32_t y = 0; y < classified.height; ++y) {
    for (std::uint32_t x = 0; x < classified.width; ++x) {
      const auto a = classified.at(x, y);
      const auto b = naive.at(x, y);
      if (a[0] == 1.0f && a[1] == 0.0f && a[2] == 1.0f) ++result.magenta_pixels;
      double worst = 0.0;
      for (int c = 0; c < 4; ++c) {
        const bool both_nan = std::isnan(a[c]) && std::isnan(b[c]);
        const double d = both_nan ? 0.0 : std::fabs(static_cast<double>(a[c]) - b[c]);
        worst = std::max(worst, std::isnan(d) ? INFINITY : d);
      }
      result.max_abs_difference = std::max(result.max_abs_difference, worst);
      if (worst > tolerance) {
        if (result.pixels_over_tolerance == 0) {
          result.first_difference = fmt::format("pixel ({}, {}): classified ({}, {}, {}) naive ({}, {}, {})", x, y,
                                                a[0], a[1], a[2], b[0], b[1], b[2]);
        }
        ++result.pixels_over_tolerance;
      }
    }
  }
  return result;
}

std::set<std::uint32_t> optimised_ids_of(const std::vector<std::uint8_t>& raw_ids) {
  std::set<std::uint32_t> ids;
  for (std::uint8_t raw : raw_ids) {
    const std::optional<split_second::OptimisedId> id = split_second::optimised_id(split_second::RawId(raw));
    if (!id) throw std::runtime_error("raw tile ID " + std::to_string(raw) + " is out of range or pruned");
    ids.insert(id->value());
  }
  return ids;
}

CliResult run_cli(std::vector<std::string> args) {
  if (std::find(args.begin(), args.end(), "--device") == args.end()) {
    args.insert(args.begin(), {"--device", "llvmpipe"});
  }
  args.insert(args.begin(), "tilelight");
  std::vector<const char*> argv;
  argv.reserve(args.size());
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int code = app::run(static_cast<int>(argv.size()), argv.data(), out, err);
  return {code, out.str(), err.str()};
}

Camera telephoto_camera() {
  return {"telephoto",
          "10 degrees onto the boxes from 70 m",
          {0.0f, 12.0f, 45.0f},
          {0.0f, 1.5f, -25.0f},
          {0, 1, 0},
          10.0f,
          {0.0f, 0.0f, -20.0f}};
}

ReferenceComparison compare_with_reference(const std::vector<std::uint8_t>& gpu, const ReferenceClassification& cpu,
                                           std::uint32_t tiles_x) {
  namespace bit = tilelight::raw_bit_masks;
  const std::uint32_t shadow_bits = bit::SHADOW_SOLID | bit::SHADOW_SOFT;
  const std::uint32_t exact_bits = bit::SKY | bit::SUN_LIGHT;
  const std::uint32_t at_least_bits = bit::MSAA_EDGE | bit::SHADOW_FADE | bit::LIGHT_SCATTERING;
  ReferenceComparison result;
  for (std::size_t i = 0; i < gpu.size() && i < cpu.raw_ids.size(); ++i) {
    const std::uint32_t cpu_id = cpu.raw_ids[i];
    const std::uint32_t gpu_id = gpu[i];
    const std::uint32_t certain = ~static_cast<std::uint32_t>(cpu.uncertain_bits[i]);
    if (cpu.uncertain_bits[i] != 0) ++result.uncertain_tiles;
    const char* why = nullptr;
    if (((gpu_id ^ cpu_id) & exact_bits & certain) != 0) {
      why = "sky or sun bit differs";
    } else if ((cpu_id & at_least_bits & certain & ~gpu_id) != 0) {
      why = "a needed MSAA-edge, fade or scattering bit is missing";
    } else if ((gpu_id & bit::SUN_LIGHT) != 0) {
      const std::uint32_t type = gpu_id & shadow_bits;
      if (type == shadow_bits) why = "both shadow bits";
      if (type == bit::SHADOW_SOLID && cpu.solid_ruled_out[i]) why = "SOLID, but a sample has a lit tap";
      if (type == 0 && cpu.lit_ruled_out[i]) why = "no shadow, but a sample has an occluded tap";
      const bool settled_by_taps = (cpu_id & bit::SUN_LIGHT) != 0 && (cpu_id & shadow_bits) != bit::SHADOW_SOFT;
      if (settled_by_taps && type == bit::SHADOW_SOFT) ++result.soft_by_bounds;
      if (settled_by_taps && type != bit::SHADOW_SOFT) ++result.settled_by_bounds;
    }
    if (why != nullptr && result.mismatches++ == 0) {
      result.first_mismatch = fmt::format("tile ({}, {}): GPU raw ID {:#04x}, CPU {:#04x} (uncertain bits {:#04x}): {}",
                                          i % tiles_x, i / tiles_x, gpu_id, cpu_id, cpu.uncertain_bits[i], why);
    }
  }
  if (gpu.size() != cpu.raw_ids.size()) {
    ++result.mismatches;
    result.first_mismatch = fmt::format("{} GPU IDs, {} CPU IDs", gpu.size(), cpu.raw_ids.size());
  }
  return result;
}

}  // namespace tilelight::test
