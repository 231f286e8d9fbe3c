#include "compressed_box_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace tilelight::test {
namespace {

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;

void append_u32(Bytes& out, std::size_t value) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

}  // namespace

Bytes read_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), {}};
}

std::string base64(const Bytes& data) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < data.size(); i += 3) {
    const std::uint32_t n =
        data[i] << 16 | (i + 1 < data.size() ? data[i + 1] << 8 : 0) | (i + 2 < data.size() ? data[i + 2] : 0);
    for (std::size_t k = 0; k < 4; ++k) out += k <= data.size() - i ? kDigits[(n >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

Bytes glb(std::string json, Bytes bin) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, 0);
  Bytes out;
  append_u32(out, 0x46546C67);  // "glTF"
  append_u32(out, 2);
  append_u32(out, 12 + 8 + json.size() + 8 + bin.size());
  append_u32(out, json.size());
  append_u32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  append_u32(out, bin.size());
  append_u32(out, 0x004E4942);  // "BIN"
  out.insert(out.end(), bin.begin(), bin.end());
  return out;
}

GltfScene load_text(const std::string& text, const std::string& name) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.data());
  return load_gltf_from_memory({bytes, text.size()}, name, {});
}

void expect_box(const Scene& scene) {
  const Scene box = load_gltf_scene(kFixtures / "box.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].indices, box.meshes[0].indices);
  ASSERT_EQ(scene.meshes[0].vertices.size(), box.meshes[0].vertices.size());
  for (std::size_t i = 0; i < box.meshes[0].vertices.size(); ++i) {
    EXPECT_EQ(scene.meshes[0].vertices[i].position, box.meshes[0].vertices[i].position) << i;
    EXPECT_EQ(scene.meshes[0].vertices[i].normal, box.meshes[0].vertices[i].normal) << i;
  }
  ASSERT_EQ(scene.instances.size(), box.instances.size());
  for (std::size_t i = 0; i < box.instances.size(); ++i) EXPECT_EQ(scene.instances[i].model, box.instances[i].model);
}

}  // namespace tilelight::test
