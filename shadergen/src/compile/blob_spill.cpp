#include "compile/blob_spill.h"

#include <cerrno>
#include <cstdio>
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
  // Worded as the output's staging words them: the user named the output, not the spill.
  std::error_code ec;
  const fs::path parent = folder_.parent_path();
  const std::string named = (output_.empty() ? folder_ : output_).string();
  if (!parent.empty()) fs::create_directories(parent, ec);
  if (ec) return make_error(named, 0, "cannot create its parent folder " + parent.string() + ": " + ec.message());
  fs::create_directory(folder_, ec);
  if (ec)
    return make_error(named, 0, "cannot create a spill folder beside it (" + folder_.string() + "): " + ec.message());
  created_ = true;
  return Ok{};
}

bool BlobSpill::first_put(const std::string& hash) {
  auto nibble = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;  // upper case too: "AB" and "ab" name different files
  };
  std::array<unsigned char, 32> digest{};
  bool hex = hash.size() == 2 * digest.size();
  for (std::size_t i = 0; hex && i < digest.size(); ++i) {
    int high = nibble(hash[2 * i]), low = nibble(hash[2 * i + 1]);
    hex = high >= 0 && low >= 0;
    digest[i] = static_cast<unsigned char>(high * 16 + low);
  }
  return hex ? stored_digests_.insert(digest).second : stored_.insert(hash).second;
}

Status BlobSpill::put(const std::string& hash, std::span<const std::uint32_t> words) {
  {
    std::lock_guard lock(mutex_);
    if (!first_put(hash)) return Ok{};
    if (Status s = create_folder(); !s) return s;
  }
  // Written in place, not through a temporary: no one else reads this folder, and a failed write
  // fails the build. Not synced here: the output's staging syncs the files it links in.
  const fs::path path = path_of(hash);
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return make_error(shown(path).string(), 0, std::string("cannot write: ") + std::strerror(errno));
  bool written = std::fwrite(words.data(), sizeof(std::uint32_t), words.size(), file) == words.size();
  int error = written ? 0 : errno;
  if (std::fclose(file) != 0 && written) written = false, error = errno;
  if (written) return Ok{};
  return make_error(shown(path).string(), 0, "write failed: " + write_failure(error));
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

fs::path BlobSpill::shown(const fs::path& file) const {
  if (output_.empty()) return file;
  if (file.extension() == ".spv") return output_ / "spirv" / (file.stem().string().substr(0, 16) + ".spv");
  return output_ / file.filename();
}

std::string BlobSpill::write_failure(int error) {
  return error != 0 ? std::strerror(error) : "the write did not complete (a full disk?)";
}

Result<fs::path> BlobSpill::scratch_file(const std::string& name) {
  std::lock_guard lock(mutex_);
  if (Status s = create_folder(); !s) return std::move(s).take_errors();
  return folder_ / name;
}

}  // namespace shadergen
