// The geometry real files use: sparse accessors (every kind of storage: replaced elements of a
// buffer view, an accessor of zeros, indices) and KHR_mesh_quantization's 8 and 16-bit
// attributes, each loading exactly as the float file it was made from
// (tests/fixtures/gltf/make_fixtures.py), and their broken forms refused with the whole message.
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>

#include <string>

namespace tilelight {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace gltf_geometry_test {
namespace {

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;

Scene load(const std::string& name) { return load_gltf_scene(kFixtures / name); }

// The same meshes, vertex for vertex and index for index, and the same instances.
void expect_same_scene(const Scene& scene, const Scene& reference) {
  ASSERT_EQ(scene.meshes.size(), reference.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& a = scene.meshes[m];
    const Mesh& b = reference.meshes[m];
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
      EXPECT_EQ(a.vertices[i].position, b.vertices[i].position) << "vertex " << i;
      EXPECT_EQ(a.vertices[i].normal, b.vertices[i].normal) << "vertex " << i;
      EXPECT_EQ(a.vertices[i].uv, b.vertices[i].uv) << "vertex " << i;
    }
    EXPECT_EQ(a.base_colour_texture, b.base_colour_texture);
  }
  ASSERT_EQ(scene.instances.size(), reference.instances.size());
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    EXPECT_EQ(scene.instances[i].model, reference.instances[i].model);
  EXPECT_EQ(scene.textures.size(), reference.textures.size());
}

TEST(GltfGeometry, SparseAccessorsLoadAsTheDenseFile) {
  // Without the substitutions the box would have (9, 9, 9) corners, zero normals and three
  // indices 0: the file only equals box.gltf when every one is applied.
  expect_same_scene(load("box_sparse.gltf"), load("box.gltf"));
}

TEST(GltfGeometry, QuantizedAttributesLoadAsTheFloatFile) {
  const Scene reference = load("textured_quad.gltf");
  for (const char* name : {"textured_quad_quantized.gltf", "textured_quad_quantized_bytes.gltf"}) {
    SCOPED_TRACE(name);
    expect_same_scene(load(name), reference);
  }
}

struct BadGeometry {
  const char* file;
  const char* message;  // the whole message after "<path>: "
};

void PrintTo(const BadGeometry& b, std::ostream* os) { *os << b.file; }

class GltfBadGeometry : public ::testing::TestWithParam<BadGeometry> {};

TEST_P(GltfBadGeometry, IsAnErrorNamingTheFileAndTheElement) {
  const std::filesystem::path path = kFixtures / GetParam().file;
  try {
    (void)load_gltf_scene(path);
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": " + GetParam().message);
  }
}

std::string name_of(const ::testing::TestParamInfo<BadGeometry>& info) {
  std::string name = info.param.file;
  return name.substr(0, name.find('.'));
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, GltfBadGeometry,
    ::testing::Values(
        BadGeometry{
            "bad_sparse_index_range.gltf",
            "accessors[0].sparse.indices: index 24 at element 3 is out of range (the accessor has 24 elements)"},
        BadGeometry{"bad_sparse_index_order.gltf",
                    "accessors[0].sparse.indices: index 5 at element 2 does not increase (the one before is 10)"},
        BadGeometry{"bad_sparse_index_repeated.gltf",
                    "accessors[0].sparse.indices: index 5 at element 2 does not increase (the one before is 5)"},
        BadGeometry{"bad_sparse_count.gltf",
                    "accessors[0].sparse.count: 25 elements replaced, but the accessor has 24 (1 to 24 may be)"},
        BadGeometry{"bad_sparse_count_zero.gltf",
                    "accessors[0].sparse.count: 0 elements replaced, but the accessor has 24 (1 to 24 may be)"},
        BadGeometry{"bad_sparse_count_huge.gltf",
                    "accessors[0].sparse.count: expected a non-negative integer below 2^31, got an integer"},
        BadGeometry{"bad_sparse_values_range.gltf",
                    "accessors[0].sparse.values: 4 elements of 12 bytes, 12 apart, from byte 40 do not fit in "
                    "bufferViews[4] (48 bytes)"},
        BadGeometry{"bad_sparse_indices_range.gltf",
                    "accessors[0].sparse.indices: 4 elements of 1 bytes, 1 apart, from byte 2 do not fit in "
                    "bufferViews[3] (4 bytes)"},
        BadGeometry{"bad_sparse_indices_type.gltf",
                    "accessors[0].sparse.indices.componentType: 5126 is not an unsigned 8, 16 or 32-bit integer type"},
        BadGeometry{"bad_sparse_indices_stride.gltf",
                    "bufferViews[3] (used by accessors[0].sparse.indices): byteStride 4 is not allowed here: sparse "
                    "data is tightly packed"},
        BadGeometry{"bad_sparse_view_missing.gltf",
                    "accessors[0].sparse.values: bufferView 99 does not exist (the file has 9)"},
        BadGeometry{"bad_sparse_vertex_index.gltf",
                    "accessors[2] (used as meshes[0].primitives[0].indices): index 99 at element 7 is out of range "
                    "(the primitive has 24 vertices)"},
        BadGeometry{"bad_zero_accessor_huge.gltf",
                    "accessors[1]: 33554432 elements without a bufferView, more than this loader makes (16777216)"},
        BadGeometry{"bad_quantized_not_listed.gltf",
                    "accessors[0] (used as meshes[0].primitives[0].attributes.POSITION): VEC3 of signed 16-bit "
                    "integers (normalized) needs KHR_mesh_quantization, which the file does not list in "
                    "extensionsUsed"},
        BadGeometry{"bad_quantized_normal.gltf",
                    "accessors[1] (used as meshes[0].primitives[0].attributes.NORMAL): expected VEC3 of 32-bit floats "
                    "(or, with KHR_mesh_quantization, of normalized signed 8 or 16-bit integers), got VEC3 of signed "
                    "8-bit integers"},
        BadGeometry{"bad_quantized_position_uint.gltf",
                    "accessors[0] (used as meshes[0].primitives[0].attributes.POSITION): expected VEC3 of 32-bit "
                    "floats (or, with KHR_mesh_quantization, of 8 or 16-bit integers), got VEC3 of unsigned 32-bit "
                    "integers"},
        BadGeometry{"bad_quantized_range.gltf",
                    "accessors[0]: 5 elements of 6 bytes, 8 apart, from byte 0 do not fit in bufferViews[0] (32 "
                    "bytes)"}),
    name_of);

}  // namespace
}  // namespace gltf_geometry_test
}  // namespace tilelight
