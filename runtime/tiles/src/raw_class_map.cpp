#include "raw_class_map.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

namespace tilelight {

RawClassMap make_raw_class_map(std::string_view builder, std::span<const std::uint8_t> lut,
                               std::span<const bool> pruned, std::uint32_t class_count, std::uint32_t max_classes) {
  if (class_count == 0 || class_count > max_classes) {
    throw Error(fmt::format("{}: the class count must be 1..{} (got {})", builder, max_classes, class_count));
  }
  if (lut.size() != kRawClassCount) {
    throw Error(fmt::format("{}: the LUT must have {} entries (got {})", builder, kRawClassCount, lut.size()));
  }
  if (!pruned.empty() && pruned.size() != kRawClassCount) {
    throw Error(fmt::format("{}: the pruned set must have {} entries or none (got {})", builder, kRawClassCount,
                            pruned.size()));
  }
  RawClassMap map;
  map.fill(kNoClass);
  for (std::uint32_t raw = 0; raw < kRawClassCount; ++raw) {
    if (lut[raw] >= class_count) {
      throw Error(fmt::format("{}: LUT entry {} is {}, out of range (0..{})", builder, raw, lut[raw], class_count - 1));
    }
    if (pruned.empty() || !pruned[raw]) map[raw] = lut[raw];
  }
  return map;
}

void throw_no_class(std::uint32_t tile_x, std::uint32_t tile_y, std::uint8_t raw) {
  if (raw >= kRawClassCount) {
    throw Error(
        fmt::format("tile ({}, {}): raw ID {} is out of range (0..{})", tile_x, tile_y, raw, kRawClassCount - 1));
  }
  throw Error(fmt::format("tile ({}, {}): raw ID {} is impossible (a pruned class)", tile_x, tile_y, raw));
}

}  // namespace tilelight
