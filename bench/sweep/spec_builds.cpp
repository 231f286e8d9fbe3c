#include "spec_builds.h"

#include "timed_process.h"

#include "tilelight/base/error.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>

namespace tilelight::sweep {
namespace {

// A path of `spec` made absolute against the spec's folder, as shadergen resolves it.
std::string absolute_from(const std::filesystem::path& spec, const std::string& path) {
  const std::filesystem::path p(path);
  return p.is_absolute() ? path : (spec.parent_path() / p).lexically_normal().string();
}

// The spec without companions, its paths absolute, written to `to`.
void write_uber_only(const std::filesystem::path& spec, const std::filesystem::path& to) {
  std::ifstream in(spec);
  if (!in) throw Error("cannot read " + spec.string());
  nlohmann::json j = nlohmann::json::parse(in);
  j.erase("companions");
  if (j.contains("uber_shader")) j["uber_shader"]["path"] = absolute_from(spec, j["uber_shader"]["path"]);
  if (j.contains("uber_shaders")) {
    for (auto& [name, uber] : j["uber_shaders"].items()) uber["path"] = absolute_from(spec, uber["path"]);
  }
  if (j.contains("include_dirs")) {
    for (auto& dir : j["include_dirs"]) dir = absolute_from(spec, dir);
  }
  std::ofstream out(to);
  out << j.dump(2) << '\n';
  if (!out) throw Error("cannot write " + to.string());
}

std::uint32_t number_before(const std::string& text, const std::string& words, const std::string& spec) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex("([0-9]+) " + words))) {
    throw Error("shadergen's summary of " + spec + " has no '" + words + "': " + text);
  }
  return static_cast<std::uint32_t>(std::stoul(m[1].str()));
}

}  // namespace

std::filesystem::path light_spec(const std::filesystem::path& permutations_dir, LightKinds kinds) {
  std::string name = "split_second";
  if (kinds != LightKinds::variant) name += std::string("_") + to_string(kinds);
  return permutations_dir / (name + ".json");
}

SpecBuild build_light_spec(const std::filesystem::path& shadergen, const std::filesystem::path& spec,
                           const std::filesystem::path& scratch) {
  std::filesystem::create_directories(scratch);
  const std::filesystem::path copy = scratch / spec.filename();
  const std::filesystem::path out = scratch / (spec.stem().string() + "-out");
  std::filesystem::remove_all(out);
  write_uber_only(spec, copy);
  const bench::Run run = bench::run({shadergen.string(), "build", copy.string(), "--out", out.string(), "--no-cache"});
  if (!run.ok) throw Error("shadergen build " + copy.string() + " failed:\n" + run.out);
  SpecBuild b;
  b.spec = spec.filename().string();
  b.sources = number_before(run.out, "distinct sources", b.spec);
  b.blobs = number_before(run.out, "SPIR-V blobs", b.spec);
  b.seconds = run.seconds;
  std::filesystem::remove_all(out);
  return b;
}

}  // namespace tilelight::sweep
