// Real glTF 2.0 files from Debian's assimp-testmodels: its sample models load, its broken
// files (assimp's own bad-input tests) are errors naming the file.
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>

#include <string>

namespace tilelight {
namespace {

const std::filesystem::path kModels = TILELIGHT_ASSIMP_GLTF2_MODELS;

void require_models() {
  ASSERT_TRUE(std::filesystem::is_directory(kModels))
      << kModels << " is missing: install Debian's assimp-testmodels (scripts/install-deps.sh --tests)";
}

struct Model {
  const char* file;
  std::uint64_t triangles;
};

void PrintTo(const Model& m, std::ostream* os) { *os << m.file; }

class AssimpModels : public ::testing::TestWithParam<Model> {};

TEST_P(AssimpModels, Load) {
  require_models();
  const std::filesystem::path path = kModels / GetParam().file;
  const Scene scene = load_gltf_scene(path);
  EXPECT_EQ(scene.source, path.filename().string());
  EXPECT_EQ(scene.triangle_count(), GetParam().triangles);
}

std::string name_of(const std::string& file) {
  std::string name = std::filesystem::path(file).stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

std::string model_test_name(const ::testing::TestParamInfo<Model>& info) {
  return name_of(info.param.file) + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(
    Gltf2, AssimpModels,
    ::testing::Values(Model{"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 121496},  // 115 nodes, 34 meshes
                      Model{"ClearCoat-glTF/ClearCoatTest.gltf", 37116},
                      Model{"BoxTextured-glTF/BoxTextured.gltf", 12},  // external .bin
                      Model{"BoxTextured-glTF-Binary/BoxTextured.glb", 12},
                      Model{"BoxTextured-glTF-Embedded/BoxTextured.gltf", 12},  // data URIs
                      Model{"BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", 12},
                      Model{"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", 12},
                      Model{"BoxTexcoords-glTF/boxTexcoords.gltf", 12}, Model{"cameras/Cameras.gltf", 2},
                      Model{"glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", 12},
                      Model{"simple_skin/simple_skin.gltf", 8}, Model{"textureTransform/TextureTransformTest.gltf", 24},
                      Model{"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", 2},   // a strip
                      Model{"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_06.gltf", 2}),  // a fan
    model_test_name);

struct Broken {
  const char* file;
  const char* says;
};

void PrintTo(const Broken& b, std::ostream* os) { *os << b.file; }

class AssimpBrokenFiles : public ::testing::TestWithParam<Broken> {};

TEST_P(AssimpBrokenFiles, AreErrorsNamingTheFile) {
  require_models();
  const std::filesystem::path path = kModels / GetParam().file;
  try {
    (void)load_gltf_scene(path);
    FAIL() << "loaded";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
    EXPECT_NE(what.find(GetParam().says), std::string::npos) << what;
  }
}

std::string broken_test_name(const ::testing::TestParamInfo<Broken>& info) {
  return name_of(info.param.file) + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(
    Gltf2, AssimpBrokenFiles,
    ::testing::Values(
        Broken{"RecursiveNodes/RecursiveNodes.gltf",
               "the node hierarchy has a cycle: nodes[0] -> nodes[1] -> nodes[0]"},
        Broken{"IndexOutOfRange/IndexOutOfRange.gltf", "index 255 at element 0 is out of range"},
        Broken{"IndexOutOfRange/AllIndicesOutOfRange.gltf", "index 65535 at element 0 is out of range"},
        Broken{"MissingBin/BoxTextured.gltf",
               "buffers[0]: the file /usr/share/assimp/models/glTF2/MissingBin/BoxTextured0.bin does not exist"},
        Broken{"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "element 0 is not finite (-inf, -0.5, 0.5)"},
        Broken{"IncorrectVertexArrays/Cube.gltf", "meshes[1].primitives[0]: 35 vertices, not a multiple of 3"},
        Broken{"SchemaFailures/sceneWrongType.gltf", "scene: expected a non-negative integer, got a string"},
        Broken{"TestNoRootNode/NoScene.gltf", "the file has no scene"},
        Broken{"TestNoRootNode/SceneWithoutNodes.gltf", "scenes[0] has no triangles to draw"},
        Broken{"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "requires the extension KHR_technique_webgl"},
        Broken{"wrongTypes/badArray.gltf", "meshes[0].primitives: expected an array, got an object"},
        Broken{"wrongTypes/badExtension.gltf", "extensions.KHR_texture_transform: expected an object, got a string"},
        Broken{"wrongTypes/badNumber.gltf", "materials[0].normalTexture.index: missing (required)"},
        Broken{"wrongTypes/badObject.gltf", "materials[0].pbrMetallicRoughness: expected an object, got an array"},
        Broken{"wrongTypes/badString.gltf", "scenes[0].name: expected a string, got an integer"},
        Broken{"wrongTypes/badUint.gltf", "baseColorTexture.index: expected a non-negative integer, got a negative"},
        // Points and lines only: nothing with a surface to draw.
        Broken{"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf", "has no triangles to draw"}),
    broken_test_name);

}  // namespace
}  // namespace tilelight
