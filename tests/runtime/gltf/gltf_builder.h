#pragma once
// A small glTF 2.0 file built in memory by a test: axis-aligned quads (one node, mesh and material
// each), materials written as JSON, and PNG textures, everything embedded as data URIs, so a test
// states its whole input where it checks the result. Header-only: the loader tests and the frame
// tests both use it.
#include "tilelight/picture/png.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace tilelight::test {

class GltfBuilder {
 public:
  // A quad in the plane z = `z` from `lo` to `hi` (x, y), wound counter-clockwise seen from +z
  // (its front) or, with `facing_away`, from -z, with normals to match. TEXCOORD_0 is (0, 0) at the
  // top left (lo.x, hi.y) and (1, 1) at the bottom right; TEXCOORD_1 is 1 - TEXCOORD_0. `node`:
  // the node's matrix (a negative determinant mirrors the quad).
  void add_quad(glm::vec2 lo, glm::vec2 hi, float z, int material, bool facing_away = false,
                const glm::mat4& node = glm::mat4(1.0f)) {
    const float n = facing_away ? -1.0f : 1.0f;
    Quad q;
    q.positions = {glm::vec3(lo.x, hi.y, z), glm::vec3(lo.x, lo.y, z), glm::vec3(hi.x, lo.y, z),
                   glm::vec3(hi.x, hi.y, z)};
    q.uvs = {glm::vec2(0, 0), glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(1, 0)};
    q.normal = glm::vec3(0, 0, n);
    // Seen from +z, 0 (top left), 1 (bottom left), 2 (bottom right) is counter-clockwise.
    q.indices =
        facing_away ? std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2} : std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3};
    q.material = material;
    q.node = node;
    quads_.push_back(q);
  }

  // A material: the JSON object's members, e.g. R"("alphaMode": "MASK")". Returns its index.
  int add_material(const std::string& members) {
    materials_.push_back("{" + members + "}");
    return static_cast<int>(materials_.size()) - 1;
  }

  // A width x height RGBA8 texture (rows from the top), read with nearest filtering, clamped.
  // Returns its texture index.
  int add_texture(std::uint32_t width, std::uint32_t height, const std::vector<std::uint8_t>& rgba) {
    images_.push_back("data:image/png;base64," + base64(encode_png(width, height, rgba)));
    return static_cast<int>(images_.size()) - 1;
  }

  std::string json() const {
    std::vector<std::uint8_t> buffer;
    std::string accessors, views, meshes, nodes, scene_nodes;
    for (std::size_t k = 0; k < quads_.size(); ++k) {
      const Quad& q = quads_[k];
      std::vector<glm::vec3> normals(4, q.normal);
      std::vector<glm::vec2> flipped;
      for (const glm::vec2& uv : q.uvs) flipped.push_back(glm::vec2(1.0f) - uv);
      const int position = add_view(buffer, views, q.positions.data(), 48);
      const int normal = add_view(buffer, views, normals.data(), 48);
      const int uv0 = add_view(buffer, views, q.uvs.data(), 32);
      const int uv1 = add_view(buffer, views, flipped.data(), 32);
      const int index = add_view(buffer, views, q.indices.data(), 24);
      glm::vec3 lo = q.positions[0], hi = q.positions[0];
      for (const glm::vec3& p : q.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
      append(accessors,
             accessor(position, 4, "VEC3", 5126, ",\"min\":[" + numbers(lo) + "],\"max\":[" + numbers(hi) + "]"));
      append(accessors, accessor(normal, 4, "VEC3", 5126, ""));
      append(accessors, accessor(uv0, 4, "VEC2", 5126, ""));
      append(accessors, accessor(uv1, 4, "VEC2", 5126, ""));
      append(accessors, accessor(index, 6, "SCALAR", 5125, ""));
      const int a = static_cast<int>(k) * 5;
      append(meshes, "{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(a) +
                         ",\"NORMAL\":" + std::to_string(a + 1) + ",\"TEXCOORD_0\":" + std::to_string(a + 2) +
                         ",\"TEXCOORD_1\":" + std::to_string(a + 3) + "},\"indices\":" + std::to_string(a + 4) +
                         ",\"material\":" + std::to_string(q.material) + "}]}");
      append(nodes, "{\"mesh\":" + std::to_string(k) + ",\"matrix\":[" + numbers(q.node) + "]}");
      append(scene_nodes, std::to_string(k));
    }
    std::string images, textures;
    for (std::size_t i = 0; i < images_.size(); ++i) {
      append(images, "{\"uri\":\"" + images_[i] + "\"}");
      append(textures, "{\"source\":" + std::to_string(i) + ",\"sampler\":0}");
    }
    std::string materials;
    for (const std::string& m : materials_) append(materials, m);
    std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[" + scene_nodes + "]}],\"nodes\":[" +
        nodes + "],\"meshes\":[" + meshes + "],\"accessors\":[" + accessors + "],\"bufferViews\":[" + views +
        "],\"buffers\":[{\"byteLength\":" + std::to_string(buffer.size()) +
        ",\"uri\":\"data:application/octet-stream;base64," + base64(buffer) + "\"}],\"materials\":[" + materials + "]";
    if (!images_.empty()) {
      json += ",\"images\":[" + images + "],\"textures\":[" + textures +
              "],\"samplers\":[{\"magFilter\":9728,\"minFilter\":9728,\"wrapS\":33071,\"wrapT\":33071}]";
    }
    return json + "}";
  }

  std::vector<std::uint8_t> bytes() const {
    const std::string text = json();
    return {text.begin(), text.end()};
  }

 private:
  struct Quad {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;
    glm::vec3 normal{};
    std::vector<std::uint32_t> indices;
    int material = 0;
    glm::mat4 node{1.0f};
  };

  static void append(std::string& list, const std::string& item) { list += (list.empty() ? "" : ",") + item; }

  static std::string numbers(glm::vec3 v) {
    return std::to_string(v.x) + "," + std::to_string(v.y) + "," + std::to_string(v.z);
  }

  static std::string numbers(const glm::mat4& m) {  // column-major, as glTF's matrix
    std::string list;
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) append(list, std::to_string(m[c][r]));
    }
    return list;
  }

  static std::string accessor(int view, int count, const char* type, int component, const std::string& extra) {
    return "{\"bufferView\":" + std::to_string(view) + ",\"componentType\":" + std::to_string(component) +
           ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type + "\"" + extra + "}";
  }

  static int add_view(std::vector<std::uint8_t>& buffer, std::string& views, const void* data, std::size_t size) {
    const std::size_t offset = buffer.size();
    buffer.resize(offset + size);
    std::memcpy(buffer.data() + offset, data, size);
    const int index = static_cast<int>(std::count(views.begin(), views.end(), '{'));
    append(views,
           "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) + ",\"byteLength\":" + std::to_string(size) + "}");
    return index;
  }

  static std::string base64(std::span<const std::uint8_t> bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
      const std::uint32_t chunk = (std::uint32_t{bytes[i]} << 16) |
                                  (i + 1 < bytes.size() ? std::uint32_t{bytes[i + 1]} << 8 : 0u) |
                                  (i + 2 < bytes.size() ? std::uint32_t{bytes[i + 2]} : 0u);
      out += kDigits[(chunk >> 18) & 63];
      out += kDigits[(chunk >> 12) & 63];
      out += i + 1 < bytes.size() ? kDigits[(chunk >> 6) & 63] : '=';
      out += i + 2 < bytes.size() ? kDigits[chunk & 63] : '=';
    }
    return out;
  }

  std::vector<Quad> quads_;
  std::vector<std::string> materials_;
  std::vector<std::string> images_;
};

}  // namespace tilelight::test
