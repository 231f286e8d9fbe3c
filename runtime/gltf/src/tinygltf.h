#pragma once
// tinygltf as this library uses it: every file that includes tiny_gltf.h includes it through
// here, so all of them see the same configuration.
//   TINYGLTF_NO_FS               no default file callbacks: load_gltf.cpp supplies its own (the
//                                default ExpandFilePath runs wordexp() on every URI)
//   TINYGLTF_NO_STB_IMAGE(_WRITE) no image decoding or writing by tinygltf: only the images a
//                                material uses as base colour are decoded, later, by
//                                base_colour_textures.cpp (with its own bounds checks and limits)
//   TINYGLTF_NO_EXTERNAL_IMAGE   external image files are not read by tinygltf either: the same
//                                file reads them when, and only when, they are used
#define TINYGLTF_NO_FS
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
