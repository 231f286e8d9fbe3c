// Checks a generated registry's hashes against a second SHA-256 implementation: coreutils
// sha256sum, run as a child process over every blob's little-endian SPIR-V words. The registry
// tests link only the generated code (as a consumer does), not shadergen's own SHA-256, so this
// is the independent check that every `hash` and `vertex_hash` is the digest of its words.
//
// Header-only; its child-process runner is tests::support's, which every test links.
#pragma once

#include <gtest/gtest.h>
#include <shadergen/registry.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <testsupport/child_process.h>

namespace registry_digests {

struct Blob {
  std::string label;  // "raw 5", "optimised 3 vertex", "companion tile"
  std::span<const std::uint32_t> words;
  std::string_view hash;
};

inline void add_permutation(std::vector<Blob>& blobs, const std::string& label, const shadergen::Permutation& p) {
  if (!p.spirv.empty()) blobs.push_back({label, p.spirv, p.hash});
  if (!p.vertex_spirv.empty()) blobs.push_back({label + " vertex", p.vertex_spirv, p.vertex_hash});
}

inline std::vector<Blob> blobs_of(const shadergen::Registry& r) {
  std::vector<Blob> blobs;
  for (const shadergen::Permutation& p : r.raw) add_permutation(blobs, "raw " + std::to_string(p.id), p);
  for (const shadergen::Permutation& p : r.optimised) add_permutation(blobs, "optimised " + std::to_string(p.id), p);
  for (const shadergen::CompanionShader& c : r.companions)
    add_permutation(blobs, "companion " + std::string(c.name), c.shader);
  return blobs;
}

// sha256sum's digest of each blob's words, in the order given. A words array shared by several
// permutations is written once.
inline std::vector<std::string> sha256sum_of(const std::vector<Blob>& blobs) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("registry-digests-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::map<const std::uint32_t*, std::string> file_of;
  std::vector<std::string> files;
  for (const Blob& blob : blobs) {
    auto [it, added] = file_of.try_emplace(blob.words.data(), (folder / std::to_string(file_of.size())).string());
    if (!added) continue;
    std::FILE* file = std::fopen(it->second.c_str(), "wb");
    if (file == nullptr) return {};
    std::fwrite(blob.words.data(), sizeof(std::uint32_t), blob.words.size(), file);  // x86/ARM: little-endian
    std::fclose(file);
    files.push_back(it->second);
  }
  testsupport::ChildOutcome run = testsupport::Child("sha256sum", files).wait();
  fs::remove_all(folder);
  if (run.exit_code != 0) return {};
  std::map<std::string, std::string> digest_of_file;
  std::istringstream lines(run.out);
  for (std::string digest, file; lines >> digest >> file;) digest_of_file[file] = digest;
  std::vector<std::string> digests;
  for (const Blob& blob : blobs) digests.push_back(digest_of_file[file_of[blob.words.data()]]);
  return digests;
}

// Every blob's hash is sha256sum's digest of its words; returns how many blobs were checked.
inline std::size_t expect_hashes_are_sha256_of_words(const shadergen::Registry& r) {
  const std::vector<Blob> blobs = blobs_of(r);
  const std::vector<std::string> digests = sha256sum_of(blobs);
  EXPECT_EQ(digests.size(), blobs.size()) << "sha256sum did not run over every blob";
  for (std::size_t i = 0; i < blobs.size() && i < digests.size(); ++i)
    EXPECT_EQ(blobs[i].hash, digests[i]) << blobs[i].label;
  return blobs.size();
}

}  // namespace registry_digests
