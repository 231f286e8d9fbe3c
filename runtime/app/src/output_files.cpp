#include "tilelight/app/output_files.h"

#include "tilelight/base/error.h"

#include <cstring>
#include <system_error>

namespace tilelight::app {
namespace fs = std::filesystem;

OutputFiles::OutputFiles(fs::path folder) : folder_(std::move(folder)) {
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (ec) throw Error("--out " + folder_.string() + ": cannot create the folder: " + ec.message());
  if (!fs::is_directory(folder_)) throw Error("--out " + folder_.string() + ": not a folder");
  try {
    StagedFile probe(folder_ / "write-test", {});  // removed again by its destructor
  } catch (const Error& e) {
    throw Error("--out " + folder_.string() + ": cannot write there: " + e.what());
  }
}

void OutputFiles::stage(const std::string& name, std::span<const std::uint8_t> bytes) {
  staged_.emplace_back(folder_ / name, bytes);
}

void OutputFiles::stage_text(const std::string& name, std::string_view text) {
  stage(name, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

void OutputFiles::commit() {
  for (StagedFile& file : staged_) file.commit();
  staged_.clear();
}

}  // namespace tilelight::app
