// glTF 2.0 -> Scene: the container and JSON types checked here, the file parsed by tinygltf,
// then every reference and length checked again while the scene is built from it.
#include "tilelight/gltf/load_gltf.h"

#include "base_colour_textures.h"
#include "draco_primitives.h"
#include "external_files.h"
#include "glb_container.h"
#include "gltf_cameras.h"
#include "gltf_light_json.h"
#include "gltf_lights.h"
#include "gltf_material.h"
#include "ignored_features.h"
#include "json_schema.h"
#include "meshopt_views.h"
#include "node_graph.h"
#include "primitive_mesh.h"
#include "read_file.h"
#include "scene_framing.h"
#include "tilelight/base/error.h"
#include "tinygltf.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace tilelight {
namespace {

using namespace gltf_detail;

constexpr std::size_t kMaxInstances = std::size_t{1} << 20;
constexpr std::uint64_t kMaxSceneTriangles = std::uint64_t{1} << 26;  // drawn per frame, instances counted

// tinygltf's file callbacks: external buffers are read with the project's one reader, worded
// like read_file(), or, for a load from memory without a folder, refused. Paths are used as written (no wordexp() expansion).
struct FileAccess {
  bool allowed = false;
};

bool file_exists(const std::string& path, void* user) {
  if (!static_cast<FileAccess*>(user)->allowed) return false;
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string expand_path(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  if (!static_cast<FileAccess*>(user)->allowed) {
    if (err != nullptr) *err += path + ": external files are not read here\n";
    return false;
  }
  if (auto failure = whole_file::read(path, *out, kMaxFileBytes)) {
    if (err != nullptr) *err += describe_read_failure(*failure, path) + "\n";
    return false;
  }
  return true;
}

bool write_whole_file(std::string* err, const std::string& path, const std::vector<unsigned char>&, void*) {
  if (err != nullptr) *err += path + ": the loader writes no files\n";
  return false;
}

// tinygltf's multi-line error text as one line, with any data URI it quotes cut short.
std::string one_line(std::string text) {
  for (std::size_t at = text.find("data:"); at != std::string::npos; at = text.find("data:", at + 1)) {
    const std::size_t end = std::min(text.find(' ', at), text.size());
    if (end - at > 48) text.replace(at + 40, end - at - 40, "...");
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ';');
  return text.empty() ? "tinygltf rejected the file without saying why" : text;
}

// The parsed file, the features of it that are not drawn (ignored_features.h), its lights
// (gltf_light_json.h) and its compressed buffer views and primitives, not yet decoded
// (meshopt_views.h, draco_primitives.h).
struct Parsed {
  tinygltf::Model model;
  std::vector<std::string> ignored;
  FileLights lights;
  std::vector<MeshoptView> meshopt;
  std::vector<DracoPrimitive> draco;
};

// The JSON checked before tinygltf reads it: types, glTF 1.0, external buffers present,
// compressed views and primitives. Returns the JSON tinygltf is to read instead of `json`, or ""
// for `json` itself: a meshopt fallback buffer is given bytes tinygltf can load, a Draco
// primitive's indices accessor a buffer view.
std::string check_json(std::string_view json, const std::filesystem::path& base_dir, Parsed& parsed) {
  nlohmann::json root = check_json_schema(json);
  check_external_buffers(root, base_dir);
  parsed.ignored = ignored_features(root);
  parsed.lights = read_file_lights(root);
  parsed.meshopt = meshopt_views(root);
  parsed.draco = draco_primitives(root);
  const bool fallbacks = empty_fallback_buffers(root);
  const bool draco_indices = point_draco_indices_at_streams(root, parsed.draco);
  return fallbacks || draco_indices ? root.dump() : std::string();
}

Parsed parse(std::span<const std::uint8_t> bytes, const std::filesystem::path& base_dir) {
  FileAccess access{!base_dir.empty()};
  tinygltf::TinyGLTF parser;
  parser.SetFsCallbacks({&file_exists, &expand_path, &read_whole_file, &write_whole_file, &access});
  parser.SetImageLoader(&keep_encoded_image, nullptr);
  Parsed parsed;
  std::string err, warn;
  bool ok = false;
  if (is_glb(bytes)) {
    // A GLB's JSON chunk is padded to 4 bytes with spaces; NULs there are tolerated as padding.
    const GlbChunks chunks = split_glb(bytes);
    std::string_view json = chunks.json;
    while (!json.empty() && json.back() == '\0') json.remove_suffix(1);
    const std::string rewritten = check_json(json, base_dir, parsed);
    const std::vector<std::uint8_t> glb =
        rewritten.empty() ? std::vector<std::uint8_t>() : make_glb(rewritten, chunks.bin);
    const std::span<const std::uint8_t> input = rewritten.empty() ? bytes : std::span<const std::uint8_t>(glb);
    ok = parser.LoadBinaryFromMemory(&parsed.model, &err, &warn, input.data(), static_cast<unsigned int>(input.size()),
                                     base_dir.string());
  } else {
    if (bytes.empty()) throw Error("the file is empty");
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const std::string rewritten = check_json(text, base_dir, parsed);
    const std::string_view input = rewritten.empty() ? text : std::string_view(rewritten);
    ok = parser.LoadASCIIFromString(&parsed.model, &err, &warn, input.data(), static_cast<unsigned int>(input.size()),
                                    base_dir.string());
  }
  if (!ok) throw Error(one_line(err));
  decode_meshopt_views(parsed.model, parsed.meshopt);
  // After meshopt: a Draco stream may lie in a meshopt-decoded view.
  decode_draco_primitives(parsed.model, parsed.draco);
  return parsed;
}

std::size_t chosen_scene(const tinygltf::Model& model, const GltfLoadOptions& options) {
  if (model.scenes.empty()) throw Error("the file has no scene (\"scenes\" is empty or missing): nothing to draw");
  if (options.scene_index) {
    if (*options.scene_index >= model.scenes.size()) {
      throw Error(fmt::format("scene {} does not exist (the file has {} scene(s), 0 to {})", *options.scene_index,
                              model.scenes.size(), model.scenes.size() - 1));
    }
    return *options.scene_index;
  }
  if (model.defaultScene < 0) return 0;
  if (static_cast<std::size_t>(model.defaultScene) >= model.scenes.size()) {
    throw Error(
        fmt::format("scene: scene {} does not exist (the file has {})", model.defaultScene, model.scenes.size()));
  }
  return static_cast<std::size_t>(model.defaultScene);
}

// A transform that collapses a dimension draws nothing and has no normal matrix.
bool invertible(const glm::mat4& m) { return std::fabs(glm::determinant(glm::mat3(m))) >= 1e-18f; }

// A mirroring transform turns counter-clockwise (front) faces clockwise (glTF: "the winding
// order ... is reversed").
bool mirrors(const glm::mat4& m) { return glm::determinant(glm::mat3(m)) < 0.0f; }

// The material's mask, sidedness and texture applied to a mesh built for it; for mirrored
// instances, its triangles wound the other way, so that their front faces stay front faces.
void apply_material(Mesh& mesh, const MaterialLook& look, const std::optional<BaseColourTexture>& texture,
                    bool mirrored) {
  mesh.alpha_mask = look.alpha_mask;
  mesh.blend = look.blend;
  mesh.double_sided = look.double_sided;
  if (texture) {
    mesh.base_colour_texture = texture->texture;
    transform_uvs(mesh, texture->uv_transform);
  }
  if (mirrored) {
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  }
}

// The scene, and the warnings its lights give (gltf_lights.h).
GltfScene build_scene(const Parsed& parsed, const std::filesystem::path& base_dir, const GltfLoadOptions& options) {
  const tinygltf::Model& model = parsed.model;
  const std::size_t scene_index = chosen_scene(model, options);
  const std::vector<PlacedMesh> placed = place_meshes(model, scene_index);

  Scene scene;
  BaseColourTextures textures(model, base_dir);
  // (mesh, primitive, mirrored) -> scene mesh; a mirrored instance gets the mesh wound the other way.
  std::map<std::tuple<int, int, bool>, std::optional<std::uint32_t>> mesh_of;
  std::vector<std::vector<Instance>> instances_of_mesh;
  std::uint64_t triangles = 0;
  std::size_t instance_count = 0;
  std::uint32_t next_motion_id = 1;
  for (const PlacedMesh& p : placed) {
    const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(p.mesh)];
    for (std::size_t k = 0; k < mesh.primitives.size(); ++k) {
      const std::string user = fmt::format("meshes[{}].primitives[{}]", p.mesh, k);
      const MaterialLook look = material_look(model, mesh.primitives[k].material, user);
      const auto key = std::tuple(p.mesh, static_cast<int>(k), mirrors(p.world));
      auto found = mesh_of.find(key);
      if (found == mesh_of.end()) {
        const std::optional<BaseColourTexture> texture = textures.of_material(mesh.primitives[k].material);
        std::optional<Mesh> built = primitive_mesh(model, p.mesh, static_cast<int>(k),
                                                   texture ? std::optional(texture->texcoord_set) : std::nullopt);
        if (built) apply_material(*built, look, texture, std::get<2>(key));
        std::optional<std::uint32_t> index;
        if (built) {
          index = static_cast<std::uint32_t>(scene.meshes.size());
          scene.meshes.push_back(std::move(*built));
          instances_of_mesh.emplace_back();
        }
        found = mesh_of.emplace(key, index).first;
      }
      if (!found->second || !invertible(p.world)) continue;
      instances_of_mesh[*found->second].push_back(material_instance(look, p.world, next_motion_id));
      next_motion_id = next_motion_id % 127u + 1u;  // 1..127; 0 is the sky
      triangles += scene.meshes[*found->second].indices.size() / 3;
      if (++instance_count > kMaxInstances || triangles > kMaxSceneTriangles) {
        throw Error(fmt::format("scenes[{}] is too large: more than {} mesh instances or {} triangles", scene_index,
                                kMaxInstances, kMaxSceneTriangles));
      }
    }
  }
  if (triangles == 0) {
    throw Error(
        fmt::format("scenes[{}] has no triangles to draw ({} node(s) with a mesh)", scene_index, placed.size()));
  }
  for (std::uint32_t m = 0; m < instances_of_mesh.size(); ++m) {
    if (instances_of_mesh[m].empty()) continue;
    const auto first = static_cast<std::uint32_t>(scene.instances.size());
    scene.instances.insert(scene.instances.end(), instances_of_mesh[m].begin(), instances_of_mesh[m].end());
    scene.batches.push_back({m, first, static_cast<std::uint32_t>(instances_of_mesh[m].size())});
  }
  fit_scene(scene, scene_bounds(scene));
  add_file_cameras(model, scene);
  // After the framing, which the lights follow; before the textures go, as globe maps add some.
  std::vector<std::string> light_warnings = add_file_lights(model, scene_index, parsed.lights, textures, scene);
  scene.textures = textures.take_textures();
  return GltfScene{std::move(scene), std::move(light_warnings)};
}

GltfScene load(std::span<const std::uint8_t> bytes, const std::string& name, const std::string& source,
               const std::filesystem::path& base_dir, const GltfLoadOptions& options) {
  try {
    // tinygltf takes sizes as unsigned int.
    if (bytes.size() > kMaxFileBytes) {
      throw Error(fmt::format("{} bytes, more than this loader reads ({})", bytes.size(), kMaxFileBytes));
    }
    const Parsed parsed = parse(bytes, base_dir);
    GltfScene built = build_scene(parsed, base_dir, options);
    GltfScene loaded{std::move(built.scene), {}};
    loaded.scene.source = source;
    for (const std::string& line : parsed.ignored) loaded.warnings.push_back("warning: " + name + ": " + line);
    for (const std::string& line : built.warnings) loaded.warnings.push_back("warning: " + name + ": " + line);
    return loaded;
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  } catch (const std::bad_alloc&) {
    throw Error(name + ": out of memory while loading it");
  } catch (const std::length_error& e) {
    throw Error(name + ": too large to load (" + e.what() + ")");
  }
}

}  // namespace

GltfScene load_gltf(const std::filesystem::path& file, const GltfLoadOptions& options) {
  const std::vector<std::uint8_t> bytes = read_file(file, file.string());
  std::filesystem::path folder = file.parent_path();
  if (folder.empty()) folder = ".";
  return load(bytes, file.string(), file.filename().string(), folder, options);
}

GltfScene load_gltf_from_memory(std::span<const std::uint8_t> bytes, const std::string& name,
                                const std::filesystem::path& base_dir, const GltfLoadOptions& options) {
  return load(bytes, name, std::filesystem::path(name).filename().string(), base_dir, options);
}

Scene load_gltf_scene(const std::filesystem::path& file, const GltfLoadOptions& options) {
  return load_gltf(file, options).scene;
}

Scene load_gltf_scene_from_memory(std::span<const std::uint8_t> bytes, const std::string& name,
                                  const std::filesystem::path& base_dir, const GltfLoadOptions& options) {
  return load_gltf_from_memory(bytes, name, base_dir, options).scene;
}

}  // namespace tilelight
