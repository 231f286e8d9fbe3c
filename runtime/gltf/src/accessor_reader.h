#pragma once
// Reading a glTF accessor's elements with every reference and length checked: the accessor,
// its buffer view and buffer exist, the elements lie inside the view and the view inside the
// buffer's bytes (as loaded, not as "byteLength" claims), the stride holds an element.
// Errors are tilelight::Error naming the accessor ("accessors[3]: ..."), without the file.

#include "tinygltf.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {

// The bytes of buffer view `index`, which `user` ("accessors[3]", "images[0]") refers to: the
// view and its buffer exist and the view lies inside the buffer's bytes as loaded.
std::span<const std::uint8_t> buffer_view_bytes(const tinygltf::Model& model, int index, const std::string& user);

// The accessor `index`, which `user` ("meshes[0].primitives[1].attributes.POSITION") refers to.
// Must be VEC3 of 32-bit floats, every component finite.
std::vector<glm::vec3> read_vec3(const tinygltf::Model& model, int index, const std::string& user);

// Texture coordinates (TEXCOORD_n): VEC2 of 32-bit floats, every component finite, or of
// normalised unsigned 8 or 16-bit integers (read as value / 255 or / 65535).
std::vector<glm::vec2> read_texcoords(const tinygltf::Model& model, int index, const std::string& user);

// Triangle-list indices: SCALAR of unsigned 8, 16 or 32 bits, each below `vertex_count`.
std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& user,
                                        std::size_t vertex_count);

}  // namespace tilelight::gltf_detail
