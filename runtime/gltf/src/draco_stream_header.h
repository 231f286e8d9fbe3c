#pragma once
// The counts a Draco stream declares, read from its first bytes before libdraco sees it, so a
// stream that claims more triangles or vertices than its accessors hold (and would make
// libdraco allocate for them) is refused first. Read: bitstream version 2.2 (what Draco 1.3
// and later write), a triangle mesh, sequential or edgebreaker connectivity, no metadata.
// Layout (Draco's bitstream specification): "DRACO", major, minor, encoder type (1: mesh),
// method (0: sequential, 1: edgebreaker), flags (uint16, 0x8000: metadata); then sequential:
// varint faces, varint points; edgebreaker: a traversal byte, varint vertices, varint faces.

#include <cstdint>
#include <span>
#include <string>

namespace tilelight::gltf_detail {

struct DracoStreamCounts {
  std::uint64_t faces = 0;
  std::uint64_t vertices = 0;       // sequential: the points; edgebreaker: the encoded positions,
  bool vertices_are_points = true;  // at most the points (a seam splits a position into several)
};

// Throws tilelight::Error prefixed with `path` for a stream this loader does not read.
DracoStreamCounts draco_stream_counts(std::span<const std::uint8_t> stream, const std::string& path);

}  // namespace tilelight::gltf_detail
