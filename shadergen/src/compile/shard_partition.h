// shard_partition.h - which compile jobs a shard of a domain owns (`build --shard I/N`).
//
// The compile jobs are in the order make_jobs() gives them, which depends on the spec (and the
// variants file) only, so every machine numbers them alike before preprocessing anything.
// Shard I of N owns the contiguous range [floor(I*J/N), floor((I+1)*J/N)) of the J jobs: the N
// ranges are disjoint, cover every job, and differ in size by at most one. A shard preprocesses
// and compiles its own jobs only, so a distinct source that jobs of two shards share is
// compiled by both (its cache key, and so its entry, is the same).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace shadergen {

struct JobRange {
  std::size_t first = 0;
  std::size_t last = 0;  // one past the end

  std::size_t size() const { return last - first; }
  bool contains(std::size_t job) const { return job >= first && job < last; }
};

// Precondition: index < count.
constexpr JobRange shard_range(std::size_t jobs, std::uint32_t index, std::uint32_t count) {
  auto bound = [&](std::uint64_t i) { return static_cast<std::size_t>(i * jobs / count); };
  return {bound(index), bound(std::uint64_t{index} + 1)};
}

// The shard that owns job `job`. Preconditions: job < jobs, count >= 1.
constexpr std::uint32_t shard_of(std::size_t job, std::size_t jobs, std::uint32_t count) {
  return static_cast<std::uint32_t>(((std::uint64_t{job} + 1) * count + jobs - 1) / jobs - 1);
}

// The command that puts shard `place` ("3/8"; "I/N" as a template) of the build of `spec` on
// the server `url` again, as the merge's errors name it.
inline std::string shard_rerun_command(const std::string& spec, const std::string& place, const std::string& url) {
  return "shadergen build " + spec + " --shard " + place + " --remote-cache " + url +
         " (with the shards' other options)";
}

}  // namespace shadergen
