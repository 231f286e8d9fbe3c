// blob_spill.h - a build's SPIR-V on disk while the build runs.
//
// A build keeps no blob's words in memory: each distinct blob is written here as soon as it is
// made (compiled or loaded, reflected and, with strip_debug, stripped), under the SHA-256 of its
// words, and read back one at a time when the generated source is written. The folder is a
// sibling of the output folder (spill_folder_beside()), so that the output's staging can link
// the files in rather than copy them. It is created on first use and removed, with everything
// in it, when the BlobSpill is destroyed: on success, failure and cancellation alike.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "shadergen/diagnostic.h"

namespace shadergen {

class BlobSpill {
 public:
  // `output` is the folder the user named, which the spill sits beside: errors name it and the
  // output file a spill file becomes, never the spill's own name (empty: the spill's paths).
  explicit BlobSpill(std::filesystem::path folder, std::filesystem::path output = {})
      : folder_(std::move(folder)), output_(std::move(output)) {}
  ~BlobSpill();
  BlobSpill(const BlobSpill&) = delete;
  BlobSpill& operator=(const BlobSpill&) = delete;

  // Writes `words` as the file of `hash` (their SHA-256, hex) unless it was written already.
  // Thread-safe.
  Status put(const std::string& hash, std::span<const std::uint32_t> words);
  // The words put() wrote under `hash`.
  Result<std::vector<std::uint32_t>> get(const std::string& hash) const;
  // The file of `hash`; it exists once put() returned for it.
  std::filesystem::path path_of(const std::string& hash) const;
  // A file of the build's own in the folder (the generated source), which this creates if needed.
  // `name` must not end in ".spv".
  Result<std::filesystem::path> scratch_file(const std::string& name);

  const std::filesystem::path& folder() const { return folder_; }
  // The output path the user knows for spill file `file`, for messages: a blob as
  // <output>/spirv/<its file>, any other file as <output>/<its name>.
  std::filesystem::path shown(const std::filesystem::path& file) const;
  // errno's text after a failed write, or a guess when errno says nothing.
  static std::string write_failure(int error);

 private:
  Status create_folder();  // callers hold mutex_

  std::filesystem::path folder_;
  std::filesystem::path output_;
  mutable std::mutex mutex_;
  bool created_ = false;
  // Hashes put() has written or is writing: a SHA-256 in hex as its 32 bytes (one per blob of
  // the build, so half the memory of the hex text and no allocation of its own), anything else
  // as given.
  bool first_put(const std::string& hash);  // callers hold mutex_
  std::set<std::array<unsigned char, 32>> stored_digests_;
  std::set<std::string> stored_;
};

}  // namespace shadergen
