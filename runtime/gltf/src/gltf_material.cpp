#include "gltf_material.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tilelight::gltf_detail {
namespace {

constexpr const char* kSpecGloss = "KHR_materials_pbrSpecularGlossiness";
constexpr const char* kTextureTransform = "KHR_texture_transform";

const tinygltf::Value* member(const tinygltf::Value& object, const char* key) {
  return object.IsObject() && object.Has(key) ? &object.Get(key) : nullptr;
}

// A finite number, or `fallback` where the property is absent.
double number(const tinygltf::Value* value, double fallback, const std::string& user) {
  if (value == nullptr) return fallback;
  if (!value->IsNumber()) throw Error(user + ": expected a number");
  const double v = value->GetNumberAsDouble();
  if (!std::isfinite(v)) throw Error(user + ": not finite");
  return v;
}

// `n` finite numbers, each `fallback` where the property is absent.
std::vector<double> numbers(const tinygltf::Value* value, std::size_t n, double fallback, const std::string& user) {
  if (value == nullptr) return std::vector<double>(n, fallback);
  if (!value->IsArray() || value->ArrayLen() != n) throw Error(fmt::format("{}: expected {} numbers", user, n));
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) v.push_back(number(&value->Get(static_cast<int>(i)), 0.0, user));
  return v;
}

glm::vec4 colour_factor(const std::vector<double>& factor, const std::string& user) {
  if (factor.size() != 4) throw Error(user + ": expected 4 numbers");
  glm::vec4 colour;
  for (int c = 0; c < 4; ++c) {
    const double v = factor[static_cast<std::size_t>(c)];
    if (!std::isfinite(v)) throw Error(user + ": not finite");
    colour[c] = static_cast<float>(std::clamp(v, 0.0, 1.0));
  }
  return colour;
}

// A Blinn-Phong stand-in for a shininess in 0..1 and a specular strength in 0..1: rougher is
// dimmer and broader.
void set_shininess(MaterialLook& look, double smoothness, double strength) {
  const auto smooth = static_cast<float>(std::clamp(smoothness, 0.0, 1.0));
  look.spec_amount = 0.05f + smooth * (0.25f + 0.5f * static_cast<float>(std::clamp(strength, 0.0, 1.0)));
  look.spec_power = 4.0f + 124.0f * smooth * smooth;
}

void apply_metallic_roughness(MaterialLook& look, const tinygltf::PbrMetallicRoughness& pbr, const std::string& name) {
  look.base_colour = colour_factor(pbr.baseColorFactor, name + ".pbrMetallicRoughness.baseColorFactor");
  const double metallic = std::isfinite(pbr.metallicFactor) ? std::clamp(pbr.metallicFactor, 0.0, 1.0) : 1.0;
  const double roughness = std::isfinite(pbr.roughnessFactor) ? std::clamp(pbr.roughnessFactor, 0.0, 1.0) : 1.0;
  set_shininess(look, 1.0 - roughness, metallic);
}

// KHR_materials_pbrSpecularGlossiness: the diffuse factor is the base colour, the glossiness the
// smoothness, the brightest specular channel the strength.
void apply_specular_glossiness(MaterialLook& look, const tinygltf::Value& extension, const std::string& name) {
  const std::string user = name + ".extensions." + kSpecGloss;
  if (!extension.IsObject()) throw Error(user + ": expected an object");
  look.base_colour = colour_factor(numbers(member(extension, "diffuseFactor"), 4, 1.0, user + ".diffuseFactor"),
                                   user + ".diffuseFactor");
  const std::vector<double> specular = numbers(member(extension, "specularFactor"), 3, 1.0, user + ".specularFactor");
  const double glossiness = number(member(extension, "glossinessFactor"), 1.0, user + ".glossinessFactor");
  set_shininess(look, glossiness, *std::max_element(specular.begin(), specular.end()));
}

void apply_alpha_mode(MaterialLook& look, const tinygltf::Material& material, const std::string& name) {
  if (material.alphaMode == "BLEND") {
    look.blend = true;  // alphaCutoff does not apply (glTF)
    return;
  }
  if (material.alphaMode == "MASK") {
    if (!std::isfinite(material.alphaCutoff) || material.alphaCutoff < 0.0) {
      throw Error(fmt::format("{}.alphaCutoff: {} is not a finite number of at least 0", name, material.alphaCutoff));
    }
    look.alpha_mask = true;
    look.alpha_cutoff = static_cast<float>(material.alphaCutoff);
    return;
  }
  if (material.alphaMode != "OPAQUE") {
    throw Error(fmt::format("{}.alphaMode: \"{}\" is not OPAQUE, MASK or BLEND", name, material.alphaMode));
  }
}

// KHR_texture_transform's matrix (translation * rotation * scale; glTF's rotation turns uv
// clockwise for a positive angle), and its texCoord, which overrides the texture info's.
glm::mat3 texture_transform(const tinygltf::Value& extension, int& texcoord_set, const std::string& user) {
  if (!extension.IsObject()) throw Error(user + ": expected an object");
  const std::vector<double> offset = numbers(member(extension, "offset"), 2, 0.0, user + ".offset");
  const std::vector<double> scale = numbers(member(extension, "scale"), 2, 1.0, user + ".scale");
  const double rotation = number(member(extension, "rotation"), 0.0, user + ".rotation");
  if (const tinygltf::Value* texcoord = member(extension, "texCoord")) {
    if (!texcoord->IsInt() || texcoord->GetNumberAsInt() < 0) throw Error(user + ".texCoord: expected an integer >= 0");
    texcoord_set = texcoord->GetNumberAsInt();
  }
  const auto c = static_cast<float>(std::cos(rotation)), s = static_cast<float>(std::sin(rotation));
  glm::mat3 translation(1.0f), rotate(1.0f), scaling(1.0f);
  translation[2] = glm::vec3(static_cast<float>(offset[0]), static_cast<float>(offset[1]), 1.0f);
  rotate[0] = glm::vec3(c, -s, 0.0f);  // columns: the spec's rows (c, s), (-s, c)
  rotate[1] = glm::vec3(s, c, 0.0f);
  scaling[0][0] = static_cast<float>(scale[0]);
  scaling[1][1] = static_cast<float>(scale[1]);
  return translation * rotate * scaling;
}

// The texture reference of a texture info, given as its index, texCoord and extensions.
std::optional<BaseColourTextureRef> texture_ref(int index, int texcoord, const tinygltf::Value* transform,
                                                const std::string& user) {
  if (index < 0) return std::nullopt;
  if (texcoord < 0) throw Error(fmt::format("{}.texCoord: {} is negative", user, texcoord));
  BaseColourTextureRef ref{index, texcoord, glm::mat3(1.0f), user};
  if (transform != nullptr) {
    ref.uv_transform = texture_transform(*transform, ref.texcoord_set, user + ".extensions." + kTextureTransform);
  }
  return ref;
}

const tinygltf::Material* material_at(const tinygltf::Model& model, int material) {
  if (material < 0 || static_cast<std::size_t>(material) >= model.materials.size()) return nullptr;
  return &model.materials[static_cast<std::size_t>(material)];
}

}  // namespace

MaterialLook material_look(const tinygltf::Model& model, int material, const std::string& user) {
  MaterialLook look;
  if (material < 0) {  // glTF's default material: white, fully rough, single-sided
    set_shininess(look, 0.0, 1.0);
    return look;
  }
  if (static_cast<std::size_t>(material) >= model.materials.size()) {
    throw Error(fmt::format("{}.material: material {} does not exist (the file has {})", user, material,
                            model.materials.size()));
  }
  const tinygltf::Material& m = model.materials[static_cast<std::size_t>(material)];
  const std::string name = fmt::format("materials[{}]", material);
  if (const auto found = m.extensions.find(kSpecGloss); found != m.extensions.end()) {
    apply_specular_glossiness(look, found->second, name);
  } else {
    apply_metallic_roughness(look, m.pbrMetallicRoughness, name);
  }
  apply_alpha_mode(look, m, name);
  look.double_sided = m.doubleSided;
  return look;
}

std::optional<BaseColourTextureRef> base_colour_texture_ref(const tinygltf::Model& model, int material) {
  const tinygltf::Material* m = material_at(model, material);
  if (m == nullptr) return std::nullopt;
  if (const auto found = m->extensions.find(kSpecGloss); found != m->extensions.end()) {
    const std::string user = fmt::format("materials[{}].extensions.{}.diffuseTexture", material, kSpecGloss);
    const tinygltf::Value* info = member(found->second, "diffuseTexture");
    if (info == nullptr) return std::nullopt;
    if (!info->IsObject()) throw Error(user + ": expected an object");
    const tinygltf::Value* index = member(*info, "index");
    const tinygltf::Value* texcoord = member(*info, "texCoord");
    if (index == nullptr || !index->IsInt()) throw Error(user + ".index: expected an integer");
    if (texcoord != nullptr && !texcoord->IsInt()) throw Error(user + ".texCoord: expected an integer");
    const tinygltf::Value* extensions = member(*info, "extensions");
    return texture_ref(index->GetNumberAsInt(), texcoord != nullptr ? texcoord->GetNumberAsInt() : 0,
                       extensions != nullptr ? member(*extensions, kTextureTransform) : nullptr, user);
  }
  const tinygltf::TextureInfo& info = m->pbrMetallicRoughness.baseColorTexture;
  const auto transform = info.extensions.find(kTextureTransform);
  return texture_ref(info.index, info.texCoord, transform != info.extensions.end() ? &transform->second : nullptr,
                     fmt::format("materials[{}].pbrMetallicRoughness.baseColorTexture", material));
}

void transform_uvs(Mesh& mesh, const glm::mat3& uv_transform) {
  if (uv_transform == glm::mat3(1.0f)) return;  // untouched, to the bit
  for (MeshVertex& v : mesh.vertices) v.uv = glm::vec2(uv_transform * glm::vec3(v.uv, 1.0f));
}

Instance material_instance(const MaterialLook& look, const glm::mat4& world, std::uint32_t motion_id) {
  Instance instance{world, glm::vec4(glm::vec3(look.base_colour), look.spec_amount),
                    glm::vec4(look.spec_power, static_cast<float>(motion_id), 0.0f, 0.0f)};
  instance.alpha_mask = glm::vec2(look.base_colour.a, look.alpha_mask ? look.alpha_cutoff : 0.0f);
  return instance;
}

}  // namespace tilelight::gltf_detail
