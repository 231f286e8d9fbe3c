// Shared helpers for the shadergen tests: paths, scratch folders, file comparison.
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace shadergen::test {

std::filesystem::path source_dir();
std::filesystem::path split_second_spec();
std::filesystem::path toy_spec();

// A fresh, empty folder unique to this test.
std::filesystem::path scratch(const std::string& name);

std::string read_text(const std::filesystem::path& path);
void write_text(const std::filesystem::path& path, const std::string& text);

// Every regular file under `dir`, relative path -> bytes.
std::map<std::string, std::string> snapshot(const std::filesystem::path& dir);

// The first diagnostic of parse_domain(text, "spec.json") as printed, or "(no error)".
std::string first_spec_error(const std::string& text);

// Runs a shell command, returns its exit status.
int run_command(const std::string& command);

}  // namespace shadergen::test
