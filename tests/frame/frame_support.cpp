#include "frame_support.h"

#include <split_second_shaders.h>

#include <fmt/format.h>

#include <cmath>

namespace tilelight::test {

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
  for (std::uint8_t raw : raw_ids) ids.insert(split_second::kRawToOptimised[raw]);
  return ids;
}

}  // namespace tilelight::test
