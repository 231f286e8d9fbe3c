#pragma once
// Atomic file output in the runtime's error model: the project's one atomic write
// (common/atomic_file, <atomic_file/atomic_file.h>) with its failures thrown as tilelight::Error,
// worded by atomic_file::describe() ("cannot create <temporary>: <reason>", "cannot write
// <temporary>: <reason>", "cannot replace <final>: <reason>").

#include <atomic_file/atomic_file.h>

#include <cstdint>
#include <filesystem>
#include <span>

namespace tilelight {

// Writes `bytes` under a temporary name beside `path`, ready for commit_staged(). Throws
// tilelight::Error when the write fails (no temporary is left then). Precondition: the folder
// of `path` exists.
atomic_file::StagedFile stage_file(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

// Renames a staged file into place. Throws tilelight::Error on failure (the temporary is
// removed). Precondition: `file` came from stage_file() and was not committed yet.
void commit_staged(atomic_file::StagedFile& file);

// stage_file() then commit_staged(): `path` holds either its old content or exactly `bytes`.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

}  // namespace tilelight
