// The one translation unit that compiles tinygltf's implementation (README.Debian of
// libtinygltf-dev describes this route), configured by tinygltf.h.
//
// tinygltf 2.7.0's writer uses std::ofstream even with TINYGLTF_NO_FS, which leaves <fstream>
// out; so it is included here first.
#include <fstream>

#define TINYGLTF_IMPLEMENTATION
#include "tinygltf.h"
