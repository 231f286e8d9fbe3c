#include "base_colour_textures.h"

#include "accessor_reader.h"
#include "external_files.h"
#include "gltf_material.h"
#include "image_decoder.h"
#include "read_file.h"
#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <cctype>
#include <utility>

namespace tilelight::gltf_detail {
namespace {

// glTF's sampler enums (the WebGL constants).
constexpr int kNearest = 9728, kLinear = 9729;
constexpr int kNearestMipmapNearest = 9984, kLinearMipmapNearest = 9985;
constexpr int kNearestMipmapLinear = 9986, kLinearMipmapLinear = 9987;
constexpr int kClampToEdge = 33071, kMirroredRepeat = 33648, kRepeat = 10497;

TextureFilter magnify_filter(int value, const std::string& user) {
  switch (value) {
    case -1:  // undefined: the loader's choice
    case kLinear: return TextureFilter::linear;
    case kNearest: return TextureFilter::nearest;
    default: throw Error(fmt::format("{}.magFilter: {} is not a glTF magnification filter (9728, 9729)", user, value));
  }
}

// Minification: the filter within a mip level, between levels, and whether mips are read.
void apply_minify_filter(int value, TextureSampling& sampling, const std::string& user) {
  switch (value) {
    case -1:
    case kLinearMipmapLinear: sampling.minify = TextureFilter::linear; return;
    case kLinear: sampling.minify = TextureFilter::linear, sampling.mipmapped = false; return;
    case kNearest: sampling.minify = TextureFilter::nearest, sampling.mipmapped = false; return;
    case kNearestMipmapNearest:
      sampling.minify = TextureFilter::nearest, sampling.between_mips = TextureFilter::nearest;
      return;
    case kLinearMipmapNearest:
      sampling.minify = TextureFilter::linear, sampling.between_mips = TextureFilter::nearest;
      return;
    case kNearestMipmapLinear: sampling.minify = TextureFilter::nearest; return;
    default:
      throw Error(
          fmt::format("{}.minFilter: {} is not a glTF minification filter (9728, 9729, 9984 to 9987)", user, value));
  }
}

TextureWrap wrap(int value, const std::string& user, const char* property) {
  switch (value) {
    case kRepeat: return TextureWrap::repeat;
    case kMirroredRepeat: return TextureWrap::mirrored_repeat;
    case kClampToEdge: return TextureWrap::clamp_to_edge;
    default: throw Error(fmt::format("{}.{}: {} is not a glTF wrap mode (33071, 33648, 10497)", user, property, value));
  }
}

TextureSampling sampling_of(const tinygltf::Model& model, int sampler_index, const std::string& texture_name) {
  TextureSampling sampling;
  if (sampler_index < 0) return sampling;  // glTF: repeat, filters the loader's choice
  if (static_cast<std::size_t>(sampler_index) >= model.samplers.size()) {
    throw Error(fmt::format("{}.sampler: sampler {} does not exist (the file has {})", texture_name, sampler_index,
                            model.samplers.size()));
  }
  const tinygltf::Sampler& sampler = model.samplers[static_cast<std::size_t>(sampler_index)];
  const std::string name = fmt::format("samplers[{}]", sampler_index);
  sampling.magnify = magnify_filter(sampler.magFilter, name);
  apply_minify_filter(sampler.minFilter, sampling, name);
  sampling.wrap_u = wrap(sampler.wrapS, name, "wrapS");
  sampling.wrap_v = wrap(sampler.wrapT, name, "wrapT");
  return sampling;
}

}  // namespace

bool keep_encoded_image(tinygltf::Image* image, int, std::string*, std::string*, int, int, const unsigned char* bytes,
                        int size, void*) {
  // A buffer-view image's bytes are tinygltf's unchecked view of the buffer: not touched here.
  if (image->bufferView >= 0 || bytes == nullptr || size <= 0) return true;
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

BaseColourTextures::BaseColourTextures(const tinygltf::Model& model, std::filesystem::path base_dir)
    : model_(model), base_dir_(std::move(base_dir)) {}

std::optional<BaseColourTexture> BaseColourTextures::of_material(int material) {
  const std::optional<BaseColourTextureRef> ref = base_colour_texture_ref(model_, material);
  if (!ref) return std::nullopt;
  return BaseColourTexture{scene_texture(ref->texture, ref->user), ref->texcoord_set, ref->uv_transform};
}

std::uint32_t BaseColourTextures::scene_texture(int texture_index, const std::string& user) {
  if (const auto found = scene_texture_of_.find(texture_index); found != scene_texture_of_.end()) return found->second;
  if (static_cast<std::size_t>(texture_index) >= model_.textures.size()) {
    throw Error(fmt::format("{}.index: texture {} does not exist (the file has {})", user, texture_index,
                            model_.textures.size()));
  }
  const tinygltf::Texture& gltf_texture = model_.textures[static_cast<std::size_t>(texture_index)];
  const std::string name = fmt::format("textures[{}]", texture_index);
  if (gltf_texture.source < 0 || static_cast<std::size_t>(gltf_texture.source) >= model_.images.size()) {
    throw Error(fmt::format("{}.source: image {} does not exist (the file has {})", name, gltf_texture.source,
                            model_.images.size()));
  }
  Texture texture;
  texture.name = gltf_texture.name.empty() ? name : gltf_texture.name;
  texture.sampling = sampling_of(model_, gltf_texture.sampler, name);
  DecodedImage image =
      decode_image(image_bytes(gltf_texture.source), fmt::format("images[{}] (used by {})", gltf_texture.source, name));
  texels_ += std::uint64_t{image.width} * image.height;
  if (texels_ > kMaxSceneTexels) {
    throw Error(
        fmt::format("{}: the scene's base colour textures have more than {} texels together", name, kMaxSceneTexels));
  }
  texture.width = image.width;
  texture.height = image.height;
  texture.rgba = std::move(image.rgba);
  const auto index = static_cast<std::uint32_t>(textures_.size());
  textures_.push_back(std::move(texture));
  scene_texture_of_.emplace(texture_index, index);
  return index;
}

std::vector<std::uint8_t> BaseColourTextures::image_bytes(int image_index) const {
  const tinygltf::Image& image = model_.images[static_cast<std::size_t>(image_index)];
  const std::string name = fmt::format("images[{}]", image_index);
  if (image.bufferView >= 0) {
    const std::span<const std::uint8_t> bytes = buffer_view_bytes(model_, image.bufferView, name);
    return {bytes.begin(), bytes.end()};
  }
  if (image.as_is) return image.image;  // a data URI, decoded from base64 by tinygltf
  if (image.uri.empty()) throw Error(name + ": neither a bufferView nor a uri");
  if (base_dir_.empty()) {
    throw Error(
        fmt::format("{}: the external image \"{}\" is not read (a load from memory reads no files)", name, image.uri));
  }
  const std::filesystem::path path = external_file(base_dir_, image.uri, name);
  return read_file(path, fmt::format("{}: {}", name, path.string()));
}

}  // namespace tilelight::gltf_detail
