#pragma once
// An accessor's elements as numbers, whatever their storage: dense in a buffer view, absent
// (all zeros), and either one with sparse substitutions on top (glTF 2.0 "Sparse Accessors").
// Every byte read is checked against the buffer as loaded; every sparse index is checked to be
// strictly increasing and below the accessor's count. Errors are tilelight::Error naming the
// element at fault ("accessors[3].sparse.indices: ..."), without the file.
//
// What the components may be (type, component type, normalized) is the caller's to check:
// accessor_reader.h does, per use.

#include "tinygltf.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {

// The most elements an accessor without a buffer view may have: nothing in the file bounds
// its count, so this keeps a tiny file from asking for gigabytes of zeros.
inline constexpr std::size_t kMaxZeroAccessorElements = std::size_t{1} << 24;

// Bytes per component of a glTF component type (5120..5126), 0 for any other.
std::size_t component_bytes(int component_type);

// The components of accessor `index` (precondition: it exists), `components` per element,
// element after element, each converted to float: floats as stored, normalized integers to
// -1..1 or 0..1 as glTF defines, other integers as their value.
std::vector<float> read_float_components(const tinygltf::Model& model, int index, std::size_t components);

// The same for unsigned integer components (indices), as their value.
std::vector<std::uint32_t> read_uint_components(const tinygltf::Model& model, int index);

}  // namespace tilelight::gltf_detail
