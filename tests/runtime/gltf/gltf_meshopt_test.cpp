// EXT_meshopt_compression: the box with its positions, normals and indices compressed by
// meshoptimizer's encoder (here, from box_external.bin) loads exactly as box.gltf, from a .gltf
// and from a .glb, each with an empty fallback buffer; broken compressed views are errors
// naming the view. TILELIGHT_WRITE_MESHOPT_FIXTURE=1 rewrites tests/fixtures/gltf/box_meshopt.gltf
// (the frame test's file and a fuzz seed) from the same encoding.
#include "compressed_box_support.h"
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace tilelight {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace gltf_meshopt_test {
namespace {

using Json = nlohmann::json;
using namespace test;  // compressed_box_support.h

GltfScene load_box(const std::string& text) { return load_text(text, "box_meshopt.gltf"); }

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;

// The box of box_external.gltf with its three views compressed into buffer 0; buffer 1 is the
// empty fallback. `compressed`: the encoded bytes, for buffer 0.
Json compressed_box(Bytes& compressed) {
  Json doc = Json::parse(read_bytes(kFixtures / "box_external.gltf"));
  const Bytes plain = read_bytes(kFixtures / "box_external.bin");
  compressed.clear();
  for (std::size_t v = 0; v < 3; ++v) {
    Json& view = doc["bufferViews"][v];
    const std::size_t offset = view["byteOffset"], length = view["byteLength"];
    const bool indices = v == 2;
    const std::size_t stride = indices ? 2 : 12, count = length / stride;
    Bytes encoded;
    if (indices) {
      std::vector<unsigned int> values(count);
      for (std::size_t i = 0; i < count; ++i) values[i] = plain[offset + 2 * i] | plain[offset + 2 * i + 1] << 8;
      encoded.resize(meshopt_encodeIndexBufferBound(count, 24));
      encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), values.data(), count));
    } else {
      encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
      encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), plain.data() + offset, count, stride));
    }
    view["buffer"] = 1;
    view["extensions"]["EXT_meshopt_compression"] = {{"buffer", 0},
                                                     {"byteOffset", compressed.size()},
                                                     {"byteLength", encoded.size()},
                                                     {"byteStride", stride},
                                                     {"count", count},
                                                     {"mode", indices ? "TRIANGLES" : "ATTRIBUTES"}};
    compressed.insert(compressed.end(), encoded.begin(), encoded.end());
    compressed.resize((compressed.size() + 3) / 4 * 4);
  }
  doc["buffers"] = Json::array(
      {{{"byteLength", compressed.size()}},
       {{"byteLength", plain.size()}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
  doc["extensionsUsed"] = {"EXT_meshopt_compression"};
  doc["extensionsRequired"] = {"EXT_meshopt_compression"};
  return doc;
}

std::string embedded_box() {
  Bytes compressed;
  Json doc = compressed_box(compressed);
  doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(compressed);
  return doc.dump(1) + "\n";
}

Bytes glb_box() {
  Bytes compressed;
  const std::string json = compressed_box(compressed).dump();
  return glb(json, compressed);
}

TEST(GltfMeshopt, ACompressedGltfLoadsAsTheBox) {
  const std::string text = embedded_box();
  if (std::getenv("TILELIGHT_WRITE_MESHOPT_FIXTURE") != nullptr) {
    std::ofstream(kFixtures / "box_meshopt.gltf", std::ios::binary) << text;
  }
  const GltfScene loaded = load_box(text);
  expect_box(loaded.scene);
  EXPECT_EQ(loaded.warnings, std::vector<std::string>{});
}

TEST(GltfMeshopt, ACompressedGlbWithAnEmptyFallbackBufferLoadsAsTheBox) {
  const Bytes glb = glb_box();
  expect_box(load_gltf_from_memory(glb, "box_meshopt.glb", {}).scene);
}

// Normals as gltfpack stores them: 8-bit octahedral (KHR_mesh_quantization's normalized
// bytes), compressed with the OCTAHEDRAL filter.
TEST(GltfMeshopt, OctahedralFilteredNormalsLoadAsTheBoxNormals) {
  Bytes compressed;
  Json doc = compressed_box(compressed);
  const Bytes plain = read_bytes(kFixtures / "box_external.bin");
  Json& view = doc["bufferViews"][1];
  const std::size_t offset = view["byteOffset"], count = 24, stride = 4;
  std::vector<float> normals(count * 4, 0.0f);
  for (std::size_t i = 0; i < count; ++i) std::memcpy(&normals[i * 4], plain.data() + offset + i * 12, 12);
  Bytes filtered(count * stride);
  meshopt_encodeFilterOct(filtered.data(), count, stride, 8, normals.data());
  Bytes encoded(meshopt_encodeVertexBufferBound(count, stride));
  encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), filtered.data(), count, stride));
  view["byteLength"] = count * stride;
  view["byteStride"] = stride;
  view["extensions"]["EXT_meshopt_compression"] = {{"buffer", 0},
                                                   {"byteOffset", compressed.size()},
                                                   {"byteLength", encoded.size()},
                                                   {"byteStride", stride},
                                                   {"count", count},
                                                   {"mode", "ATTRIBUTES"},
                                                   {"filter", "OCTAHEDRAL"}};
  compressed.insert(compressed.end(), encoded.begin(), encoded.end());
  doc["accessors"][1]["componentType"] = 5120;
  doc["accessors"][1]["normalized"] = true;
  doc["extensionsUsed"].push_back("KHR_mesh_quantization");
  doc["buffers"][0]["byteLength"] = compressed.size();
  doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(compressed);

  const Scene scene = load_box(doc.dump()).scene;
  const Scene box = load_gltf_scene(kFixtures / "box.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.meshes[0].vertices.size(), box.meshes[0].vertices.size());
  for (std::size_t i = 0; i < box.meshes[0].vertices.size(); ++i) {
    EXPECT_EQ(scene.meshes[0].vertices[i].position, box.meshes[0].vertices[i].position) << i;
    const glm::vec3 n = scene.meshes[0].vertices[i].normal, expected = box.meshes[0].vertices[i].normal;
    EXPECT_NEAR(glm::dot(n, expected), 1.0f, 1e-5f) << i << ": the filter was not undone";
  }
}

TEST(GltfMeshopt, TheCheckedInFixtureLoadsAsTheBox) { expect_box(load_gltf_scene(kFixtures / "box_meshopt.gltf")); }

struct BadView {
  const char* name;
  void (*change)(Json& doc);
  const char* message;  // after "box_meshopt.gltf: "
};

void PrintTo(const BadView& b, std::ostream* os) { *os << b.name; }

class GltfMeshoptBadInput : public ::testing::TestWithParam<BadView> {};

TEST_P(GltfMeshoptBadInput, IsAnErrorNamingTheView) {
  Json doc = Json::parse(embedded_box());
  GetParam().change(doc);
  try {
    (void)load_box(doc.dump());
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), std::string("box_meshopt.gltf: ") + GetParam().message);
  }
}

std::string view_name(const ::testing::TestParamInfo<BadView>& info) { return info.param.name; }

Json& extension(Json& doc, int view) { return doc["bufferViews"][view]["extensions"]["EXT_meshopt_compression"]; }

INSTANTIATE_TEST_SUITE_P(
    Views, GltfMeshoptBadInput,
    ::testing::Values(
        BadView{"unknown_mode", [](Json& d) { extension(d, 0)["mode"] = "QUADS"; },
                "bufferViews[0].extensions.EXT_meshopt_compression.mode: \"QUADS\" is not ATTRIBUTES, TRIANGLES or "
                "INDICES"},
        BadView{"odd_stride",
                [](Json& d) {
                  extension(d, 0)["byteStride"] = 6;
                  extension(d, 0)["count"] = 48;
                },
                "bufferViews[0].extensions.EXT_meshopt_compression.byteStride: 6 (ATTRIBUTES needs a multiple of 4 "
                "up to 256)"},
        BadView{"wrong_count", [](Json& d) { extension(d, 0)["count"] = 25; },
                "bufferViews[0].extensions.EXT_meshopt_compression: count 25 x byteStride 12 is 300 bytes, but the "
                "view's byteLength is 288"},
        BadView{"missing_buffer", [](Json& d) { extension(d, 1)["buffer"] = 7; },
                "bufferViews[1].extensions.EXT_meshopt_compression.buffer: buffer 7 does not exist (the file has 2)"},
        BadView{
            "past_the_buffer", [](Json& d) { extension(d, 2)["byteOffset"] = 4000; },
            "bufferViews[2].extensions.EXT_meshopt_compression: bytes 4000..4029 are past the end of buffers[0], which "
            "has 216 bytes"},
        BadView{"truncated",
                [](Json& d) { extension(d, 0)["byteLength"] = extension(d, 0)["byteLength"].get<int>() - 8; },
                "bufferViews[0].extensions.EXT_meshopt_compression: the compressed data is corrupt (meshoptimizer's "
                "decoder returned -3)"},
        BadView{"filter_on_indices", [](Json& d) { extension(d, 2)["filter"] = "OCTAHEDRAL"; },
                "bufferViews[2].extensions.EXT_meshopt_compression.filter: only ATTRIBUTES may be filtered"},
        BadView{"not_a_string", [](Json& d) { extension(d, 2)["mode"] = 4; },
                "bufferViews[2].extensions.EXT_meshopt_compression.mode: expected a string"},
        BadView{"uncompressed_view_of_the_fallback", [](Json& d) { d["bufferViews"][0].erase("extensions"); },
                "bufferViews[0]: bytes 0..288 are past the end of buffers[1], which has 4 bytes"}),
    view_name);

}  // namespace
}  // namespace gltf_meshopt_test
}  // namespace tilelight
