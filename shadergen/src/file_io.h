// file_io.h - reading and writing files with errors that name the path and the reason.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "shadergen/diagnostic.h"

namespace shadergen {

// The whole file. Errors: "<path>: error: cannot read: <reason>".
Result<std::string> read_file(const std::filesystem::path& path);

// Writes `bytes` to a temporary file beside `path`, flushes it and renames it over `path`, so
// readers see the old file or the new one, never a part. Fails on short writes (disk full).
Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

// True when `path` exists and holds exactly `bytes`.
bool file_has_bytes(const std::filesystem::path& path, std::string_view bytes);

// A name unique to this process and call, for temporaries: ".<stem>.tmp-<pid>-<n>".
std::string temporary_name(std::string_view stem);

}  // namespace shadergen
