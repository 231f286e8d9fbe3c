// shadergen_build_bench - how fast `shadergen build` is against the script a user would write
// instead, measured back to back in one run (issue 4, target 4).
//
// On a private copy of the domain's files, each repetition runs, in this order:
//   a) the script (bench/shadergen_script.sh): glslangValidator, spirv-opt -O and spirv-val per
//      permutation, two permutations at a time (a shader that uses #include without naming
//      GL_GOOGLE_include_directive gets that line in the copy, as the script needs it);
//   b) `shadergen build --no-cache -j 2` (cold);
//   c) `shadergen build -j 2` with a populated cache and an unchanged output (warm);
//   d) after inserting one declaration inside one `#ifdef FEATURE` block of the uber-shader or
//      of a file it includes, `shadergen build -j 2 --stats`, and how many permutations it
//      recompiled.
// Every step is a separate process, timed from start to exit. Prints the medians and the
// ratios. Exits 1 if a step fails or a count is wrong (the warm build compiled something or
// changed the output, its output differs from the cold build's, or the #ifdef edit recompiled
// other than the permutations whose text holds the edited block: those counted by preprocessing
// every permutation with glslangValidator -E, independently of shadergen), so a one-repetition
// run is a smoke test.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <median/median.h>
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "timed_process.h"

namespace {

namespace fs = std::filesystem;
using bench::output_files;
using bench::read_text;
using bench::Run;

struct Options {
  fs::path spec = SHADERGEN_SOURCE_DIR "/permutations/split_second.json";
  fs::path shadergen = SHADERGEN_EXE;
  fs::path script = SHADERGEN_SOURCE_DIR "/bench/shadergen_script.sh";
  fs::path work;  // empty: a fresh folder under the system temporary folder, removed at the end
  int repetitions = 5;
  std::string edit_define;  // empty: the first raw feature with an `#ifdef` line (uber-shader or its includes)
};

std::optional<Options> parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    auto next = [&]() -> std::optional<std::string> {
      if (i + 1 >= argc) return std::nullopt;
      return std::string(argv[++i]);
    };
    std::optional<std::string> value = arg.rfind("--", 0) == 0 ? next() : std::nullopt;
    if (!value) return std::nullopt;
    if (arg == "--spec")
      o.spec = *value;
    else if (arg == "--shadergen")
      o.shadergen = *value;
    else if (arg == "--script")
      o.script = *value;
    else if (arg == "--work")
      o.work = *value;
    else if (arg == "--reps")
      o.repetitions = std::atoi(value->c_str());
    else if (arg == "--edit-define")
      o.edit_define = *value;
    else
      return std::nullopt;
  }
  if (o.repetitions < 1) return std::nullopt;
  return o;
}

void write_text(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// The copy: the folders of the spec, the shaders and the include dirs, below their common
// ancestor, so the spec's relative paths still resolve and the original files stay untouched.
fs::path common_ancestor(const std::vector<fs::path>& dirs) {
  fs::path root = dirs.front();
  for (const fs::path& dir : dirs)
    while (!root.empty() && dir.lexically_relative(root).string().rfind("..", 0) == 0) root = root.parent_path();
  return root;
}

fs::path copy_domain(const shadergen::DomainSpec& spec, const fs::path& to) {
  auto folder = [](const fs::path& p) { return fs::absolute(p).lexically_normal().parent_path(); };
  std::vector<fs::path> dirs{folder(spec.spec_path), folder(spec.uber.path)};
  for (const auto& c : spec.companions) dirs.push_back(folder(c.file.path));
  for (const auto& d : spec.include_dirs) dirs.push_back(fs::absolute(d).lexically_normal());
  fs::path root = common_ancestor(dirs);
  for (const fs::path& dir : dirs) {
    fs::path target = (to / dir.lexically_relative(root)).lexically_normal();
    fs::create_directories(target);
    fs::copy(dir, target, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  }
  return to / fs::absolute(spec.spec_path).lexically_normal().lexically_relative(root);
}

// glslangValidator has no switch that enables #include (shadergen enables it in its preamble),
// so a shader that uses #include without naming the extension gets the line a script user
// would have to add, after #version. Both sides then compile the same files.
void name_include_extension(const fs::path& shader) {
  std::string text = read_text(shader);
  if (text.find("#include") == std::string::npos || text.find("GL_GOOGLE_include_directive") != std::string::npos)
    return;
  std::size_t version = text.find("#version");
  std::size_t at = version == std::string::npos ? 0 : text.find('\n', version);
  at = at == std::string::npos ? text.size() : at + (version == std::string::npos ? 0 : 1);
  write_text(shader, text.insert(at, "#extension GL_GOOGLE_include_directive : require\n"));
}

std::string stage_flag(shadergen::Stage stage) { return std::string(shadergen::stage_extension(stage)); }

struct Job {
  std::string name;
  shadergen::Stage stage;
  fs::path path;
  std::vector<std::string> defines;
};

// Exactly the permutations shadergen compiles: unpruned raw, optimised, companions.
std::vector<Job> jobs_of(const shadergen::DomainSpec& spec, const shadergen::PermutationPlan& plan) {
  std::vector<Job> jobs;
  for (const auto& raw : plan.raw)
    if (!raw.pruned)
      jobs.push_back(
          {"raw" + std::to_string(raw.id), spec.uber.stage, spec.uber.path, shadergen::raw_defines(spec, raw.id)});
  for (const auto& o : plan.optimised)
    jobs.push_back({"optimised" + std::to_string(o.id), spec.uber.stage, spec.uber.path, o.defines});
  for (const auto& c : spec.companions) jobs.push_back({"companion_" + c.name, c.file.stage, c.file.path, c.defines});
  return jobs;
}

void write_job_list(const std::vector<Job>& jobs, const fs::path& file) {
  std::string text;
  for (const Job& job : jobs) {
    text += job.name + " " + stage_flag(job.stage) + " " + job.path.string();
    for (const std::string& d : job.defines) text += " " + d;
    text += "\n";
  }
  write_text(file, text);
}

std::string trimmed(const std::string& line) {
  auto first = line.find_first_not_of(" \t");
  auto last = line.find_last_not_of(" \t\r");
  return first == std::string::npos ? std::string() : line.substr(first, last - first + 1);
}

// Where the edit goes: just after the line `#ifdef DEFINE`. Returns npos when there is none.
std::size_t ifdef_line_end(const std::string& text, const std::string& define) {
  std::istringstream lines(text);
  std::string line;
  std::size_t offset = 0;
  while (std::getline(lines, line)) {
    offset += line.size() + 1;
    if (trimmed(line) == "#ifdef " + define) return std::min(offset, text.size());
  }
  return std::string::npos;
}

// The file and the line the edit goes after.
struct EditSite {
  std::string define;
  fs::path file;
};

// The uber-shader, then every file it includes, transitively, in the order first met: an
// `#include "name"` resolves against the including file's folder, then the include folders.
std::vector<fs::path> include_closure(const fs::path& shader, const std::vector<fs::path>& include_dirs) {
  static const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<fs::path> files{fs::absolute(shader).lexically_normal()};
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::istringstream lines(read_text(files[i]));
    std::string line;
    std::smatch m;
    while (std::getline(lines, line)) {
      if (!std::regex_search(line, m, include_line)) continue;
      std::vector<fs::path> candidates{files[i].parent_path() / m[1].str()};
      for (const fs::path& dir : include_dirs) candidates.push_back(fs::absolute(dir) / m[1].str());
      for (const fs::path& candidate : candidates) {
        if (!fs::is_regular_file(candidate)) continue;
        fs::path found = candidate.lexically_normal();
        if (std::find(files.begin(), files.end(), found) == files.end()) files.push_back(found);
        break;
      }
    }
  }
  return files;
}

// The first file of the uber-shader's include closure with an `#ifdef DEFINE` line, for the
// wanted define or else the first raw feature that has one. Empty define: none.
EditSite pick_edit_site(const shadergen::DomainSpec& spec, const std::string& wanted) {
  std::vector<std::string> defines;
  if (!wanted.empty())
    defines.push_back(wanted);
  else
    for (const auto& feature : spec.raw_features) defines.push_back(feature.define);
  std::vector<fs::path> files = include_closure(spec.uber.path, spec.include_dirs);
  for (const std::string& define : defines)
    for (const fs::path& file : files)
      if (ifdef_line_end(read_text(file), define) != std::string::npos) return {define, file};
  return {};
}

// "NAME" means NAME=1, as in shadergen's preamble.
std::string define_argument(const std::string& define) {
  return "-D" + define + (define.find('=') == std::string::npos ? "=1" : "");
}

// How many jobs' preprocessed text holds the block after `#ifdef site.define` in site.file:
// a probe declaration goes there, glslangValidator -E preprocesses every job, and the file is
// restored. nullopt (after a message) when a job does not preprocess.
std::optional<std::size_t> jobs_reaching(const std::vector<Job>& jobs, const shadergen::DomainSpec& spec,
                                         const EditSite& site) {
  const std::string original = read_text(site.file);
  const std::string probe = "shadergen_bench_probe";
  std::string probed = original;
  probed.insert(ifdef_line_end(probed, site.define), "float " + probe + " = 0.0;\n");
  write_text(site.file, probed);
  std::size_t count = 0;
  bool ok = true;
  for (const Job& job : jobs) {
    std::vector<std::string> args{"glslangValidator", "-E", "-S", stage_flag(job.stage)};
    auto name_of = [](const std::string& d) { return d.substr(0, d.find('=')); };
    for (const std::string& d : spec.defines)  // a job's own define of the same name replaces it
      if (std::none_of(job.defines.begin(), job.defines.end(), [&](const auto& j) { return name_of(j) == name_of(d); }))
        args.push_back(define_argument(d));
    for (const std::string& d : job.defines) args.push_back(define_argument(d));
    for (const fs::path& dir : spec.include_dirs) args.push_back("-I" + dir.string());
    args.push_back(job.path.string());
    bench::Run r = bench::run(args);
    if (!r.ok) {
      std::cerr << "shadergen_build_bench: glslangValidator -E failed on " << job.name << ":\n" << r.out;
      ok = false;
      break;
    }
    count += r.out.find(probe) != std::string::npos;
  }
  write_text(site.file, original);
  return ok ? std::optional<std::size_t>(count) : std::nullopt;
}

std::optional<int> number_after(const std::string& text, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(pattern))) return std::nullopt;
  return std::stoi(m[1]);
}

class Bench {
 public:
  Bench(Options o, shadergen::DomainSpec spec, std::vector<Job> jobs, EditSite site, std::size_t expected)
      : o_(std::move(o)), spec_(std::move(spec)), jobs_(std::move(jobs)), site_(std::move(site)), expected_(expected) {}

  bool run_all() {
    write_job_list(jobs_, o_.work / "jobs.txt");
    original_ = read_text(site_.file);
    if (!step("prime the cache", build("warm", false, true)).ok) return false;
    for (int rep = 1; rep <= o_.repetitions; ++rep)
      if (!repetition(rep)) return false;
    return true;
  }

  void report() const {
    double script = median::of(script_s_), cold = median::of(cold_s_), warm = median::of(warm_s_),
           edit = median::of(edit_s_);
    std::printf("shadergen build speed: %s, %zu permutations, %d repetition(s), medians, back to back\n",
                o_.spec.string().c_str(), jobs_.size(), o_.repetitions);
    std::printf("  (a) script: glslangValidator + spirv-opt -O + spirv-val, 2 at a time  %8.3f s\n", script);
    std::printf(
        "  (b) shadergen build --no-cache -j 2 (cold)                           %8.3f s  %6.2fx faster than (a) "
        "(target >= 2x)\n",
        cold, script / cold);
    std::printf(
        "  (c) shadergen build -j 2 (warm: cache hit, output unchanged)         %8.3f s  %6.2fx faster than (b) "
        "(target >= 20x)\n",
        warm, cold / warm);
    std::printf(
        "  (d) after an edit inside #ifdef %s (%s): rebuild  %8.3f s  %d of %zu permutations recompiled (%zu "
        "hold the block)\n",
        site_.define.c_str(), site_.file.filename().c_str(), edit, recompiled_, jobs_.size(), expected_);
    std::printf("  every run (s): (a) %s; (b) %s; (c) %s; (d) %s\n", bench::seconds_list(script_s_).c_str(),
                bench::seconds_list(cold_s_).c_str(), bench::seconds_list(warm_s_).c_str(),
                bench::seconds_list(edit_s_).c_str());
  }

 private:
  std::vector<std::string> build(const std::string& out, bool cold, bool quiet_stats) const {
    std::vector<std::string> args{
        o_.shadergen.string(), "build", spec_.spec_path.string(), "--out", (o_.work / out).string(), "-j", "2"};
    if (cold)
      args.push_back("--no-cache");
    else
      args.insert(args.end(), {"--cache-dir", (o_.work / "cache").string()});
    if (!quiet_stats) args.push_back("--stats");
    return args;
  }

  Run step(const std::string& what, const std::vector<std::string>& args) const {
    Run r = bench::run(args);
    if (!r.ok) std::cerr << "shadergen_build_bench: " << what << " failed:\n" << r.out;
    return r;
  }

  bool fail(const std::string& why) const {
    std::cerr << "shadergen_build_bench: " << why << "\n";
    return false;
  }

  bool repetition(int rep) {
    fs::remove_all(o_.work / "script");
    std::vector<std::string> script{o_.script.string(), (o_.work / "jobs.txt").string(), (o_.work / "script").string()};
    for (const fs::path& dir : spec_.include_dirs) script.push_back(dir.string());
    Run a = step("the script", script);
    Run b = step("cold build", build("cold", true, true));
    Run c = step("warm build", build("warm", false, true));
    if (!a.ok || !b.ok || !c.ok) return false;
    if (c.out.find("(0 compiled,") == std::string::npos || c.out.find("output unchanged") == std::string::npos)
      return fail("the warm build compiled something or changed its output:\n" + c.out);
    if (output_files(o_.work / "warm") != output_files(o_.work / "cold"))
      return fail("the warm build's output differs from the cold build's");
    if (!edit_and_rebuild(rep)) return false;
    script_s_.push_back(a.seconds), cold_s_.push_back(b.seconds), warm_s_.push_back(c.seconds);
    return true;
  }

  // A declaration valid at global and function scope, named per repetition so that every
  // repetition changes the text of the same permutations.
  bool edit_and_rebuild(int rep) {
    std::string text = original_;
    text.insert(ifdef_line_end(text, site_.define), "float shadergen_bench_edit_" + std::to_string(rep) + " = 0.0;\n");
    write_text(site_.file, text);
    Run d = step("rebuild after the edit", build("edited", false, false));
    if (!d.ok) return false;
    auto recompiled = number_after(d.out, R"(permutations: \d+ \((\d+) recompiled)");
    if (!recompiled) return fail("no recompile count in:\n" + d.out);
    recompiled_ = *recompiled;
    if (static_cast<std::size_t>(recompiled_) != expected_)
      return fail("the edit recompiled " + std::to_string(recompiled_) + " permutations, expected " +
                  std::to_string(expected_));
    edit_s_.push_back(d.seconds);
    // The next warm build starts from this text with an up-to-date output (not timed).
    return step("catching up after the edit", build("warm", false, true)).ok;
  }

  Options o_;
  shadergen::DomainSpec spec_;
  std::vector<Job> jobs_;
  EditSite site_;
  std::size_t expected_;  // permutations the edit must recompile
  std::string original_;
  int recompiled_ = 0;
  std::vector<double> script_s_, cold_s_, warm_s_, edit_s_;
};

int usage() {
  std::cerr << "usage: shadergen_build_bench [--spec SPEC] [--reps N] [--shadergen EXE] [--script SCRIPT]\n"
               "                             [--work DIR] [--edit-define DEFINE]\n";
  return 2;
}

// The whole bench; main() adds only the last word on a failure nothing else reported (a
// file-system error from std::filesystem, out of memory).
int run(int argc, char** argv) {
  auto options = parse_args(argc, argv);
  if (!options) return usage();
  bool temporary = options->work.empty();
  if (temporary) options->work = fs::temp_directory_path() / ("shadergen-build-bench-" + std::to_string(::getpid()));
  options->work = fs::absolute(options->work);
  fs::remove_all(options->work);
  fs::create_directories(options->work);

  auto original = shadergen::load_domain(options->spec);
  if (!original) return std::cerr << original.errors().front().to_string() << "\n", 1;
  auto spec = shadergen::load_domain(copy_domain(*original, options->work / "tree"));
  if (!spec) return std::cerr << spec.errors().front().to_string() << "\n", 1;
  auto plan = shadergen::expand(*spec);
  if (!plan) return std::cerr << plan.errors().front().to_string() << "\n", 1;

  name_include_extension(spec->uber.path);
  for (const auto& companion : spec->companions) name_include_extension(companion.file.path);
  EditSite site = pick_edit_site(*spec, options->edit_define);
  if (site.define.empty())
    return std::cerr << "shadergen_build_bench: no `#ifdef FEATURE` line in the uber-shader or its includes\n", 1;
  std::vector<Job> jobs = jobs_of(*spec, *plan);
  auto expected = jobs_reaching(jobs, *spec, site);
  if (!expected) return 1;
  Bench bench(*options, std::move(spec).value(), std::move(jobs), site, *expected);
  bool ok = bench.run_all();
  if (ok) bench.report();
  if (temporary) fs::remove_all(options->work);
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "shadergen_build_bench: error: " << e.what() << "\n";
    return 1;
  }
}
