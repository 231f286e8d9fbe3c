#pragma once
// Reading a glTF accessor's elements for one use (positions, normals, texture coordinates,
// indices), with the formats glTF allows for that use checked and every reference and length
// checked (accessor_elements.h: dense, zero and sparse storage). The 8 and 16-bit integer
// formats of KHR_mesh_quantization are read where the file lists it in extensionsUsed.
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
// VEC3 of 32-bit floats, every component finite; with KHR_mesh_quantization also of signed or
// unsigned 8 or 16-bit integers, normalized or not.
std::vector<glm::vec3> read_positions(const tinygltf::Model& model, int index, const std::string& user);

// Normals: VEC3 of 32-bit floats, every component finite; with KHR_mesh_quantization also of
// normalized signed 8 or 16-bit integers.
std::vector<glm::vec3> read_normals(const tinygltf::Model& model, int index, const std::string& user);

// Texture coordinates (TEXCOORD_n): VEC2 of 32-bit floats, every component finite, or of
// normalized unsigned 8 or 16-bit integers; with KHR_mesh_quantization also of signed or
// unsigned 8 or 16-bit integers, normalized or not.
std::vector<glm::vec2> read_texcoords(const tinygltf::Model& model, int index, const std::string& user);

// Triangle-list indices: SCALAR of unsigned 8, 16 or 32 bits, each below `vertex_count`.
std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& user,
                                        std::size_t vertex_count);

}  // namespace tilelight::gltf_detail
