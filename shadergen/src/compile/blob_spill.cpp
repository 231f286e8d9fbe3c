#include "compile/blob_spill.h"

#include <cstring>

#include "base/file_io.h"

namespace shadergen {
namespace fs = std::filesystem;

BlobSpill::~BlobSpill() {
  std::error_code ec;
  if (created_) fs::remove_all(folder_, ec);
}

Status BlobSpill::create_folder() {
  if (created_) return Ok{};
  std::error_code ec;
  if (!folder_.parent_path().empty()) fs::create_directories(folder_.parent_path(), ec);
  if (!ec) fs::create_directory(folder_, ec);
  if (ec) return make_error(folder_.string(), 0, "cannot create the folder for the build's SPIR-V: " + ec.message());
  created_ = true;
  return Ok{};
}

Status BlobSpill::put(const std::string& hash, std::span<const std::uint32_t> words) {
  {
    std::lock_guard lock(mutex_);
    if (!stored_.insert(hash).second) return Ok{};
    if (Status s = create_folder(); !s) return s;
  }
  // Not synced here: the output's staging syncs the files it links in.
  std::string_view bytes(reinterpret_cast<const char*>(words.data()), words.size_bytes());
  Status written = write_file_atomic(path_of(hash), bytes, false);
  if (!written) {
    std::lock_guard lock(mutex_);
    stored_.erase(hash);
  }
  return written;
}

Result<std::vector<std::uint32_t>> BlobSpill::get(const std::string& hash) const {
  auto bytes = read_file(path_of(hash));
  if (!bytes) return std::move(bytes).take_errors();
  if (bytes->size() % sizeof(std::uint32_t) != 0)
    return make_error(path_of(hash).string(), 0, "not a whole number of SPIR-V words");
  std::vector<std::uint32_t> words(bytes->size() / sizeof(std::uint32_t));
  if (!words.empty()) std::memcpy(words.data(), bytes->data(), bytes->size());
  return words;
}

fs::path BlobSpill::path_of(const std::string& hash) const { return folder_ / (hash + ".spv"); }

Result<fs::path> BlobSpill::scratch_file(const std::string& name) {
  std::lock_guard lock(mutex_);
  if (Status s = create_folder(); !s) return std::move(s).take_errors();
  return folder_ / name;
}

}  // namespace shadergen
