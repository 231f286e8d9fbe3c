// shard_partition.h - which distinct sources a shard of a domain owns (`build --shard I/N`).
//
// The distinct sources are numbered in the order of their first compile job, which depends on
// the spec and the files it reads only, so every machine numbers them alike. Shard I of N owns
// the contiguous range [floor(I*S/N), floor((I+1)*S/N)) of the S sources: the N ranges are
// disjoint, cover every source, and differ in size by at most one.
#pragma once

#include <cstddef>
#include <cstdint>

namespace shadergen {

struct SourceRange {
  std::size_t first = 0;
  std::size_t last = 0;  // one past the end
};

// Precondition: index < count.
constexpr SourceRange shard_range(std::size_t sources, std::uint32_t index, std::uint32_t count) {
  auto bound = [&](std::uint64_t i) { return static_cast<std::size_t>(i * sources / count); };
  return {bound(index), bound(std::uint64_t{index} + 1)};
}

// The shard that owns source `source`. Preconditions: source < sources, count >= 1.
constexpr std::uint32_t shard_of(std::size_t source, std::size_t sources, std::uint32_t count) {
  return static_cast<std::uint32_t>(((std::uint64_t{source} + 1) * count + sources - 1) / sources - 1);
}

}  // namespace shadergen
