// cache.h - the content cache: compiled, optimised, validated blobs keyed by everything that
// determines them (preprocessed source, stage, target, optimiser recipe, tool version).
//
// An entry is verified before use: magic, format version, its own key and a SHA-256 of the
// payload. A truncated, corrupted or foreign entry reads as a miss and is recompiled, never
// used; entries are written to a temporary file and renamed, so readers never see half of one.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "shadergen/diagnostic.h"

namespace shadergen {

struct CachedBlob {
  std::vector<std::uint32_t> words;
  bool fell_back = false;  // see OptimisedBlob
  std::string fallback_reason;
};

class ContentCache {
 public:
  // A disabled cache: every lookup misses and stores are dropped.
  ContentCache() = default;
  explicit ContentCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

  bool enabled() const { return !directory_.empty(); }
  const std::filesystem::path& directory() const { return directory_; }

  std::optional<CachedBlob> load(std::string_view key) const;
  // Errors name the entry path; callers may treat them as warnings (the build still works).
  Status store(std::string_view key, const CachedBlob& blob) const;

  std::filesystem::path entry_path(std::string_view key) const;

  // What this machine knows a remote cache holds (it sent or received those entries): one
  // file of keys per server, read once and written once per build, so that a warm build offers
  // the server only what it may lack, and sends nothing once the server has everything.
  // `server` is any stable name of the server (its URL without credentials). Best effort: a
  // list that cannot be read or written only costs existence checks later.
  std::set<std::string> keys_on_server(std::string_view server) const;
  void remember_keys_on_server(std::string_view server, const std::set<std::string>& keys) const;

 private:
  std::filesystem::path directory_;
};

// Everything besides the source that decides a blob's bytes. No command-line flag changes a
// blob (-j, --stats, --depfile, --cpp-name, --namespace only change other files), so the
// tool and library versions, the target and the optimiser recipe are the whole list.
struct CacheKeyParts {
  std::string tool_version;         // SHADERGEN_VERSION
  std::string glslang_version;      // the compiler library linked in
  std::string spirv_tools_version;  // the optimiser and validator library linked in
  std::string target;               // target_description() of the domain's target
  std::string optimiser_recipe;     // kOptimiserRecipe (compile/spirv_passes.h)
};

// The key of a stage-`stage_name` blob compiled from `preprocessed` text by the tool described
// by `parts` (compile/toolchain.h describes this one; tests describe "another version").
std::string cache_key(const CacheKeyParts& parts, std::string_view stage_name, std::string_view preprocessed);

// $SHADERGEN_CACHE_DIR, else $XDG_CACHE_HOME/shadergen, else ~/.cache/shadergen; empty if none
// of those variables is set.
std::filesystem::path default_cache_directory();

// Serialised entry, exposed for tests that corrupt entries on purpose.
std::string encode_cache_entry(std::string_view key, const CachedBlob& blob);
std::optional<CachedBlob> decode_cache_entry(std::string_view key, std::string_view bytes);

}  // namespace shadergen
