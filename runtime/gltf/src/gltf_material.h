#pragma once
// What the renderer draws of a glTF material: its base colour (metallic-roughness's, or
// KHR_materials_pbrSpecularGlossiness's diffuse), a Blinn-Phong stand-in for its shininess, its
// alpha mode and sidedness, and where its base colour texture is read (texture, TEXCOORD_n set,
// KHR_texture_transform). Every value is checked; errors name the material and property.

#include "tilelight/scene/scene.h"
#include "tinygltf.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {

struct MaterialLook {
  glm::vec4 base_colour{1.0f};  // linear RGBA factor, each in 0..1
  float spec_amount = 0.05f;    // Instance::albedo_spec.a
  float spec_power = 4.0f;      // Instance::material.x
  bool alpha_mask = false;      // alphaMode MASK
  float alpha_cutoff = 0.5f;    // with alpha_mask
  bool blend = false;           // alphaMode BLEND (the forward pass)
  bool double_sided = false;
};

// Material `material` of the model (-1: glTF's default material). `user` names the primitive
// that refers to it, for an index out of range.
MaterialLook material_look(const tinygltf::Model& model, int material, const std::string& user);

// Where a material's base colour texture is read.
struct BaseColourTextureRef {
  int texture = -1;  // index into model.textures
  int texcoord_set = 0;
  // uv' = uv_transform * (u, v, 1): KHR_texture_transform's translation * rotation * scale
  // (identity without the extension).
  glm::mat3 uv_transform{1.0f};
  std::string user;  // "materials[2].pbrMetallicRoughness.baseColorTexture", for messages
};

// The material's base colour texture: pbrMetallicRoughness.baseColorTexture, or the spec-gloss
// extension's diffuseTexture where the material has that extension. None: no texture.
std::optional<BaseColourTextureRef> base_colour_texture_ref(const tinygltf::Model& model, int material);

// Applies a base colour texture's uv transform to every vertex of a mesh: a transform affine in
// uv commutes with interpolation, so it is done once here rather than per fragment.
void transform_uvs(Mesh& mesh, const glm::mat3& uv_transform);

// The Instance of a placed primitive with material `material`.
Instance material_instance(const MaterialLook& look, const glm::mat4& world, std::uint32_t motion_id);

}  // namespace tilelight::gltf_detail
