// output_dir.h - replacing an output folder all at once.
//
// Files are staged in a sibling folder; commit() then swaps it in with two renames, so a
// failed or interrupted build never leaves a half-written output behind, and the previous
// output stays exactly as it was until the new one is complete. Files whose bytes did not
// change are hard-linked from the previous output, keeping their timestamps, so a build
// system that watches them (Ninja's restat) rebuilds nothing downstream.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "shadergen/diagnostic.h"

namespace shadergen {

class StagedOutput {
 public:
  explicit StagedOutput(std::filesystem::path out_dir) : out_dir_(std::move(out_dir)) {}

  // `relative` uses '/' separators and stays inside the folder.
  void add(const std::string& relative, std::string bytes) { files_[relative] = Entry{std::move(bytes), {}}; }
  // A file whose bytes are already on disk, in `file`: compared by streaming and linked (or, on
  // another file system, copied) into the staging folder, so they are never held in memory.
  // `file` should be on the output's file system (a folder beside it: spill_folder_beside())
  // and must stay unchanged until commit() returns.
  void add_file(const std::string& relative, const std::filesystem::path& file) {
    files_[relative] = Entry{{}, file.native()};
  }

  // True when the folder already holds exactly these files with exactly these bytes.
  bool unchanged() const;

  // Writes the new folder and swaps it in. Does nothing if unchanged(). On failure the old
  // folder is intact and no staging folder is left behind; errors name the output path.
  // `cancelled` (may be empty) is asked once more after staging, before the swap, so an
  // interrupt that arrives while files are written still leaves the old folder in place.
  //
  // Concurrency: the whole commit runs under an exclusive flock() on the parent folder, so
  // builds into the same output take turns; the second finds the folder unchanged. Under
  // that lock any staging or set-aside folder of this output is a leftover of a killed
  // build: it is removed, or put back as the output if the kill came between the renames.
  // A spill folder (spill_folder_beside()) is removed only when its process is gone.
  Result<bool> commit(const std::function<bool()>& cancelled = {});

 private:
  Status stage(const std::filesystem::path& staging) const;
  void clear_leftovers() const;
  Status swap_in(const std::filesystem::path& staging);

  struct Entry {
    std::string bytes;
    // When not empty, the file that holds the bytes instead. A string, not a path: a build adds
    // one per blob, and a path also keeps a list of its components (a few hundred bytes more).
    std::string file;
  };
  bool holds(const std::filesystem::path& path, const Entry& entry) const;

  std::filesystem::path out_dir_;
  std::map<std::string, Entry> files_;
};

// A new folder name beside `out_dir` for a build's files before they are staged (BlobSpill).
// It is not one of the staging or set-aside names that a commit clears as leftovers: a
// concurrent build's spill folder stays untouched.
std::filesystem::path spill_folder_beside(const std::filesystem::path& out_dir);

}  // namespace shadergen
