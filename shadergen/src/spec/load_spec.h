// load_spec.h - the one way a spec file is read: its bytes read once, parsed, and hashed, so the
// spec and the digest that keys the input-set cache (cache/input_cache.h) come from the same
// bytes even while the file is being edited. load_domain() (shadergen/domain.h) is this without
// the digest, for `shadergen lut`, `list` and `explain`.
#pragma once

#include <filesystem>
#include <string>

#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"

namespace shadergen {

struct LoadedSpec {
  DomainSpec spec;
  std::string digest;  // SHA-256 of the bytes parsed, hex
};

// Errors name `spec_path`: "spec file does not exist", "spec path is a directory, not a file",
// "cannot open spec file for reading", "spec is larger than N bytes", or the spec's own.
Result<LoadedSpec> load_spec(const std::filesystem::path& spec_path);

}  // namespace shadergen
