#include "tilelight_app/output_files.h"

#include "tilelight/error.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace tilelight::app {
namespace fs = std::filesystem;
namespace {

std::string temporary_name(const std::string& name) {
  return "." + name + ".partial-" + std::to_string(::getpid());
}

}  // namespace

OutputFiles::OutputFiles(fs::path folder) : folder_(std::move(folder)) {
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (ec) throw Error("--out " + folder_.string() + ": cannot create the folder: " + ec.message());
  if (!fs::is_directory(folder_)) throw Error("--out " + folder_.string() + ": not a folder");
  const fs::path probe = folder_ / temporary_name("write-test");
  {
    std::ofstream file(probe);
    if (!file) {
      throw Error("--out " + folder_.string() + ": cannot write there: " + std::strerror(errno));
    }
  }
  fs::remove(probe, ec);
}

OutputFiles::~OutputFiles() {
  std::error_code ec;
  for (const auto& entry : staged_) fs::remove(entry.first, ec);
}

void OutputFiles::stage(const std::string& name, const std::function<void(const fs::path&)>& write) {
  const fs::path temporary = folder_ / temporary_name(name);
  staged_.emplace_back(temporary, folder_ / name);
  write(temporary);
}

void OutputFiles::stage_text(const std::string& name, const std::string& text) {
  stage(name, [&](const fs::path& path) {
    std::ofstream file(path, std::ios::binary);
    file << text;
    file.close();
    if (!file) throw Error(path.string() + ": cannot write: " + std::strerror(errno));
  });
}

void OutputFiles::commit() {
  for (const auto& [temporary, final_path] : staged_) {
    std::error_code ec;
    fs::rename(temporary, final_path, ec);
    if (ec) throw Error(final_path.string() + ": cannot move into place: " + ec.message());
  }
  staged_.clear();
}

}  // namespace tilelight::app
