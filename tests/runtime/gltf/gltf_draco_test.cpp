// KHR_draco_mesh_compression: the box, its positions, normals and indices encoded by libdraco's
// encoder (sequential connectivity, no quantization: lossless and in the same vertex order),
// loads exactly as box.gltf; assimp's Draco engine loads; broken extensions, streams and
// accessors are errors naming the element. TILELIGHT_WRITE_DRACO_FIXTURE=1 rewrites
// tests/fixtures/gltf/box_draco.gltf (a checked-in copy) and the fuzz seeds
// tests/fuzz/corpus/gltf/seed-box_draco.gltf and seed-bad_draco_*.gltf (one a broken case).
#include "compressed_box_support.h"
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace tilelight {
namespace {

using Json = nlohmann::json;
using namespace test;  // compressed_box_support.h

GltfScene load_box(const std::string& text) { return load_text(text, "box_draco.gltf"); }

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;
const std::filesystem::path kCorpus = TILELIGHT_GLTF_CORPUS;
const std::filesystem::path kAssimpModels = TILELIGHT_ASSIMP_GLTF2_MODELS;

constexpr std::uint32_t kVertices = 24, kIndices = 36;

// A float VEC3 attribute of the box's kVertices vertices, from box_external.bin at `offset`.
int add_vec3(draco::Mesh& mesh, draco::GeometryAttribute::Type type, const Bytes& plain, std::size_t offset) {
  draco::GeometryAttribute attribute;
  attribute.Init(type, nullptr, 3, draco::DT_FLOAT32, false, 12, 0);
  const int id = mesh.AddAttribute(attribute, true, kVertices);
  for (std::uint32_t i = 0; i < kVertices; ++i) {
    mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(i), plain.data() + offset + 12 * i);
  }
  return id;
}

// The Draco stream of box_external.bin's box: POSITION is Draco attribute 0, NORMAL 1.
// `as_exporters_write`: edgebreaker connectivity (which reorders vertices) and quantized
// attributes, instead of the sequential, lossless encoding.
Bytes encoded_box(bool as_exporters_write = false) {
  const Bytes plain = read_bytes(kFixtures / "box_external.bin");
  draco::Mesh mesh;
  mesh.set_num_points(kVertices);
  add_vec3(mesh, draco::GeometryAttribute::POSITION, plain, 0);
  add_vec3(mesh, draco::GeometryAttribute::NORMAL, plain, 288);
  for (std::uint32_t f = 0; f < kIndices / 3; ++f) {
    draco::Mesh::Face face;
    for (int c = 0; c < 3; ++c) {
      const std::size_t at = 576 + 2 * (3 * f + c);
      face[c] = draco::PointIndex(plain[at] | plain[at + 1] << 8);
    }
    mesh.AddFace(face);
  }
  draco::Encoder encoder;
  if (as_exporters_write) {
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
  } else {
    encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
  }
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &buffer);
  EXPECT_TRUE(status.ok()) << status.error_msg();
  return Bytes(buffer.data(), buffer.data() + buffer.size());
}

// box_external.gltf with its three accessors decoded from one Draco stream, embedded.
// `edit`: a change to the stream's bytes, for the broken cases.
Json draco_box(bool as_exporters_write = false, void (*edit)(Bytes&) = nullptr) {
  Json doc = Json::parse(read_bytes(kFixtures / "box_external.gltf"));
  Bytes stream = encoded_box(as_exporters_write);
  if (edit != nullptr) edit(stream);
  for (Json& accessor : doc["accessors"]) accessor.erase("bufferView");
  doc["bufferViews"] = Json::array({{{"buffer", 0}, {"byteLength", stream.size()}}});
  doc["buffers"] =
      Json::array({{{"byteLength", stream.size()}, {"uri", "data:application/octet-stream;base64," + base64(stream)}}});
  doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
      {"bufferView", 0}, {"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}};
  doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  return doc;
}

// The same box as a .glb, the Draco stream its BIN chunk.
Bytes glb_box() {
  Json doc = draco_box();
  doc["buffers"][0].erase("uri");
  return glb(doc.dump(), encoded_box());
}

TEST(GltfDraco, ADracoBoxLoadsAsTheBox) {
  const std::string text = draco_box().dump(1) + "\n";
  if (std::getenv("TILELIGHT_WRITE_DRACO_FIXTURE") != nullptr) {
    std::ofstream(kFixtures / "box_draco.gltf", std::ios::binary) << text;
    std::ofstream(kCorpus / "seed-box_draco.gltf", std::ios::binary) << text;
  }
  const GltfScene loaded = load_box(text);
  expect_box(loaded.scene);
  EXPECT_EQ(loaded.warnings, std::vector<std::string>{});
}

// The loader rewrites the JSON (the indices accessor gets a view for tinygltf) and re-assembles
// the .glb around the BIN chunk.
TEST(GltfDraco, ADracoGlbLoadsAsTheBox) {
  const Bytes glb = glb_box();
  expect_box(load_gltf_from_memory(glb, "box_draco.glb", {}).scene);
}

// Whether `a` and `b` are the same triangle, up to a rotation of its corners (so the winding
// is kept), within `tolerance`.
bool same_triangle(const std::array<glm::vec3, 3>& a, const std::array<glm::vec3, 3>& b, float tolerance) {
  for (int r = 0; r < 3; ++r) {
    bool all = true;
    for (int c = 0; c < 3; ++c)
      all = all && glm::all(glm::lessThanEqual(glm::abs(a[c] - b[(c + r) % 3]), glm::vec3(tolerance)));
    if (all) return true;
  }
  return false;
}

std::vector<std::array<glm::vec3, 3>> triangles_of(const Mesh& mesh) {
  std::vector<std::array<glm::vec3, 3>> out;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    out.push_back({mesh.vertices[mesh.indices[i]].position, mesh.vertices[mesh.indices[i + 1]].position,
                   mesh.vertices[mesh.indices[i + 2]].position});
  }
  return out;
}

// Edgebreaker reorders the vertices and 14-bit quantization moves them by under 1e-4 of the
// box's size: every triangle of the box is still there, with its winding.
TEST(GltfDraco, AnEdgebreakerQuantizedBoxHasTheBoxsTriangles) {
  const Scene scene = load_box(draco_box(true).dump()).scene;
  const Scene box = load_gltf_scene(kFixtures / "box.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  const auto decoded = triangles_of(scene.meshes[0]), expected = triangles_of(box.meshes[0]);
  ASSERT_EQ(decoded.size(), expected.size());
  for (std::size_t t = 0; t < expected.size(); ++t) {
    EXPECT_TRUE(std::any_of(decoded.begin(), decoded.end(),
                            [&](const auto& d) { return same_triangle(d, expected[t], 1e-3f); }))
        << "triangle " << t << " is missing";
  }
  for (const auto& v : scene.meshes[0].vertices) EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-3f);
}

TEST(GltfDraco, TheCheckedInFixtureLoadsAsTheBox) { expect_box(load_gltf_scene(kFixtures / "box_draco.gltf")); }

// assimp-testmodels' engine: 34 primitives in 29 meshes, each a Draco stream of indices,
// positions and normals, 65,311 triangles in all (the indices accessors' counts).
TEST(GltfDraco, AssimpsDracoEngineLoads) {
  const GltfScene loaded = load_gltf(kAssimpModels / "draco/2CylinderEngine.gltf");
  EXPECT_EQ(loaded.scene.meshes.size(), 34u);
  std::size_t triangles = 0;
  for (const Mesh& mesh : loaded.scene.meshes) triangles += mesh.indices.size() / 3;
  EXPECT_EQ(triangles, 65311u);
  // The extension is not among what is ignored, and the file's camera (placed by a node) can
  // be chosen: nothing to warn of.
  EXPECT_EQ(loaded.warnings, std::vector<std::string>{});
}

struct BadDraco {
  const char* name;
  void (*change)(Json& doc);
  const char* message;  // after "box_draco.gltf: "
};

void PrintTo(const BadDraco& b, std::ostream* os) { *os << b.name; }

class GltfDracoBadInput : public ::testing::TestWithParam<BadDraco> {};

TEST_P(GltfDracoBadInput, IsAnErrorNamingTheElement) {
  Json doc = draco_box();
  GetParam().change(doc);
  if (std::getenv("TILELIGHT_WRITE_DRACO_FIXTURE") != nullptr) {
    std::ofstream(kCorpus / (std::string("seed-bad_draco_") + GetParam().name + ".gltf"), std::ios::binary)
        << doc.dump(1) << "\n";
  }
  try {
    (void)load_box(doc.dump());
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), std::string("box_draco.gltf: ") + GetParam().message);
  }
}

std::string bad_name(const ::testing::TestParamInfo<BadDraco>& info) { return info.param.name; }

Json& primitive(Json& doc) { return doc["meshes"][0]["primitives"][0]; }
Json& extension(Json& doc) { return primitive(doc)["extensions"]["KHR_draco_mesh_compression"]; }

// The sequential box's header: "DRACO", version 2.2, mesh, sequential, flags 0 (bytes 0-10),
// then varint faces (byte 11: 12) and points (byte 12: 24).
void with_stream(Json& doc, void (*edit)(Bytes&)) { doc = draco_box(false, edit); }

#define DRACO_PATH "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression"

INSTANTIATE_TEST_SUITE_P(
    Primitives, GltfDracoBadInput,
    ::testing::Values(
        BadDraco{"not_an_object", [](Json& d) { extension(d) = 3; }, DRACO_PATH ": expected an object, got an integer"},
        BadDraco{"no_buffer_view", [](Json& d) { extension(d).erase("bufferView"); },
                 DRACO_PATH ".bufferView: missing (required)"},
        BadDraco{"buffer_view_missing", [](Json& d) { extension(d)["bufferView"] = 9; },
                 DRACO_PATH ".bufferView: buffer view 9 does not exist (the file has 1)"},
        BadDraco{"attributes_not_an_object", [](Json& d) { extension(d)["attributes"] = Json::array(); },
                 DRACO_PATH ".attributes: expected an object"},
        BadDraco{"attribute_not_listed", [](Json& d) { extension(d)["attributes"]["TEXCOORD_0"] = 2; },
                 DRACO_PATH ".attributes.TEXCOORD_0: not one of the primitive's attributes"},
        BadDraco{"negative_id", [](Json& d) { extension(d)["attributes"]["POSITION"] = -1; },
                 DRACO_PATH ".attributes.POSITION: expected a non-negative integer"},
        BadDraco{"id_not_in_stream", [](Json& d) { extension(d)["attributes"]["POSITION"] = 7; },
                 DRACO_PATH ".attributes.POSITION: Draco attribute 7 is not in the compressed data"},
        BadDraco{"points", [](Json& d) { primitive(d)["mode"] = 0; },
                 "meshes[0].primitives[0].mode: a Draco-compressed primitive must be TRIANGLES (4)"},
        BadDraco{"no_indices", [](Json& d) { primitive(d).erase("indices"); },
                 "meshes[0].primitives[0].indices: missing (a Draco-compressed primitive needs its indices "
                 "accessor)"},
        BadDraco{"view_past_its_buffer", [](Json& d) { d["bufferViews"][0]["byteOffset"] = 8; },
                 DRACO_PATH
                 ".bufferView: bytes 8..648 of bufferViews[0] are past the end of buffers[0], which has 640 bytes"},
        BadDraco{"truncated",
                 [](Json& d) { d["bufferViews"][0]["byteLength"] = d["bufferViews"][0]["byteLength"].get<int>() - 40; },
                 DRACO_PATH ": the compressed data is corrupt (libdraco: Failed to decode point attributes.)"},
        BadDraco{"not_a_draco_stream",
                 [](Json& d) {
                   d["bufferViews"][0]["byteOffset"] = 4;
                   d["bufferViews"][0]["byteLength"] = d["bufferViews"][0]["byteLength"].get<int>() - 4;
                 },
                 DRACO_PATH ": not a Draco stream (it does not start with \"DRACO\")"},
        BadDraco{"vertex_count", [](Json& d) { d["accessors"][0]["count"] = 25; },
                 DRACO_PATH
                 ".attributes.POSITION: the Draco stream declares 24 vertices, but accessors[0] has count 25"},
        BadDraco{"index_count", [](Json& d) { d["accessors"][2]["count"] = 33; },
                 DRACO_PATH ": the Draco stream declares 12 triangles, but accessors[2] has count 33"},
        BadDraco{"index_count_not_triangles", [](Json& d) { d["accessors"][2]["count"] = 35; },
                 DRACO_PATH ": the indices accessor's count 35 is not 3 x at most 16777216 triangles"},
        BadDraco{"vertex_count_huge", [](Json& d) { d["accessors"][1]["count"] = 1 << 25; },
                 DRACO_PATH ".attributes.NORMAL: count 33554432 is more than this loader decodes (16777216 "
                            "vertices)"},
        BadDraco{
            "normal_as_vec2", [](Json& d) { d["accessors"][1]["type"] = "VEC2"; },
            DRACO_PATH
            ".attributes.NORMAL: decodes to 3 float32 components a vertex, which do not fit accessors[1] (2 FLOAT)"},
        BadDraco{
            "position_as_shorts", [](Json& d) { d["accessors"][0]["componentType"] = 5122; },
            DRACO_PATH
            ".attributes.POSITION: decodes to 3 float32 components a vertex, which do not fit accessors[0] (3 SHORT)"},
        BadDraco{"old_version", [](Json& d) { with_stream(d, [](Bytes& b) { b[6] = 1; }); },
                 DRACO_PATH ": Draco bitstream version 2.1; this loader reads 2.2 (Draco 1.3 and later)"},
        BadDraco{"point_cloud", [](Json& d) { with_stream(d, [](Bytes& b) { b[7] = 0; }); },
                 DRACO_PATH ": the Draco stream is not a triangle mesh (encoder type 0)"},
        BadDraco{"metadata", [](Json& d) { with_stream(d, [](Bytes& b) { b[10] = 0x80; }); },
                 DRACO_PATH ": the Draco stream carries metadata, which this loader does not read"},
        BadDraco{"header_cut_short", [](Json& d) { d["bufferViews"][0]["byteLength"] = 12; },
                 DRACO_PATH ": the Draco stream ends inside its header"},
        BadDraco{"claims_four_billion_triangles",
                 [](Json& d) {
                   with_stream(d, [](Bytes& b) {
                     b.erase(b.begin() + 11);
                     b.insert(b.begin() + 11, {0xFF, 0xFF, 0xFF, 0xFF, 0x0F});
                   });
                 },
                 DRACO_PATH ": the Draco stream declares 4294967295 triangles, but accessors[2] has count 36"},
        BadDraco{"overlong_varint",
                 [](Json& d) {
                   with_stream(d, [](Bytes& b) { b.insert(b.begin() + 11, {0x80, 0x80, 0x80, 0x80, 0x80}); });
                 },
                 DRACO_PATH ": a count in the Draco header is longer than 5 bytes"},
        BadDraco{"float_indices", [](Json& d) { d["accessors"][2]["componentType"] = 5126; },
                 DRACO_PATH ": accessors[2] is not an unsigned integer scalar"}),
    bad_name);

}  // namespace
}  // namespace tilelight
