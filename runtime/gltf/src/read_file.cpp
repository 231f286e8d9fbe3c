#include "read_file.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace tilelight::gltf_detail {

std::vector<std::uint8_t> read_file(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(what + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw Error(what + ": cannot open: " + std::strerror(errno));
  const std::streamoff size = in.tellg();
  if (size < 0) throw Error(what + ": cannot read its size");
  if (static_cast<std::uint64_t>(size) > kMaxFileBytes) {
    throw Error(fmt::format("{}: {} bytes, more than this loader reads ({})", what, size, kMaxFileBytes));
  }
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), size))
    throw Error(what + ": read failed: " + std::strerror(errno));
  return bytes;
}

}  // namespace tilelight::gltf_detail
