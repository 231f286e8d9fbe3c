#include "output_dir.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "file_io.h"

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
    return out_dir.parent_path() / temporary_name(name.string() + "." + std::string(what));
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

}  // namespace

bool StagedOutput::unchanged() const {
    std::error_code ec;
    if (!fs::is_directory(out_dir_, ec)) return false;
    std::set<std::string> present = existing_files(out_dir_);
    if (present.size() != files_.size()) return false;
    for (const auto& [relative, bytes] : files_)
        if (!present.count(relative) || !file_has_bytes(out_dir_ / relative, bytes)) return false;
    return true;
}

Status StagedOutput::stage(const fs::path& staging) const {
    std::error_code ec;
    for (const auto& [relative, bytes] : files_) {
        fs::path target = staging / relative;
        fs::create_directories(target.parent_path(), ec);
        if (ec) return make_error(target.parent_path().string(), 0, "cannot create folder: " + ec.message());
        fs::path previous = out_dir_ / relative;
        if (file_has_bytes(previous, bytes)) {
            fs::create_hard_link(previous, target, ec);
            if (!ec) continue;  // otherwise fall through and write a copy
            ec.clear();
        }
        if (Status written = write_file_atomic(target, bytes); !written) return written;
    }
    return Ok{};
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
        return make_error(out_dir_.string(), 0, std::string("cannot move the previous output aside: ") + std::strerror(errno));
    if (std::rename(staging.c_str(), out_dir_.c_str()) != 0) {
        int error = errno;
        std::rename(old.c_str(), out_dir_.c_str());  // put the previous output back
        return make_error(out_dir_.string(), 0, std::string("cannot replace output folder: ") + std::strerror(error));
    }
    fs::remove_all(old, ec);
    return Ok{};
}

Result<bool> StagedOutput::commit() {
    std::error_code ec;
    if (!out_dir_.parent_path().empty()) {
        fs::create_directories(out_dir_.parent_path(), ec);
        if (ec) return make_error(out_dir_.parent_path().string(), 0, "cannot create folder: " + ec.message());
    }
    ParentLock lock(out_dir_.parent_path());
    if (!lock.locked())
        return make_error(out_dir_.parent_path().string(), 0, std::string("cannot lock folder: ") + std::strerror(errno));
    if (unchanged()) return false;
    fs::path staging = sibling(out_dir_, "staging");
    fs::create_directory(staging, ec);
    if (ec) return make_error(staging.string(), 0, "cannot create staging folder: " + ec.message());
    Status status = stage(staging);
    if (status) status = swap_in(staging);
    if (!status) {
        fs::remove_all(staging, ec);
        return std::move(status).take_errors();
    }
    return true;
}

}  // namespace shadergen
