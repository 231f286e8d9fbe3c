#include "output/output_dir.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include "base/file_io.h"

#include <atomic_file/atomic_file.h>

namespace shadergen {
namespace fs = std::filesystem;

namespace {

std::set<std::string> existing_files(const fs::path& dir) {
  std::set<std::string> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file()) out.insert(it->path().lexically_relative(dir).generic_string());
  return out;
}

// A sibling of the output folder, so that renames stay on one file system.
fs::path sibling(const fs::path& out_dir, std::string_view what) {
  fs::path name = out_dir.filename();
  return out_dir.parent_path() / atomic_file::temporary_name(name.string() + "." + std::string(what));
}

// The start of every sibling(out_dir, what) name (see temporary_name()).
std::string sibling_prefix(const fs::path& out_dir, std::string_view what) {
  return std::string(".").append(out_dir.filename().string()).append(".").append(what).append(".tmp-");
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// remove_all() that also works on a tree whose folders are read-only (a user's `chmod -R a-w`
// on the output, or a checkout that keeps build outputs read-only): deleting an entry needs
// write permission on its folder, so every folder is first made owner-writable. Only trees
// that this class set aside are removed this way.
void remove_tree(const fs::path& root, std::error_code& ec) {
  const auto owner_writable = [](const fs::path& dir) {
    std::error_code ignored;
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add, ignored);
  };
  if (fs::is_directory(fs::symlink_status(root, ec))) {
    owner_writable(root);
    for (fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec))
      if (it->is_directory() && !it->is_symlink()) owner_writable(it->path());
  }
  ec.clear();
  fs::remove_all(root, ec);
}

// The same failure, reported against `path` (the output file the user knows) instead of the
// staging copy that no longer exists once the commit has failed.
Status renamed(Status status, const fs::path& path) {
  if (status) return status;
  Diagnostics errors = std::move(status).take_errors();
  for (Diagnostic& d : errors) d.file = path.string();
  return errors;
}

// Holds an exclusive flock() on the folder that contains the output, so that two builds
// writing the same output take turns at the swap. Locking the folder itself (rather than a
// lock file) leaves nothing behind. Released by the destructor, or by the kernel if the
// process dies.
class ParentLock {
 public:
  explicit ParentLock(const fs::path& dir) {
    fd_ = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) {
      ::close(fd_);
      fd_ = -1;
    }
  }
  ~ParentLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  ParentLock(const ParentLock&) = delete;
  ParentLock& operator=(const ParentLock&) = delete;
  bool locked() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

// A spill folder belongs to a build that may still run (it is not under this lock until its
// commit): it is a leftover only when the process named in it ("<pid>-<n>") no longer exists.
bool owner_is_gone(const std::string& pid_and_count) {
  const auto dash = pid_and_count.find('-');
  if (dash == 0 || dash == std::string::npos) return false;
  long pid = 0;
  for (std::size_t i = 0; i < dash; ++i) {
    if (pid_and_count[i] < '0' || pid_and_count[i] > '9' || pid > 100000000) return false;
    pid = pid * 10 + (pid_and_count[i] - '0');
  }
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace

fs::path spill_folder_beside(const fs::path& out_dir) { return sibling(out_dir, "spill"); }

bool StagedOutput::holds(const fs::path& path, const Entry& entry) const {
  return entry.file.empty() ? file_has_bytes(path, entry.bytes) : files_equal(path, entry.file);
}

bool StagedOutput::unchanged() const {
  std::error_code ec;
  if (!fs::is_directory(out_dir_, ec)) return false;
  std::set<std::string> present = existing_files(out_dir_);
  if (present.size() != files_.size()) return false;
  for (const auto& [relative, entry] : files_)
    if (!present.count(relative) || !holds(out_dir_ / relative, entry)) return false;
  return true;
}

namespace {

// A file-backed entry's bytes as a staged file: linked when the file system allows, copied
// otherwise. stage() syncs them all at once at the end.
Status link_in(const fs::path& from, const fs::path& target) {
  std::error_code ec;
  fs::create_hard_link(from, target, ec);
  if (!ec) return Ok{};
  ec.clear();
  fs::copy_file(from, target, fs::copy_options::overwrite_existing, ec);
  if (ec) return make_error(target.string(), 0, "cannot write: " + ec.message());
  return Ok{};
}

// Makes everything written under `folder` durable before the output is swapped in, with one
// syncfs() of its file system in place of one fsync() per staged file: those took 2 of the
// 20 seconds of a cold build of 12,288 blobs (docs/results.md k5). Errors name `shown`.
Status sync_file_system(const fs::path& folder, const fs::path& shown) {
  int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return make_error(shown.string(), 0, std::string("cannot write: ") + std::strerror(errno));
  int synced = ::syncfs(fd);
  int error = errno;
  ::close(fd);
  if (synced != 0) return make_error(shown.string(), 0, std::string("write failed: ") + std::strerror(error));
  return Ok{};
}

}  // namespace

Status StagedOutput::stage(const fs::path& staging) const {
  std::error_code ec;
  std::vector<const std::pair<const std::string, Entry>*> to_write;
  for (const auto& file : files_) {
    const auto& [relative, entry] = file;
    fs::path target = staging / relative;
    fs::create_directories(target.parent_path(), ec);
    if (ec) return make_error((out_dir_ / relative).parent_path().string(), 0, "cannot create folder: " + ec.message());
    fs::path previous = out_dir_ / relative;
    if (holds(previous, entry)) {
      fs::create_hard_link(previous, target, ec);
      if (!ec) continue;  // otherwise fall through and write a copy
      ec.clear();
    }
    to_write.push_back(&file);
  }
  // Nothing is synced file by file: sync_file_system() makes all of it durable at the end.
  for (const auto* file : to_write) {
    const auto& [relative, entry] = *file;
    Status written = entry.file.empty() ? write_file_atomic(staging / relative, entry.bytes, /*durable=*/false)
                                        : link_in(entry.file, staging / relative);
    if (!written) return renamed(std::move(written), out_dir_ / relative);
  }
  return sync_file_system(staging, out_dir_);
}

Status StagedOutput::swap_in(const fs::path& staging) {
  std::error_code ec;
  if (!fs::exists(out_dir_, ec)) {
    if (std::rename(staging.c_str(), out_dir_.c_str()) != 0)
      return make_error(out_dir_.string(), 0, std::string("cannot create output folder: ") + std::strerror(errno));
    return Ok{};
  }
  if (!fs::is_directory(out_dir_, ec)) return make_error(out_dir_.string(), 0, "exists and is not a folder");
  fs::path old = sibling(out_dir_, "old");
  if (std::rename(out_dir_.c_str(), old.c_str()) != 0)
    return make_error(out_dir_.string(), 0,
                      std::string("cannot move the previous output aside: ") + std::strerror(errno));
  if (std::rename(staging.c_str(), out_dir_.c_str()) != 0) {
    int error = errno;
    std::rename(old.c_str(), out_dir_.c_str());  // put the previous output back
    return make_error(out_dir_.string(), 0, std::string("cannot replace output folder: ") + std::strerror(error));
  }
  remove_tree(old, ec);
  return Ok{};
}

void StagedOutput::clear_leftovers() const {
  const fs::path parent = out_dir_.parent_path().empty() ? fs::path(".") : out_dir_.parent_path();
  const std::string staging_prefix = sibling_prefix(out_dir_, "staging");
  const std::string old_prefix = sibling_prefix(out_dir_, "old");
  const std::string spill_prefix = sibling_prefix(out_dir_, "spill");
  std::error_code ec;
  std::vector<fs::path> leftovers;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (starts_with(name, staging_prefix) || starts_with(name, old_prefix) ||
        (starts_with(name, spill_prefix) && owner_is_gone(name.substr(spill_prefix.size()))))
      leftovers.push_back(it->path());
  }
  for (const fs::path& path : leftovers) {
    // Killed between the two renames of swap_in(): the set-aside folder is the previous
    // output, complete. Put it back rather than lose it.
    if (starts_with(path.filename().string(), old_prefix) && !fs::exists(out_dir_, ec) &&
        std::rename(path.c_str(), out_dir_.c_str()) == 0)
      continue;
    remove_tree(path, ec);
  }
}

Result<bool> StagedOutput::commit(const std::function<bool()>& cancelled) {
  std::error_code ec;
  const fs::path parent = out_dir_.parent_path();
  if (!parent.empty()) {
    fs::create_directories(parent, ec);
    if (ec)
      return make_error(out_dir_.string(), 0,
                        "cannot create its parent folder " + parent.string() + ": " + ec.message());
  }
  ParentLock lock(parent);
  if (!lock.locked())
    return make_error(out_dir_.string(), 0,
                      "cannot lock its parent folder " + (parent.empty() ? fs::path(".") : parent).string() + ": " +
                          std::strerror(errno));
  clear_leftovers();
  if (unchanged()) return false;
  fs::path staging = sibling(out_dir_, "staging");
  fs::create_directory(staging, ec);
  if (ec)
    return make_error(out_dir_.string(), 0,
                      "cannot create a staging folder beside it (" + staging.string() + "): " + ec.message());
  Status status = stage(staging);
  if (status && cancelled && cancelled()) status = make_error("build interrupted");
  if (status) status = swap_in(staging);
  if (!status) {
    fs::remove_all(staging, ec);
    return std::move(status).take_errors();
  }
  return true;
}

}  // namespace shadergen
