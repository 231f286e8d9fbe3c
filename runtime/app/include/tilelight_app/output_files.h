#pragma once
// All-or-nothing output: files are written under temporary names in the output folder and
// renamed into place only when every one of them was written, so a failed run leaves the
// folder as it was (earlier results intact, no partial files).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace tilelight::app {

class OutputFiles {
 public:
  // Creates `folder` if needed and proves it writable; throws tilelight::Error naming it.
  explicit OutputFiles(std::filesystem::path folder);
  ~OutputFiles();  // removes whatever was staged but not committed
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // `write` receives the temporary path to write `name` to.
  void stage(const std::string& name, const std::function<void(const std::filesystem::path&)>& write);
  void stage_text(const std::string& name, const std::string& text);
  // Renames every staged file into place.
  void commit();
  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path folder_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // temp -> final
};

}  // namespace tilelight::app
