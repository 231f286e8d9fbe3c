#include "external_files.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <cctype>
#include <system_error>

namespace tilelight::gltf_detail {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower >= 'a' && lower <= 'f' ? lower - 'a' + 10 : -1;
}

// A URI reference's path as a file path: %XX escapes decoded (glTF URIs are RFC 3986).
std::string decode_percent_escapes(const std::string& uri) {
  std::string path;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex_digit(uri[i + 1]) >= 0 && hex_digit(uri[i + 2]) >= 0) {
      path += static_cast<char>(hex_digit(uri[i + 1]) * 16 + hex_digit(uri[i + 2]));
      i += 2;
    } else {
      path += uri[i];
    }
  }
  return path;
}

}  // namespace

std::filesystem::path external_file(const std::filesystem::path& base_dir, const std::string& uri,
                                    const std::string& element) {
  std::error_code ec;
  std::filesystem::path path = std::filesystem::absolute(base_dir / decode_percent_escapes(uri), ec);
  if (ec) path = base_dir / decode_percent_escapes(uri);
  path = path.lexically_normal();
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    throw Error(fmt::format("{}: the file {} does not exist (uri \"{}\")", element, path.string(), uri));
  }
  if (std::filesystem::is_directory(status)) {
    throw Error(fmt::format("{}: {} is a folder, not a file (uri \"{}\")", element, path.string(), uri));
  }
  return path;
}

void check_external_buffers(const nlohmann::json& root, const std::filesystem::path& base_dir) {
  const auto buffers = root.find("buffers");
  if (buffers == root.end()) return;
  for (std::size_t i = 0; i < buffers->size(); ++i) {
    const auto uri = (*buffers)[i].find("uri");
    if (uri == (*buffers)[i].end() || uri->get<std::string>().rfind("data:", 0) == 0) continue;
    const std::string element = fmt::format("buffers[{}]", i);
    if (base_dir.empty()) {
      throw Error(fmt::format("{}: the external file \"{}\" is not read (a load from memory reads no files)", element,
                              uri->get<std::string>()));
    }
    (void)external_file(base_dir, uri->get<std::string>(), element);
  }
}

}  // namespace tilelight::gltf_detail
