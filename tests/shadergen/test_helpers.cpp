#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <sys/wait.h>

#include "shadergen/domain.h"

namespace shadergen::test {

std::filesystem::path source_dir() { return SHADERGEN_SOURCE_DIR; }
std::filesystem::path split_second_spec() { return source_dir() / "permutations" / "split_second.json"; }
std::filesystem::path toy_spec() { return source_dir() / "tests" / "fixtures" / "toy" / "toy.json"; }

std::string first_spec_error(const std::string& text) {
    auto result = parse_domain(text, "spec.json");
    if (result.ok()) return "(no error)";
    return result.errors().front().to_string();
}

std::filesystem::path scratch(const std::string& name) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "suite";
    std::filesystem::path dir = std::filesystem::path(SHADERGEN_TEST_SCRATCH) / test / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
    std::map<std::string, std::string> files;
    if (!std::filesystem::exists(dir)) return files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
        if (entry.is_regular_file())
            files[entry.path().lexically_relative(dir).generic_string()] = read_text(entry.path());
    return files;
}

int run_command(const std::string& command) {
    int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace shadergen::test
