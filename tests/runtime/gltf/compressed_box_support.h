#pragma once
// What the tests of compressed geometry share (gltf_meshopt_test.cpp, gltf_draco_test.cpp): the
// bytes of box.gltf's buffer, a buffer as a data URI's base64, a .glb made of a JSON chunk and a
// BIN chunk, loading a file given as text, and the check that a scene is box.gltf's.

#include "tilelight/gltf/load_gltf.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tilelight::test {

using Bytes = std::vector<std::uint8_t>;

Bytes read_bytes(const std::filesystem::path& path);
std::string base64(const Bytes& data);

// A glTF 2.0 binary: `json` then `bin` (each padded to 4 bytes, JSON with spaces).
Bytes glb(std::string json, Bytes bin);

GltfScene load_text(const std::string& text, const std::string& name);

// Expects `scene` to hold box.gltf's one mesh (indices, positions and normals exactly) and
// its instances.
void expect_box(const Scene& scene);

}  // namespace tilelight::test
