#include "file_io.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <unistd.h>

namespace shadergen {

// Block reads into a buffer sized from the file: a warm build reads megabytes of cache
// entries and previous outputs, and a character-at-a-time stream read costs more than the rest.
Result<std::string> read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(path.string(), 0, std::string("cannot read: ") + std::strerror(errno));
    std::error_code ec;
    auto expected = std::filesystem::file_size(path, ec);
    std::string bytes;
    if (!ec) bytes.reserve(static_cast<std::size_t>(expected));
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) bytes.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (in.bad()) return make_error(path.string(), 0, std::string("read failed: ") + std::strerror(errno));
    return bytes;
}

std::string temporary_name(std::string_view stem) {
    static std::atomic<unsigned> counter{0};
    return "." + std::string(stem) + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes) {
    std::filesystem::path temp = path.parent_path() / temporary_name(path.filename().string());
    std::FILE* file = std::fopen(temp.c_str(), "wb");
    if (!file) return make_error(path.string(), 0, std::string("cannot write: ") + std::strerror(errno));
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    int write_errno = errno;
    ok = (std::fflush(file) == 0) && ok;
    if (!ok) write_errno = errno;
    ok = (::fsync(::fileno(file)) == 0 || errno == EINVAL) && ok;
    ok = (std::fclose(file) == 0) && ok;
    if (!ok) {
        std::remove(temp.c_str());
        return make_error(path.string(), 0, std::string("write failed: ") + std::strerror(write_errno ? write_errno : EIO));
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        int rename_errno = errno;
        std::remove(temp.c_str());
        return make_error(path.string(), 0, std::string("cannot replace: ") + std::strerror(rename_errno));
    }
    return Ok{};
}

bool file_has_bytes(const std::filesystem::path& path, std::string_view bytes) {
    std::error_code ec;
    auto size = std::filesystem::file_size(path, ec);
    if (ec || size != bytes.size()) return false;
    auto current = read_file(path);
    return current && current.value() == bytes;
}

}  // namespace shadergen
