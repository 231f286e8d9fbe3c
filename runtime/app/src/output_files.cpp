#include "tilelight/app/output_files.h"

#include "tilelight/base/error.h"

#include <cstring>
#include <system_error>

namespace tilelight::app {
namespace fs = std::filesystem;

OutputFiles::OutputFiles(fs::path folder) : folder_(std::move(folder)) {
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (ec) throw OptionError("--out", "--out " + folder_.string() + ": cannot create the folder: " + ec.message());
  if (!fs::is_directory(folder_)) throw OptionError("--out", "--out " + folder_.string() + ": not a folder");
  atomic_file::StagedFile probe(folder_ / "write-test", {});  // removed again by its destructor
  if (probe.failure()) {
    throw OptionError("--out",
                      "--out " + folder_.string() + ": cannot write there: " + atomic_file::describe(*probe.failure()));
  }
}

void OutputFiles::stage(const std::string& name, std::span<const std::uint8_t> bytes) {
  staged_.push_back(stage_file(folder_ / name, bytes));
}

void OutputFiles::stage_text(const std::string& name, std::string_view text) {
  stage(name, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

void OutputFiles::retire(const std::string& name) { retired_.push_back(name); }

void OutputFiles::commit() {
  for (atomic_file::StagedFile& file : staged_) commit_staged(file);
  staged_.clear();
  for (const std::string& name : retired_) {
    std::error_code ec;
    fs::remove(folder_ / name, ec);  // false without an error when there was none
    if (ec) throw Error("cannot remove the earlier run's " + (folder_ / name).string() + ": " + ec.message());
  }
  retired_.clear();
}

}  // namespace tilelight::app
