// What the loader makes of valid files: node transforms, every index width, containers,
// flat normals, strips and fans, the scene's framing.
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

namespace tilelight {
namespace {

const std::filesystem::path kFixtures = TILELIGHT_GLTF_FIXTURES;

Scene load(const std::string& name, GltfLoadOptions options = {}) { return load_gltf_scene(kFixtures / name, options); }

void expect_near(const glm::mat4& a, const glm::mat4& b, float tolerance) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tolerance) << "column " << c << " row " << r;
  }
}

// The sphere around every instance's transformed vertices.
float bounding_radius(const Scene& scene, glm::vec3& centre) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const MeshBatch& batch : scene.batches) {
    for (std::uint32_t i = 0; i < batch.instance_count; ++i) {
      for (const MeshVertex& v : scene.meshes[batch.mesh].vertices) {
        const glm::vec3 p(scene.instances[batch.first_instance + i].model * glm::vec4(v.position, 1.0f));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
  }
  centre = (lo + hi) * 0.5f;
  return glm::length(hi - lo) * 0.5f;
}

TEST(GltfLoader, LoadsTheBoxWithItsNodeTransformsAndMaterial) {
  const Scene scene = load("box.gltf");
  EXPECT_EQ(scene.source, "box.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].vertices.size(), 24u);
  EXPECT_EQ(scene.meshes[0].indices.size(), 36u);
  ASSERT_EQ(scene.instances.size(), 2u);  // the root node and its child draw the same mesh
  ASSERT_EQ(scene.batches.size(), 1u);
  EXPECT_EQ(scene.triangle_count(), 24u);
  // The child's matrix puts it 3 units along the root's x axis.
  const glm::mat4 child_local{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {3, 0, 0, 1}};
  expect_near(scene.instances[1].model, scene.instances[0].model * child_local, 1e-4f);
  // The root's scale (1, 1, 2) after a quarter turn about y: its third column is twice as long.
  const glm::mat4& root = scene.instances[0].model;
  EXPECT_NEAR(glm::length(glm::vec3(root[2])) / glm::length(glm::vec3(root[0])), 2.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(glm::normalize(glm::vec3(root[0])), glm::vec3(0, 0, -1)), 1.0f, 1e-4f);
  EXPECT_NEAR(scene.instances[0].albedo_spec.r, 0.8f, 1e-6f);
  EXPECT_NEAR(scene.instances[0].albedo_spec.g, 0.2f, 1e-6f);
  EXPECT_NEAR(scene.instances[0].albedo_spec.b, 0.1f, 1e-6f);
  EXPECT_NE(scene.instances[0].material.y, scene.instances[1].material.y) << "each instance its own motion ID";
}

TEST(GltfLoader, TheSceneIsScaledToTenMetresAndFramedByTheDefaultCamera) {
  const Scene scene = load("box.gltf");
  glm::vec3 centre;
  EXPECT_NEAR(bounding_radius(scene, centre), 10.0f, 1e-3f);
  EXPECT_NEAR(glm::length(centre), 0.0f, 1e-3f);
  ASSERT_EQ(scene.camera_names(), std::vector<std::string>{"default"});
  const Camera& camera = scene.camera("default");
  // Raised, outside the sphere, looking at its centre.
  EXPECT_GT(camera.position.y, 5.0f);
  const float distance = glm::length(camera.position - camera.target);
  EXPECT_GT(distance, 10.0f);
  EXPECT_NEAR(glm::length(camera.target), 0.0f, 1e-6f);
  // Every vertex inside a 4:3 frame, and in front of where the shadows start to fade (measured
  // from the eye: no visible surface loses its shadow).
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  for (const MeshBatch& batch : scene.batches) {
    for (std::uint32_t i = 0; i < batch.instance_count; ++i) {
      for (const MeshVertex& v : scene.meshes[batch.mesh].vertices) {
        const glm::vec3 p(scene.instances[batch.first_instance + i].model * glm::vec4(v.position, 1.0f));
        // (The fit takes the box's corners: the same depths, rounded differently.)
        EXPECT_LE(glm::dot(p - camera.position, forward), scene.sun.shadow_fade_start + 1e-4f);
        EXPECT_LE(glm::dot(p - camera.position, forward), scene.sun.scattering_start + 1e-4f);
      }
    }
  }
  for (float aspect : {4.0f / 3.0f, 16.0f / 9.0f}) {
    const CameraMatrices m = camera_matrices(camera, aspect);
    for (const MeshBatch& batch : scene.batches) {
      for (std::uint32_t i = 0; i < batch.instance_count; ++i) {
        for (const MeshVertex& v : scene.meshes[batch.mesh].vertices) {
          const glm::vec4 clip =
              m.view_proj * scene.instances[batch.first_instance + i].model * glm::vec4(v.position, 1.0f);
          EXPECT_GT(clip.w, 0.5f);
          EXPECT_LE(std::fabs(clip.x), clip.w);
          EXPECT_LE(std::fabs(clip.y), clip.w);
        }
      }
    }
  }
  // The shadow map covers the sphere.
  EXPECT_GE(scene.sun.shadow_half_extent, 10.0f);
  EXPECT_GE(scene.sun.shadow_depth_range, 20.0f);
  EXPECT_LE(scene.sun.shadow_fade_start, distance + 10.0f);
  EXPECT_THROW((void)scene.camera("street"), Error);
}

TEST(GltfLoader, EveryContainerAndIndexWidthGivesTheSameScene) {
  const Scene reference = load("box.gltf");
  for (const char* name : {"box.glb", "box_nul_padded.glb", "box_external.gltf", "box_u8.gltf", "box_u32.gltf"}) {
    SCOPED_TRACE(name);
    const Scene scene = load(name);
    EXPECT_EQ(scene.source, name);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].indices, reference.meshes[0].indices);
    ASSERT_EQ(scene.meshes[0].vertices.size(), reference.meshes[0].vertices.size());
    for (std::size_t i = 0; i < scene.meshes[0].vertices.size(); ++i) {
      EXPECT_EQ(scene.meshes[0].vertices[i].position, reference.meshes[0].vertices[i].position);
      EXPECT_EQ(scene.meshes[0].vertices[i].normal, reference.meshes[0].vertices[i].normal);
    }
    ASSERT_EQ(scene.instances.size(), 2u);
    expect_near(scene.instances[1].model, reference.instances[1].model, 0.0f);
  }
}

TEST(GltfLoader, PrimitivesWithoutNormalsGetOutwardFlatNormals) {
  for (const char* name : {"box_no_normals.gltf", "box_unindexed.gltf"}) {
    SCOPED_TRACE(name);
    const Scene scene = load(name);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.indices.size(), 36u);
    ASSERT_EQ(mesh.vertices.size(), 36u);  // three vertices of its own per triangle
    for (std::size_t t = 0; t < 36; t += 3) {
      const MeshVertex& a = mesh.vertices[mesh.indices[t]];
      const MeshVertex& b = mesh.vertices[mesh.indices[t + 1]];
      const MeshVertex& c = mesh.vertices[mesh.indices[t + 2]];
      EXPECT_EQ(a.normal, b.normal);
      EXPECT_EQ(a.normal, c.normal);
      EXPECT_NEAR(glm::length(a.normal), 1.0f, 1e-6f);
      // The box is centred on its origin and wound counter-clockwise: face normals point out.
      EXPECT_GT(glm::dot(a.normal, (a.position + b.position + c.position) / 3.0f), 0.4f) << "triangle " << t / 3;
    }
  }
}

TEST(GltfLoader, StripsAndFansBecomeTriangleListsAndLinesAreSkipped) {
  const Scene scene = load("strips_and_fans.gltf");
  ASSERT_EQ(scene.meshes.size(), 2u);  // the strip and the fan; the line has no surface
  EXPECT_EQ(scene.triangle_count(), 4u);
  for (const Mesh& mesh : scene.meshes) {
    ASSERT_EQ(mesh.indices.size(), 6u);
    // Both are the same unit quad wound counter-clockwise seen from +z.
    for (const MeshVertex& v : mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
  }
}

TEST(GltfLoader, SceneIndexChoosesAScene) {
  EXPECT_EQ(load("box.gltf", GltfLoadOptions{0}).triangle_count(), 24u);
  try {
    (void)load("box.gltf", GltfLoadOptions{1});
    FAIL() << "scene 1 of a file with one scene";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              (kFixtures / "box.gltf").string() + ": scene 1 does not exist (the file has 1 scene(s), 0 to 0)");
  }
}

// box.gltf with "extras" of `arrays` nested arrays in its asset object: 2 + arrays levels deep.
std::string box_with_nested_extras(std::size_t arrays) {
  std::ifstream file(kFixtures / "box.gltf");
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::string key = "\"asset\": {";
  text.insert(text.find(key) + key.size(), "\"extras\": " + std::string(arrays, '[') + std::string(arrays, ']') + ", ");
  return text;
}

TEST(GltfLoader, JsonNestedToTheLimitLoadsAndOneLevelMoreIsAnError) {
  const std::string at_limit = box_with_nested_extras(62);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(at_limit.data());
  EXPECT_EQ(load_gltf_scene_from_memory({bytes, at_limit.size()}, "nested.gltf", {}).triangle_count(), 24u);
  const std::string over = box_with_nested_extras(63);
  try {
    (void)load_gltf_scene_from_memory({reinterpret_cast<const std::uint8_t*>(over.data()), over.size()}, "nested.gltf",
                                      {});
    FAIL() << "65 levels loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "nested.gltf: JSON nested 65 levels deep, more than this loader reads (64)");
  }
}

TEST(GltfLoader, FromMemoryRefusesExternalFilesWithoutAFolder) {
  const std::string text = R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"byteLength": 648, "uri": "box_external.bin"}]})";
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.data());
  EXPECT_THROW((void)load_gltf_scene_from_memory({bytes, text.size()}, "memory.gltf", {}), Error);
  // With the fixtures' folder the same document loads: one triangle from box_external.bin.
  EXPECT_EQ(load_gltf_scene_from_memory({bytes, text.size()}, "memory.gltf", kFixtures).triangle_count(), 1u);
}

}  // namespace
}  // namespace tilelight
