// Helpers for the fixture-domain tests (toy_build_test.cpp, glsl_error_test.cpp,
// cli_process_test.cpp, real_spec_errors_test.cpp): fixture paths, unique temporary folders,
// whole-folder snapshots, and running the shadergen executable or spirv-val as a process.
//
// Header-only so the executable that uses it needs no extra source file. Every folder a test
// writes lives under std::filesystem::temp_directory_path() with a name unique to the process
// and the call, and every build passes an explicit cache folder: no test touches the user's
// cache or another test's files, whatever ctest -j runs beside it.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace sgtest {

namespace fs = std::filesystem;

inline fs::path source_dir() { return fs::path(SHADERGEN_SOURCE_DIR); }
inline fs::path fixtures_dir() { return source_dir() / "tests" / "fixtures"; }
inline fs::path toy_spec() { return fixtures_dir() / "toy" / "toy.json"; }
inline fs::path glsl_error_spec() { return fixtures_dir() / "glsl_error" / "glsl_error.json"; }
inline fs::path split_second_spec() { return source_dir() / "permutations" / "split_second.json"; }

#ifdef SHADERGEN_EXE
inline fs::path shadergen_exe() { return fs::path(SHADERGEN_EXE); }
#endif

inline std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void write_file(const fs::path& path, const std::string& bytes) {
    if (path.has_parent_path()) fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
}

// A fresh, empty folder under the system temporary folder, removed when the object dies.
class TempDir {
public:
    explicit TempDir(const std::string& tag) {
        static std::atomic<unsigned> counter{0};
        auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
        path_ = fs::temp_directory_path() /
                ("shadergen-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" +
                 std::to_string(ticks));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const fs::path& path() const { return path_; }
    fs::path operator/(const std::string& name) const { return path_ / name; }

private:
    fs::path path_;
};

// Every regular file under `dir`: relative path -> bytes.
inline std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    if (!fs::exists(dir)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) files[entry.path().lexically_relative(dir).generic_string()] = read_file(entry.path());
    return files;
}

// Every regular file under `dir`: relative path -> modification time.
inline std::map<std::string, fs::file_time_type> mtimes(const fs::path& dir) {
    std::map<std::string, fs::file_time_type> times;
    if (!fs::exists(dir)) return times;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) times[entry.path().lexically_relative(dir).generic_string()] = entry.last_write_time();
    return times;
}

// Lists which files differ between two snapshots, for readable failure messages.
inline std::string describe_difference(const std::map<std::string, std::string>& a,
                                       const std::map<std::string, std::string>& b) {
    std::string text;
    for (const auto& [name, bytes] : a) {
        auto other = b.find(name);
        if (other == b.end()) text += "  only in the first: " + name + "\n";
        else if (other->second != bytes) text += "  differs: " + name + "\n";
    }
    for (const auto& [name, bytes] : b)
        if (!a.count(name)) text += "  only in the second: " + name + "\n";
    return text.empty() ? "  (identical)\n" : text;
}

inline std::string shell_quote(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) {
        if (c == '\'') quoted += "'\\''";
        else quoted += c;
    }
    return quoted + "'";
}

struct ProcessResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

// Runs `program args...` through the shell with stdout and stderr captured into files in a
// temporary folder; exit_code is -1 when the process did not exit normally.
inline ProcessResult run_process(const fs::path& program, const std::vector<std::string>& args) {
    TempDir capture("capture");
    std::string command = shell_quote(program.string());
    for (const std::string& arg : args) command += " " + shell_quote(arg);
    command += " >" + shell_quote((capture / "out").string()) + " 2>" + shell_quote((capture / "err").string()) +
               " </dev/null";
    int status = std::system(command.c_str());
    ProcessResult result;
    result.exit_code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    result.out = read_file(capture / "out");
    result.err = read_file(capture / "err");
    return result;
}

// The external validator, as a second opinion beside shadergen's own validate_spirv().
inline ProcessResult spirv_val(const fs::path& blob, const std::string& target_env = "vulkan1.2") {
    const fs::path installed = "/usr/bin/spirv-val";
    return run_process(fs::exists(installed) ? installed : fs::path("spirv-val"),
                       {"--target-env", target_env, blob.string()});
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// 1-based line and column of byte `offset` in `text`, as shadergen's diagnostics count them.
struct Position {
    int line = 1;
    int column = 1;
};
inline Position position_of(const std::string& text, std::size_t offset) {
    Position p;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++p.line;
            p.column = 1;
        } else {
            ++p.column;
        }
    }
    return p;
}
inline std::string where(const std::string& file, const std::string& text, std::size_t offset) {
    Position p = position_of(text, offset);
    return file + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
}

inline std::size_t count_of(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
    return n;
}

}  // namespace sgtest
