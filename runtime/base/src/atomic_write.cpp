#include "tilelight/base/atomic_write.h"

#include "tilelight/base/error.h"

#include <string_view>

namespace tilelight {

atomic_file::StagedFile stage_file(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  atomic_file::StagedFile staged(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  if (staged.failure()) throw Error(atomic_file::describe(*staged.failure()));
  return staged;
}

void commit_staged(atomic_file::StagedFile& file) {
  if (auto failure = file.commit()) throw Error(atomic_file::describe(*failure));
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  atomic_file::StagedFile staged = stage_file(path, bytes);
  commit_staged(staged);
}

}  // namespace tilelight
