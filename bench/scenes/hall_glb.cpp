#include "scenes/hall_glb.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <string>

namespace tilelight::bench {
namespace {

using nlohmann::json;

constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

class BufferWriter {
 public:
  // Appends `bytes` as a buffer view (4-byte aligned) and returns its index.
  int view(const void* bytes, std::size_t size, int target) {
    while (data_.size() % 4 != 0) data_.push_back(0);
    const std::size_t offset = data_.size();
    data_.resize(offset + size);
    std::memcpy(data_.data() + offset, bytes, size);
    views_.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
    return static_cast<int>(views_.size()) - 1;
  }
  const std::vector<std::uint8_t>& data() const { return data_; }
  const json& views() const { return views_; }

 private:
  std::vector<std::uint8_t> data_;
  json views_ = json::array();
};

json vec3(glm::vec3 v) { return json::array({v.x, v.y, v.z}); }

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(value >> (8 * k)));
}

void append_chunk(std::vector<std::uint8_t>& out, std::uint32_t type, std::vector<std::uint8_t> bytes,
                  std::uint8_t pad) {
  while (bytes.size() % 4 != 0) bytes.push_back(pad);
  append_u32(out, static_cast<std::uint32_t>(bytes.size()));
  append_u32(out, type);
  out.insert(out.end(), bytes.begin(), bytes.end());
}

}  // namespace

std::vector<std::uint8_t> encode_hall_glb(const HallScene& hall) {
  BufferWriter buffer;
  json accessors = json::array(), meshes = json::array(), nodes = json::array(), materials = json::array();
  for (const HallMaterial& m : hall.materials)
    materials.push_back({{"name", m.name},
                         {"pbrMetallicRoughness",
                          {{"baseColorFactor", {m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a}},
                           {"metallicFactor", 0.0},
                           {"roughnessFactor", m.roughness}}}});
  for (const HallMesh& mesh : hall.meshes) {
    glm::vec3 lo = mesh.positions.front(), hi = lo;
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const auto count = mesh.positions.size();
    const int first = static_cast<int>(accessors.size());
    accessors.push_back({{"bufferView", buffer.view(mesh.positions.data(), count * 12, kArrayBuffer)},
                         {"componentType", kFloat},
                         {"count", count},
                         {"type", "VEC3"},
                         {"min", vec3(lo)},
                         {"max", vec3(hi)}});
    accessors.push_back({{"bufferView", buffer.view(mesh.normals.data(), count * 12, kArrayBuffer)},
                         {"componentType", kFloat},
                         {"count", count},
                         {"type", "VEC3"}});
    accessors.push_back({{"bufferView", buffer.view(mesh.indices.data(), mesh.indices.size() * 4, kElementArrayBuffer)},
                         {"componentType", kUnsignedInt},
                         {"count", mesh.indices.size()},
                         {"type", "SCALAR"}});
    meshes.push_back({{"name", mesh.name},
                      {"primitives",
                       {{{"attributes", {{"POSITION", first}, {"NORMAL", first + 1}}},
                         {"indices", first + 2},
                         {"material", mesh.material}}}}});
    nodes.push_back({{"name", mesh.name}, {"mesh", meshes.size() - 1}});
  }
  json scene_nodes = json::array();
  for (std::size_t k = 0; k < nodes.size(); ++k) scene_nodes.push_back(k);
  const json document = {{"asset", {{"version", "2.0"}, {"generator", "tilelight_make_hall"}}},
                         {"scene", 0},
                         {"scenes", {{{"name", "hall"}, {"nodes", scene_nodes}}}},
                         {"nodes", nodes},
                         {"meshes", meshes},
                         {"materials", materials},
                         {"accessors", accessors},
                         {"bufferViews", buffer.views()},
                         {"buffers", {{{"byteLength", buffer.data().size()}}}}};
  const std::string text = document.dump();

  std::vector<std::uint8_t> glb;
  append_u32(glb, kGlbMagic);
  append_u32(glb, 2);
  append_u32(glb, 0);  // total length, set below
  append_chunk(glb, kJsonChunk, std::vector<std::uint8_t>(text.begin(), text.end()), ' ');
  append_chunk(glb, kBinChunk, buffer.data(), 0);
  const auto total = static_cast<std::uint32_t>(glb.size());
  for (int k = 0; k < 4; ++k) glb[8 + k] = static_cast<std::uint8_t>(total >> (8 * k));
  return glb;
}

}  // namespace tilelight::bench
