// Fuzz entry point: the GLSL half of `shadergen build`, through build() in process: glslang's
// preprocessor and compiler (compile/glsl_compiler.*), the optimiser and validator, reflection,
// the shared-layout and program checks, the grouping of compile errors over the permutations,
// then the manifest, the generated C++ and the output folder; afterwards the remote-cache entry
// check (compile/entry_check.*) runs on every blob written.
//
// One input is text. Its first byte picks one of eight fixed domain specs (below; '0' to '7'
// pick 0 to 7, any byte picks its value modulo 8) and its first line is otherwise ignored. The
// rest is cut at lines that are exactly "//--" into up to three files:
//   1. shader.glsl, the uber-shader (the fragment half of a program);
//   2. include/fuzz.glsl, the one file in the include folder (`#include "fuzz.glsl"`);
//   3. second.glsl, the second shader of specs 3 to 7 (a program's vertex half, a companion).
// A file the input leaves out is written empty. Seeds: tests/fuzz/corpus/glsl/.
//
// Everything happens in a scratch folder made once per process under the system temporary
// folder (removed at exit); every input rewrites its three files and removes the previous
// output and depfile, so an input's outcome never depends on the ones before it. No cache is
// used (use_cache = false) and one job runs.
//
// Beyond "no crash, hang or leak", it checks the library's contract: a failure carries at least
// one diagnostic, each a non-empty single line, and writes nothing (no output folder, no
// depfile, nothing left beside them); a success writes the folder with manifest.json, the
// generated header and the depfile, and every blob in it is fit for the build's target and of
// one of the spec's stages, as the entry check (entry_check.h) sees it, and unfit for a stage
// the spec does not have.
#include <stdlib.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "compile/entry_check.h"
#include "fuzz_check.h"
#include "shadergen/build.h"
#include "shadergen/domain.h"
#include "shadergen/registry.h"

namespace {

namespace fs = std::filesystem;
using shadergen::Stage;
using shadergen::TargetEnv;
using shadergen::fuzz::require;

// One fixed spec: its JSON, the stages its blobs may have, a stage none of them has, and the
// target every blob must validate for.
struct Template {
  const char* json;
  std::initializer_list<Stage> stages;
  Stage foreign;
  TargetEnv target;
};

// shader.glsl, include/fuzz.glsl and second.glsl in every spec; the features' defines are
// FEAT_A, FEAT_B (and QUALITY, valued, in spec 1).
const Template kTemplates[] = {
    // 0: a fragment uber-shader, collapsed, one shared layout.
    {R"({ "name": "fuzz_glsl", "uber_shader": { "path": "shader.glsl", "stage": "fragment" },
  "include_dirs": ["include"],
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "FEAT_A", "unread": "allowed" }, { "name": "B", "bit": 1, "define": "FEAT_B", "unread": "allowed" } ] },
  "optimised": { "bits": [ { "name": "AB", "bit": 0, "when": "A || B" } ],
                 "variants": [ { "when": "AB", "raw_features": ["A"] } ] } })",
     {Stage::fragment},
     Stage::compute,
     TargetEnv::vulkan1_2},
    // 1: compute, a layout per permutation, Vulkan 1.0, a fixed define and a valued feature.
    {R"({ "name": "fuzz_glsl", "uber_shader": { "path": "shader.glsl", "stage": "compute" },
  "include_dirs": ["include"], "layout": "per_permutation", "target_env": "vulkan1.0", "defines": { "FIXED": "3" },
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "FEAT_A", "unread": "allowed" },
                         { "name": "Q", "bit": 1, "define": "QUALITY", "values": [0, 1, 2], "unread": "allowed" } ],
           "impossible": [ { "when": "A && Q == 2", "why": "fuzz" } ] } })",
     {Stage::compute},
     Stage::fragment,
     TargetEnv::vulkan1_0},
    // 2: vertex, Vulkan 1.3, debug information stripped, only the optimised permutations compiled.
    {R"({ "name": "fuzz_glsl", "uber_shader": { "path": "shader.glsl", "stage": "vertex" },
  "include_dirs": ["include"], "target_env": "vulkan1.3", "strip_debug": true, "compile": "optimised",
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "FEAT_A", "unread": "allowed" }, { "name": "B", "bit": 1, "define": "FEAT_B", "unread": "allowed" } ] },
  "optimised": { "bits": [ { "name": "X", "bit": 0, "when": "A && B" } ],
                 "variants": [ { "when": "X", "raw_features": ["A", "B"] } ] } })",
     {Stage::vertex},
     Stage::fragment,
     TargetEnv::vulkan1_3},
    // 3: a program: second.glsl is the vertex half, shader.glsl the fragment half.
    {R"({ "name": "fuzz_glsl", "program": { "vertex": "second.glsl", "fragment": "shader.glsl" },
  "include_dirs": ["include"],
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "FEAT_A", "unread": "allowed" }, { "name": "B", "bit": 1, "define": "FEAT_B", "unread": "allowed" } ] } })",
     {Stage::vertex, Stage::fragment},
     Stage::compute,
     TargetEnv::vulkan1_2},
    // 4: fragment with a compute companion in the shared layout.
    {R"({ "name": "fuzz_glsl", "uber_shader": { "path": "shader.glsl", "stage": "fragment" },
  "include_dirs": ["include"],
  "companions": [ { "name": "second", "path": "second.glsl", "stage": "compute", "defines": ["COMPANION"] } ],
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "FEAT_A", "unread": "allowed" }, { "name": "B", "bit": 1, "define": "FEAT_B", "unread": "allowed" } ] } })",
     {Stage::fragment, Stage::compute},
     Stage::vertex,
     TargetEnv::vulkan1_2},
    // 5: a mesh shader with a task companion of its own layout.
    {R"({ "name": "fuzz_glsl", "uber_shader": { "path": "shader.glsl", "stage": "mesh" },
  "include_dirs": ["include"],
  "companions": [ { "name": "second", "path": "second.glsl", "stage": "task", "shared_layout": false } ],
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "FEAT_A", "unread": "allowed" } ] } })",
     {Stage::mesh, Stage::task},
     Stage::fragment,
     TargetEnv::vulkan1_2},
    // 6: ray generation with a closest-hit companion, Vulkan 1.3.
    {R"({ "name": "fuzz_glsl", "uber_shader": { "path": "shader.glsl", "stage": "ray_generation" },
  "include_dirs": ["include"], "target_env": "vulkan1.3",
  "companions": [ { "name": "second", "path": "second.glsl", "stage": "closest_hit", "shared_layout": false } ],
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "FEAT_A", "unread": "allowed" } ] } })",
     {Stage::ray_generation, Stage::closest_hit},
     Stage::compute,
     TargetEnv::vulkan1_3},
    // 7: geometry with a tessellation-evaluation companion in the shared layout.
    {R"({ "name": "fuzz_glsl", "uber_shader": { "path": "shader.glsl", "stage": "geometry" },
  "include_dirs": ["include"],
  "companions": [ { "name": "second", "path": "second.glsl", "stage": "tess_evaluation" } ],
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "FEAT_A", "unread": "allowed" }, { "name": "B", "bit": 1, "define": "FEAT_B", "unread": "allowed" } ] } })",
     {Stage::geometry, Stage::tess_evaluation},
     Stage::fragment,
     TargetEnv::vulkan1_2},
};
constexpr std::size_t kTemplateCount = std::size(kTemplates);

void write(const fs::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  require(static_cast<bool>(out), "the scratch folder's files can be written");
}

class Scratch {
 public:
  Scratch() {
    std::string pattern = (fs::temp_directory_path() / "shadergen-fuzz-glsl-XXXXXX").string();
    require(mkdtemp(pattern.data()) != nullptr, "a scratch folder can be made");
    dir_ = pattern;
    fs::create_directories(dir_ / "include");
    for (std::size_t i = 0; i < kTemplateCount; ++i) write(spec(i), kTemplates[i].json);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  fs::path spec(std::size_t index) const { return dir_ / ("spec" + std::to_string(index) + ".json"); }
  fs::path out() const { return dir_ / "out"; }
  fs::path depfile() const { return dir_ / "out.d"; }
  const fs::path& dir() const { return dir_; }

  // The input's files in place, and nothing of the previous input's outcome.
  void prepare(const std::vector<std::string_view>& parts) {
    write(dir_ / "shader.glsl", !parts.empty() ? parts[0] : std::string_view());
    write(dir_ / "include" / "fuzz.glsl", parts.size() > 1 ? parts[1] : std::string_view());
    write(dir_ / "second.glsl", parts.size() > 2 ? parts[2] : std::string_view());
    std::error_code ec;
    fs::remove_all(out(), ec);
    require(!ec, "the previous output can be removed");
    fs::remove(depfile(), ec);
    require(!ec, "the previous depfile can be removed");
  }

 private:
  fs::path dir_;
};

// The text after the first line, cut at lines that are exactly "//--"; at most three parts
// (further markers stay in the third).
std::vector<std::string_view> split_files(std::string_view text) {
  std::size_t first_line = text.find('\n');
  text = first_line == std::string_view::npos ? std::string_view() : text.substr(first_line + 1);
  constexpr std::string_view kMarker = "//--\n";
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (parts.size() < 2) {
    std::size_t at = text.find(kMarker, start);
    while (at != std::string_view::npos && at != 0 && text[at - 1] != '\n') at = text.find(kMarker, at + 1);
    if (at == std::string_view::npos) break;
    parts.push_back(text.substr(start, at - start));
    start = at + kMarker.size();
  }
  parts.push_back(text.substr(start));
  return parts;
}

bool one_line(const std::string& text) { return text.find_first_of("\r\n") == std::string::npos; }

// Nothing written beside the output either: no staging or set-aside folder of a failed commit.
bool only_inputs_in(const fs::path& dir) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    std::string name = entry.path().filename().string();
    bool input = name == "include" || name == "shader.glsl" || name == "second.glsl" ||
                 (name.rfind("spec", 0) == 0 && entry.path().extension() == ".json");
    if (!input) return false;
  }
  return true;
}

std::vector<std::uint32_t> read_words(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  require(bytes.size() % 4 == 0, "a written blob is a whole number of words");
  std::vector<std::uint32_t> words(bytes.size() / 4);
  for (std::size_t i = 0; i < words.size(); ++i)
    for (std::size_t b = 0; b < 4; ++b)
      words[i] |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[4 * i + b])) << (8 * b);
  return words;
}

void check_blobs(const Scratch& scratch, const Template& spec) {
  std::size_t blobs = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(scratch.out() / "spirv")) {
    std::vector<std::uint32_t> words = read_words(entry.path());
    bool fits_a_stage = false;
    for (Stage stage : spec.stages)
      fits_a_stage = fits_a_stage || shadergen::unfit_reason(words, stage, spec.target).empty();
    require(fits_a_stage, "every blob written validates and has an entry point of one of the spec's stages");
    require(!shadergen::unfit_reason(words, spec.foreign, spec.target).empty(),
            "no blob written has an entry point of a stage the spec does not have");
    ++blobs;
  }
  require(blobs > 0, "a successful build writes at least one blob");
}

// SHADERGEN_FUZZ_GLSL_VERBOSE set: each input's outcome on stderr, to see what a seed reaches.
bool verbose() {
  static const bool on = std::getenv("SHADERGEN_FUZZ_GLSL_VERBOSE") != nullptr;
  return on;
}

void report(std::size_t spec, const shadergen::Result<shadergen::BuildSummary>& built) {
  if (built) {
    std::fprintf(stderr, "  spec %zu: built, %u blobs\n", spec, built->unique_blobs);
    return;
  }
  std::fprintf(stderr, "  spec %zu: failed\n", spec);
  for (const shadergen::Diagnostic& d : built.errors()) std::fprintf(stderr, "    %s\n", d.to_string().c_str());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Scratch scratch;
  if (size == 0) return 0;
  const Template& spec = kTemplates[data[0] % kTemplateCount];
  std::vector<std::string_view> parts = split_files(std::string_view(reinterpret_cast<const char*>(data), size));
  scratch.prepare(parts);

  shadergen::BuildOptions options;
  options.spec_path = scratch.spec(static_cast<std::size_t>(data[0] % kTemplateCount));
  options.out_dir = scratch.out();
  options.depfile = scratch.depfile();
  options.jobs = 1;
  options.use_cache = false;
  std::vector<std::string> log;
  options.log = [&log](const std::string& line) { log.push_back(line); };
  auto built = shadergen::build(options);
  if (verbose()) report(data[0] % kTemplateCount, built);

  for (const std::string& line : log) require(one_line(line), "every warning is one line");
  std::error_code ec;
  if (!built) {
    require(!built.errors().empty(), "a failed build carries at least one diagnostic");
    for (const shadergen::Diagnostic& d : built.errors()) {
      require(!d.message.empty(), "every diagnostic says what is wrong");
      require(one_line(d.message), "every diagnostic is one line");
    }
    require(!fs::exists(scratch.out(), ec) && !ec, "a failed build writes no output folder");
    require(!fs::exists(scratch.depfile(), ec) && !ec, "a failed build writes no depfile");
    require(only_inputs_in(scratch.dir()), "a failed build leaves nothing beside the output");
    return 0;
  }
  require(fs::is_regular_file(scratch.out() / "manifest.json", ec), "a successful build writes manifest.json");
  require(fs::is_regular_file(scratch.out() / "fuzz_glsl.h", ec), "a successful build writes the generated header");
  require(fs::is_regular_file(scratch.depfile(), ec), "a successful build writes the depfile");
  require(built->unique_blobs > 0, "a successful build has blobs");
  check_blobs(scratch, spec);
  return 0;
}
