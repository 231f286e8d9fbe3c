// Fuzz entry point: the glTF loader's boundary (tilelight::gltf), one input = one file's bytes,
// loaded as "fuzz.glb" (GLB when it starts with "glTF", else glTF JSON) with external files
// refused, so no input reads the disk.
//
// Beyond "no crash, no hang, no leak", it checks that every rejection is a tilelight::Error
// naming the file and saying what is wrong, and that an accepted file gives a scene the
// renderer can draw: every reference in range, every index below its mesh's vertex count,
// positions and transforms finite, unit normals, at least one triangle, a default camera, and
// every warning a line "warning: fuzz.glb: ..." (what the file holds that is not drawn).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"

namespace {

constexpr const char* kFile = "fuzz.glb";

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

void check_scene(const tilelight::Scene& scene) {
  using shadergen::fuzz::require;
  require(scene.source == kFile, "the scene names its file");
  require(scene.triangle_count() > 0, "an accepted scene has a triangle to draw");
  require(!scene.cameras.empty() && scene.cameras[0].name == "default", "an accepted scene has the default camera");
  for (const tilelight::Mesh& mesh : scene.meshes) {
    require(!mesh.indices.empty() && mesh.indices.size() % 3 == 0, "every mesh is a non-empty triangle list");
    for (std::uint32_t index : mesh.indices) require(index < mesh.vertices.size(), "every index names a vertex");
    for (const tilelight::MeshVertex& v : mesh.vertices) {
      require(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z),
              "every position is finite");
      require(std::fabs(glm::length(v.normal) - 1.0f) < 1e-3f, "every normal has unit length");
    }
  }
  for (const tilelight::MeshBatch& batch : scene.batches) {
    require(batch.mesh < scene.meshes.size(), "every batch draws an existing mesh");
    require(batch.instance_count > 0 && batch.first_instance + batch.instance_count <= scene.instances.size(),
            "every batch draws existing instances");
  }
  for (const tilelight::Instance& instance : scene.instances)
    require(finite(instance.model), "every transform is finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using shadergen::fuzz::require;
  try {
    const tilelight::GltfScene loaded = tilelight::load_gltf_from_memory(std::span(data, size), kFile, {});
    check_scene(loaded.scene);
    for (const std::string& warning : loaded.warnings) {
      require(warning.rfind(std::string("warning: ") + kFile + ": ", 0) == 0, "every warning names the file");
      require(warning.find('\n') == std::string::npos, "every warning is one line");
    }
  } catch (const tilelight::Error& e) {
    const std::string_view what = e.what();
    const std::string prefix = std::string(kFile) + ": ";
    require(what.rfind(prefix, 0) == 0, "every error starts with the file's name");
    require(what.size() > prefix.size() + 3, "every error says what is wrong");
  }
  return 0;
}
