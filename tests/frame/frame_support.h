#pragma once
// Helpers for the frame tests: render one frame with given options and compare.

#include "tilelight/readback.h"
#include "tilelight/tile_renderer.h"

#include <cstdint>
#include <set>
#include <string>

namespace tilelight::test {

// The tolerance of the equivalence tests: the classified and naive frames must be EQUAL, bit
// for bit. Every permutation computes the full shader's arithmetic on the pixels its class
// admits (precise math on threshold decisions, exact identities where a feature is skipped),
// so there is no floating-point noise to allow for.
inline constexpr double kEquivalenceTolerance = 0.0;

struct FrameComparison {
  std::uint64_t pixels_over_tolerance = 0;
  double max_abs_difference = 0.0;
  std::uint64_t magenta_pixels = 0;  // the classified target's clear colour: an uncovered tile
  std::string first_difference;      // "pixel (x, y): classified (...) naive (...)"
};

FrameComparison compare(const RgbaImage& classified, const RgbaImage& naive, double tolerance);

// Optimised IDs present in a frame's raw tile IDs (row-major).
std::set<std::uint32_t> optimised_ids_of(const std::vector<std::uint8_t>& raw_ids);

}  // namespace tilelight::test
