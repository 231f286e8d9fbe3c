// Broken files are input like any other: each one is a tilelight::Error whose message starts
// with the file's path and says what is wrong (tests/fixtures/gltf/make_fixtures.py made each
// with one thing wrong).
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>

#include <string>

namespace tilelight {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace gltf_bad_input_test {
namespace {

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;

struct BadFile {
  const char* file;
  const char* says;  // a part of the message after the file's name
};

void PrintTo(const BadFile& b, std::ostream* os) { *os << b.file; }

class GltfBadInput : public ::testing::TestWithParam<BadFile> {};

TEST_P(GltfBadInput, IsAnErrorNamingTheFileAndWhatIsWrong) {
  const std::filesystem::path path = kFixtures / GetParam().file;
  try {
    (void)load_gltf_scene(path);
    FAIL() << "loaded";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
    EXPECT_NE(what.find(GetParam().says), std::string::npos) << what;
  }
}

std::string name_of(const ::testing::TestParamInfo<BadFile>& info) {
  std::string name = info.param.file;
  for (char& c : name) {
    if (c == '.') c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, GltfBadInput,
    ::testing::Values(
        BadFile{"bad_cycle.gltf", "the node hierarchy has a cycle: nodes[0] -> nodes[1] -> nodes[0]"},
        BadFile{"bad_two_parents.gltf", "nodes[1] is a child of both nodes[0] and nodes[2]"},
        BadFile{"bad_child_missing.gltf", "nodes[1].children: node 7 does not exist"},
        BadFile{"bad_accessor_missing.gltf", "accessor 42 does not exist"},
        BadFile{"bad_accessor_range.gltf", "accessors[0]: 25 elements of 12 bytes"},
        BadFile{"bad_view_range.gltf", "past the end of buffers[0]"},
        BadFile{"bad_wrong_type.gltf", "nodes[0].mesh: expected a non-negative integer, got a string"},
        BadFile{"bad_scene_type.gltf", "scene: expected a non-negative integer, got a string"},
        BadFile{"bad_matrix_length.gltf", "nodes[1].matrix: expected 16 elements, got 3"},
        BadFile{"bad_no_position.gltf", "meshes[0].primitives[0]: no POSITION attribute"},
        BadFile{"bad_material_missing.gltf", "material 3 does not exist"},
        BadFile{"bad_mode.gltf", "9 is not a glTF primitive mode"},
        BadFile{"bad_no_scenes.gltf", "the file has no scene"},
        BadFile{"bad_draco_stream.gltf",
                "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: not a Draco stream"},
        BadFile{"bad_index_range.gltf", "index 99 at element 1 is out of range"},
        BadFile{"bad_nan_position.gltf", "element 0 is not finite"},
        BadFile{"bad_short_buffer.gltf", "buffers[0]: its data URI holds 640 bytes, byteLength says 648"},
        BadFile{"bad_buffer_too_small.gltf", "past the end of buffers[0]"},
        BadFile{"bad_missing_bin.gltf", "buffers[0]: the file /"}, BadFile{"bad_truncated.glb", "truncated GLB"},
        BadFile{"bad_truncated_header.glb", "truncated GLB"}, BadFile{"bad_not_json.gltf", "not valid JSON"},
        BadFile{"bad_empty.gltf", "the file is empty"},
        BadFile{"bad_nul_in_json.gltf", "not valid JSON: a NUL byte at offset"},
        BadFile{"bad_deep_extras.gltf", "JSON nested 100002 levels deep, more than this loader reads (64)"},
        BadFile{"no_such_file.glb", "cannot open: No such file or directory"}, BadFile{".", "is a folder"},
        // Base colour textures.
        BadFile{"bad_image_missing.gltf", "no_such_image.png does not exist"},
        BadFile{"bad_image_not_png.gltf", "images[0] (used by textures[0]): not a PNG or JPEG image"},
        BadFile{"bad_image_truncated.gltf", "images[0] (used by textures[0]): the image is corrupt or truncated"},
        BadFile{"bad_image_too_large.gltf", "9000x9000 pixels; at most 8192 a side are loaded"},
        BadFile{"bad_texture_missing.gltf",
                "materials[0].pbrMetallicRoughness.baseColorTexture.index: texture 5 does not exist (the file has 1)"},
        BadFile{"bad_texcoord_missing.gltf",
                "meshes[0].primitives[0]: its material's base colour texture reads TEXCOORD_3, which the primitive "
                "does not have"},
        BadFile{"bad_sampler_filter.gltf", "samplers[0].magFilter: 1234 is not a glTF magnification filter"},
        BadFile{"bad_image_view_range.gltf",
                "bufferViews[5]: bytes 148..287 are past the end of buffers[0], which has 223 bytes"}),
    name_of);

}  // namespace
}  // namespace gltf_bad_input_test
}  // namespace tilelight
