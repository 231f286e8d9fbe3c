#include "spec/load_spec.h"

#include <whole_file/whole_file.h>

#include <optional>

#include "base/sha256.h"
#include "spec/json.h"

namespace shadergen {

Result<LoadedSpec> load_spec(const std::filesystem::path& spec_path) {
  std::error_code ec;
  if (!std::filesystem::exists(spec_path, ec)) return make_error(spec_path.string(), 0, "spec file does not exist");
  if (std::filesystem::is_directory(spec_path, ec))
    return make_error(spec_path.string(), 0, "spec path is a directory, not a file");
  std::string text;
  if (std::optional<whole_file::Failure> failure = whole_file::read(spec_path, text, json::kMaxJsonBytes)) {
    switch (failure->step) {
      case whole_file::Failure::Step::open:
        return make_error(spec_path.string(), 0, "cannot open spec file for reading");
      case whole_file::Failure::Step::too_large:
        return make_error(spec_path.string(), 0,
                          "spec is larger than " + std::to_string(json::kMaxJsonBytes) + " bytes");
      case whole_file::Failure::Step::read:
        return make_error(spec_path.string(), 0, "cannot read spec file: " + failure->reason.message());
    }
  }
  auto spec = parse_domain(text, spec_path);
  if (!spec) return std::move(spec).take_errors();
  return LoadedSpec{std::move(spec).value(), sha256_hex(text)};
}

Result<DomainSpec> load_domain(const std::filesystem::path& spec_path) {
  auto loaded = load_spec(spec_path);
  if (!loaded) return std::move(loaded).take_errors();
  return std::move(loaded->spec);
}

}  // namespace shadergen
