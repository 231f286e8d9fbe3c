#pragma once
// The run's output set: every file is written first under its temporary name in the output
// folder (tilelight/base/atomic_write.h), and renamed into place only once all of them were
// written. So a failed run (any error up to and including the last write) changes nothing in
// the folder: earlier results stay, no partial file is left. The renames themselves happen one
// file at a time: only a crash between two of them could leave new and earlier files side by
// side.

#include "tilelight/base/atomic_write.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tilelight::app {

class OutputFiles {
 public:
  // Creates `folder` if needed and proves it writable; throws tilelight::Error naming it.
  explicit OutputFiles(std::filesystem::path folder);

  // Writes `name`'s bytes under its temporary name; throws tilelight::Error naming that file.
  void stage(const std::string& name, std::span<const std::uint8_t> bytes);
  void stage_text(const std::string& name, std::string_view text);
  // Marks `name` as a file of the output set that this run does not produce (a baseline that
  // did not run): commit() removes an earlier run's copy, so the folder never shows a frame
  // from another run beside this run's report.
  void retire(const std::string& name);
  // Renames every staged file into place, in the order staged, then removes the retired ones.
  // Throws tilelight::Error naming the file that could not be renamed or removed.
  void commit();
  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path folder_;
  std::vector<atomic_file::StagedFile> staged_;  // their destructors remove what was never committed
  std::vector<std::string> retired_;
};

}  // namespace tilelight::app
