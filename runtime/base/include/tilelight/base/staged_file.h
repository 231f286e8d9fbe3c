#pragma once
// Atomic file output, the runtime's only way to write a file: the bytes go to a temporary file
// beside the final path and are renamed over it, so a reader (a later comparison, a human, a
// concurrent run) sees the old file or the whole new one, never half of it, and a failed write
// leaves the old file as it was.

#include <cstdint>
#include <filesystem>
#include <span>

namespace tilelight {

// One file written under its temporary name, ".<file name>.tmp-<pid>" in the final path's
// folder (the same file system, so the rename is atomic), waiting for commit().
class StagedFile {
 public:
  // Writes `bytes` to the temporary file. Precondition: the final path's folder exists.
  // Throws tilelight::Error "cannot create <temporary>: <reason>" or "cannot write
  // <temporary>: <reason>"; no temporary file is left behind then.
  StagedFile(std::filesystem::path final_path, std::span<const std::uint8_t> bytes);
  ~StagedFile();  // removes the temporary file unless commit() moved it
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&&) = delete;
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  // Renames the temporary file over the final path. Throws tilelight::Error "renaming
  // <temporary> to <final> failed: <reason>" (and removes the temporary file).
  // Precondition: not committed yet.
  void commit();

  const std::filesystem::path& temporary_path() const { return temporary_; }
  const std::filesystem::path& final_path() const { return final_; }

 private:
  std::filesystem::path final_;
  std::filesystem::path temporary_;  // empty once committed or moved from
};

// StagedFile(path, bytes).commit(): `path` holds either its old content or exactly `bytes`.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

}  // namespace tilelight
