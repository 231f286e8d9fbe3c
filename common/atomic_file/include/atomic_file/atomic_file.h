// atomic_file.h - the project's one way to write a file that readers must never see half
// written: shadergen's outputs and cache entries, tilelight's pictures and reports.
//
// The bytes go to a temporary file beside the final path (the same folder, so the same file
// system), are flushed to the disk, and the temporary is renamed over the final path. A reader
// (a build, a comparison, a human, a concurrent run) sees the old file or the whole new one, and
// a failed or interrupted write leaves the old file as it was.
//
// No exceptions and no message wording: a failure comes back as a Failure (which step, which
// file, the OS reason), and each caller words it in its own error model (shadergen's Result,
// tilelight's Error). describe() gives a default wording.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace atomic_file {

struct Failure {
  enum class Step {
    create,   // the temporary file could not be created (`path` is the temporary)
    write,    // writing, flushing or closing it failed, e.g. a full disk (`path` is the temporary)
    replace,  // renaming it over the final file failed (`path` is the final file)
  };
  Step step;
  std::filesystem::path path;
  std::error_code reason;
};

// "cannot create <path>: <reason>", "cannot write <path>: <reason>" or "cannot replace <path>:
// <reason>".
std::string describe(const Failure& failure);

// A name unique to this process and call, for temporaries beside a final file or folder:
// ".<stem>.tmp-<pid>-<n>". Thread-safe.
std::string temporary_name(std::string_view stem);

// One file written under its temporary name and flushed, waiting for commit(). Several staged
// files committed one after the other is how a run publishes a set of files late: nothing
// appears until everything was written.
class StagedFile {
 public:
  // Writes `bytes` to the temporary file. Precondition: the final path's folder exists (a
  // missing one is reported as a `create` failure). On failure no temporary is left behind and
  // failure() says why. `durable`: the bytes are synced to the disk before the rename, so that
  // a crash never publishes an empty file; false only for files that check themselves on read
  // (shadergen's cache entries), where a torn file is harmless and the sync only costs time.
  StagedFile(std::filesystem::path final_path, std::string_view bytes, bool durable = true);
  ~StagedFile();  // removes the temporary file unless commit() moved it
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&&) = delete;
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  // The failure of the write, if it failed.
  const std::optional<Failure>& failure() const { return failure_; }

  // Renames the temporary file over the final path; on failure removes the temporary and
  // returns why. Precondition: !failure() and not committed yet.
  std::optional<Failure> commit();

  const std::filesystem::path& temporary_path() const { return temporary_; }
  const std::filesystem::path& final_path() const { return final_; }

 private:
  std::filesystem::path final_;
  std::filesystem::path temporary_;  // empty once committed, moved from or failed
  std::optional<Failure> failure_;
};

// StagedFile(path, bytes) then commit(): afterwards `path` holds either its old content or
// exactly `bytes`. Returns the failure, or nothing when the file was written.
std::optional<Failure> write(const std::filesystem::path& path, std::string_view bytes, bool durable = true);

}  // namespace atomic_file
