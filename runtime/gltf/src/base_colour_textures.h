#pragma once
// The base colour textures a scene's materials use, as Scene textures: each glTF texture is
// decoded once, on first use, from its image's bytes (a buffer view, a data URI, or a file next
// to the .gltf) and read with its sampler's filters and wrap modes. Images no material uses as
// a base colour are never read or decoded.

#include "tilelight/scene/scene.h"
#include "tinygltf.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {

// The most texels the base colour textures of one scene may have together (1 GiB as RGBA8).
inline constexpr std::uint64_t kMaxSceneTexels = std::uint64_t{1} << 28;

// What a primitive's material asks for: the scene texture, the TEXCOORD_n set it reads and the
// transform of those coordinates (gltf_material.h).
struct BaseColourTexture {
  std::uint32_t texture = 0;  // index into the textures() vector
  int texcoord_set = 0;
  glm::mat3 uv_transform{1.0f};
};

class BaseColourTextures {
 public:
  // `base_dir`: the folder external images are read from; empty: external images are errors
  // (a load from memory). The model must outlive this object.
  BaseColourTextures(const tinygltf::Model& model, std::filesystem::path base_dir);

  // The base colour texture of material `material` (-1: none), decoded on first use: its
  // metallic-roughness base colour texture or its spec-gloss diffuse texture. Throws
  // tilelight::Error naming the material, texture, sampler or image at fault.
  std::optional<BaseColourTexture> of_material(int material);

  // glTF texture `texture_index` as a scene texture, decoded on first use (a light's globe map).
  // Throws tilelight::Error naming "`user`.index" when the texture does not exist, or the
  // texture, sampler or image at fault.
  std::uint32_t of_texture(int texture_index, const std::string& user) { return scene_texture(texture_index, user); }

  std::vector<Texture> take_textures() { return std::move(textures_); }

 private:
  std::uint32_t scene_texture(int texture_index, const std::string& user);
  std::vector<std::uint8_t> image_bytes(int image_index) const;

  const tinygltf::Model& model_;
  std::filesystem::path base_dir_;
  std::map<int, std::uint32_t> scene_texture_of_;  // glTF texture -> index into textures_
  std::vector<Texture> textures_;
  std::uint64_t texels_ = 0;
};

// The encoded bytes tinygltf hands its image callback for data-URI images, kept in Image::image
// (with as_is set) for BaseColourTextures; buffer-view images are read and bounds-checked by
// BaseColourTextures itself, external files are not read by tinygltf at all.
bool keep_encoded_image(tinygltf::Image* image, int index, std::string* err, std::string* warn, int width, int height,
                        const unsigned char* bytes, int size, void* user);

}  // namespace tilelight::gltf_detail
