// file_io.h - reading and writing files with errors that name the path and the reason.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "shadergen/diagnostic.h"

namespace shadergen {

// The whole file. Errors: "<path>: error: cannot read: <reason>".
Result<std::string> read_file(const std::filesystem::path& path);

// The project's atomic write (<atomic_file/atomic_file.h>: a temporary beside `path`, flushed,
// renamed over it) in shadergen's error model: readers see the old file or the new one, never a
// part. Errors name `path`: "cannot write: <reason>", "write failed: <reason>" (a short write,
// such as a full disk) or "cannot replace: <reason>".
// `durable` = false skips the sync to disk: for files that verify themselves on read.
Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes, bool durable = true);

// True when `path` exists and holds exactly `bytes`.
bool file_has_bytes(const std::filesystem::path& path, std::string_view bytes);

// True when both files exist and hold the same bytes; compared in blocks.
bool files_equal(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace shadergen
