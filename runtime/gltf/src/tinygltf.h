#pragma once
// tinygltf as this library uses it: every file that includes tiny_gltf.h includes it through
// here, so all of them see the same configuration.
//   TINYGLTF_NO_FS               no default file callbacks: load_gltf.cpp supplies its own (the
//                                default ExpandFilePath runs wordexp() on every URI)
//   TINYGLTF_NO_STB_IMAGE(_WRITE) no image decoding or writing: textures are not sampled
//   TINYGLTF_NO_EXTERNAL_IMAGE   external image files are not even read
#define TINYGLTF_NO_FS
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
