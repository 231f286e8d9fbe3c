// source_scan.h - what a domain's permuted shaders read, found without the compiler.
//
// The checks on feature kinds need two facts about the uber-shader and every file it includes:
// which identifiers the text uses (a define nobody reads is a misspelt feature), and which
// identifiers preprocessor conditionals test (#ifdef cannot test a specialization constant).
// Both hold whichever permutation is built, so the scan ignores conditionals: it follows every
// #include line and reads every line, comments excepted.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace shadergen {

struct SourceLocation {
  std::filesystem::path file;
  int line = 0;
};

// An identifier a conditional tests: `#ifdef NAME`, `#ifndef NAME`, `defined(NAME)` or a bare
// NAME in `#if` / `#elif`. `directive` says which, as the message shows it ("#ifdef",
// "#ifndef", "defined()", "#if", "#elif").
struct ConditionalTest {
  std::string name;
  std::string directive;
  SourceLocation at;
};

struct SourceScan {
  std::map<std::string, SourceLocation> identifiers;  // every identifier, where first seen
  std::vector<ConditionalTest> tests;                 // in file order, files in include order
};

// Scans `files` and what they include: "local" includes against the including file's folder,
// then `include_dirs`, <system> ones against `include_dirs` (as the compiler resolves them). A
// file that cannot be read is skipped: compiling it reports that with its line.
SourceScan scan_sources(const std::vector<std::filesystem::path>& files,
                        const std::vector<std::filesystem::path>& include_dirs);

// Where `files` (or what they include) first declare `name` as a stage input: the first line,
// comments aside, holding both the identifier `name` and the qualifier `in`. nullopt when none
// does (the input comes from a macro, say): the caller then names the spec.
std::optional<SourceLocation> input_declaration(const std::string& name,
                                                const std::vector<std::filesystem::path>& files,
                                                const std::vector<std::filesystem::path>& include_dirs);

}  // namespace shadergen
