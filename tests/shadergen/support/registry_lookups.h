// Every lookup by raw ID, of shadergen::Registry and of a generated header, for every raw ID of
// a domain and for IDs past its end: a valid ID finds its permutation, a pruned one or one out
// of range finds none (nullptr, nullopt, false), and nothing reads past a table (the sanitizer
// build runs these tests too). Each fixture registry test calls it with its generated names.
//
// Header-only, like registry_digests.h: the registry tests link only the generated code.
#pragma once

#include <gtest/gtest.h>
#include <shadergen/registry.h>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace registry_lookups {

// The generated header's tables and checked lookups, by address.
struct Generated {
  std::uint32_t raw_count;                    // kRawCount
  std::span<const bool> pruned;               // kRawPruned
  std::span<const std::uint8_t> table;        // kRawToOptimised; empty when the domain is not collapsed
  bool (*is_valid_raw_id)(shadergen::RawId);  // is_valid_raw_id
  std::optional<shadergen::OptimisedId> (*optimised_id)(shadergen::RawId);  // optimised_id
};

struct Counts {
  std::size_t valid = 0;
  std::size_t pruned = 0;
  std::size_t out_of_range = 0;
};

// Past the end of any domain: the first ID out, one further, the top bit, the largest.
inline std::array<std::uint32_t, 4> out_of_range_ids(std::uint32_t raw_count) {
  return {raw_count, raw_count + 16, 0x80000000u, 0xffffffffu};
}

inline void expect_none(const shadergen::Registry& r, const Generated& g, std::uint32_t value) {
  SCOPED_TRACE("raw " + std::to_string(value));
  const shadergen::RawId id(value);
  EXPECT_EQ(r.find_raw(id), nullptr);
  EXPECT_EQ(r.optimised_id(id), std::nullopt);
  EXPECT_EQ(r.optimised_for_raw(id), nullptr);
  EXPECT_FALSE(g.is_valid_raw_id(id));
  EXPECT_EQ(g.optimised_id(id), std::nullopt);
}

inline void expect_found(const shadergen::Registry& r, const Generated& g, std::uint32_t value) {
  SCOPED_TRACE("raw " + std::to_string(value));
  const shadergen::RawId id(value);
  EXPECT_EQ(r.find_raw(id), &r.raw[value]);
  EXPECT_TRUE(g.is_valid_raw_id(id));
  // Not collapsed: every raw ID is its own permutation.
  const std::uint32_t expected = g.table.empty() ? value : g.table[value];
  EXPECT_EQ(r.optimised_id(id), shadergen::OptimisedId(expected));
  EXPECT_EQ(g.optimised_id(id), shadergen::OptimisedId(expected));
  EXPECT_EQ(r.optimised_for_raw(id), g.table.empty() ? &r.raw[value] : &r.optimised[expected]);
}

// Checks every lookup for every ID of the domain and a few past it.
inline Counts expect_checked_lookups(const shadergen::Registry& r, const Generated& g) {
  Counts counts;
  EXPECT_EQ(r.raw.size(), g.raw_count);
  EXPECT_EQ(g.pruned.size(), g.raw_count);
  for (std::uint32_t id = 0; id < g.raw_count; ++id) {
    if (g.pruned[id]) {
      expect_none(r, g, id);
      ++counts.pruned;
    } else {
      expect_found(r, g, id);
      ++counts.valid;
    }
  }
  for (std::uint32_t id : out_of_range_ids(g.raw_count)) {
    expect_none(r, g, id);
    ++counts.out_of_range;
  }
  return counts;
}

}  // namespace registry_lookups
