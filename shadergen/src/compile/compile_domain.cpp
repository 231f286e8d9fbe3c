#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include "base/phase_clock.h"
#include "base/sha256.h"
#include "base/thread_pool.h"
#include "cache/cache.h"
#include "cache/input_cache.h"
#include "cache/remote_cache.h"
#include "cache/source_key.h"
#include "cache/tiered_cache.h"
#include "compile/blob_spill.h"
#include "compile/compile_domain.h"
#include "compile/entry_check.h"
#include "compile/error_grouping.h"
#include "compile/feature_reads.h"
#include "compile/glsl_compiler.h"
#include "compile/program_check.h"
#include "compile/shard_partition.h"
#include "compile/source_scan.h"
#include "compile/spirv_passes.h"
#include "compile/toolchain.h"
#include "spec/defines.h"
#include "spec/kind_declarations.h"
#include "spec/target_env.h"

namespace shadergen {

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// "compile": "optimised" leaves the raw permutations out (they have no job, so no blob).
std::vector<CompileJob> make_jobs(const DomainSpec& spec, const PermutationPlan& plan) {
  std::vector<CompileJob> jobs;
  const bool raw_too = spec.compile == CompileSet::all;
  // Sized once: grown by doubling, the list would hold up to twice its jobs' room.
  std::size_t raw_count = 0;
  if (raw_too)
    raw_count = static_cast<std::size_t>(
        std::count_if(plan.raw.begin(), plan.raw.end(), [](const RawPermutation& raw) { return !raw.pruned; }));
  jobs.reserve((raw_count + plan.optimised.size()) * (spec.program_vertex ? 2 : 1) + spec.companions.size());
  for (const RawPermutation& raw : plan.raw)
    if (raw_too && !raw.pruned) jobs.push_back({JobKind::raw, raw.id, spec.uber.stage});
  for (const OptimisedPermutation& optimised : plan.optimised)
    jobs.push_back({JobKind::optimised, optimised.id, spec.uber.stage});
  if (spec.program_vertex) {
    const ShaderFile& vertex = *spec.program_vertex;
    for (const RawPermutation& raw : plan.raw)
      if (raw_too && !raw.pruned) jobs.push_back({JobKind::raw, raw.id, vertex.stage, true});
    for (const OptimisedPermutation& o : plan.optimised) jobs.push_back({JobKind::optimised, o.id, vertex.stage, true});
  }
  for (std::size_t i = 0; i < spec.companions.size(); ++i)
    jobs.push_back({JobKind::companion, static_cast<std::uint32_t>(i), spec.companions[i].file.stage});
  return jobs;
}

// The domain's fixed defines, less those the job sets itself (a companion's own value wins). A
// permuted job also gets the kind declarations (companions are not permuted: they have none).
GlslSource source_of(const CompiledDomain& d, const CompileJob& job, const KindDeclarations& kinds) {
  GlslSource source{d.path_of(job), job.stage, d.spec.include_dirs, d.defines_of(job), {}, d.spec.target_env};
  if (job.kind != JobKind::companion) {
    source.defines = boolean_value_defines(std::move(source.defines), kinds);
    source.kind_macros = kinds.macros;
    source.kind_declarations = kinds.declarations;
  }
  for (const std::string& fixed : d.spec.defines) {
    bool own = std::any_of(source.defines.begin(), source.defines.end(), [&](const std::string& own_define) {
      return define_name(own_define) == define_name(fixed);
    });
    if (!own) source.fixed_defines.push_back(fixed);
  }
  return source;
}

class DomainCompiler {
 public:
  DomainCompiler(CompiledDomain& domain, const CompileOptions& options) : d_(domain), options_(options) {
    key_parts_.target = target_description(d_.spec.target_env);
  }

  Status run() {
    if (Status s = check_shader_files(); !s) return s;
    if (Status s = check_feature_reads(d_.spec); !s) return s;
    d_.jobs = make_jobs(d_.spec, d_.plan);
    index_jobs();
    if (build_.role.is_shard())
      range_ = shard_range(d_.jobs.size(), build_.role.place().index, build_.role.place().count);
    else
      range_ = {0, d_.jobs.size()};
    PhaseClock clock(d_.phases);
    auto reused = reuse_inputs();
    if (!reused) return std::move(reused).take_errors();
    d_.inputs_reused = *reused;
    clock.lap("input check");
    if (!d_.inputs_reused) {
      if (Status s = preprocess_all(); !s) return s;
      clock.lap("preprocess");
    }
    if (build_.role.is_shard()) {
      Status s = compile_shard(build_.role.place());
      clock.lap("shard compile or find");
      if (s) s = remember_part(build_.role.place());
      return s;
    }
    if (Status s = compile_sources(); !s) return s;
    clock.lap("compile or load");
    Status checked = check_blobs(clock);
    // A merge compiles nothing: the blobs it checked are the server's, and its error stands.
    if (!checked && remote_hits() > 0 && !build_.role.is_merge()) checked = recompile_remote_hits(checked, clock);
    if (!checked) return checked;
    keep_remote_hits();
    if (d_.spec.strip_debug) {
      // Only now: the caches, the server's entries included, keep the blobs with their names.
      if (Status s = strip_blobs(); !s) return s;
      clock.lap("strip debug");
    }
    remember_inputs();
    clock.lap("remember");
    return Ok{};
  }

 private:
  void index_jobs() {
    d_.raw_jobs.assign(d_.plan.raw.size(), -1);
    d_.optimised_jobs.assign(d_.plan.optimised.size(), -1);
    d_.companion_jobs.assign(d_.spec.companions.size(), -1);
    bool program = d_.spec.program_vertex.has_value();
    d_.raw_vertex_jobs.assign(program ? d_.plan.raw.size() : 0, -1);
    d_.optimised_vertex_jobs.assign(program ? d_.plan.optimised.size() : 0, -1);
    for (std::size_t i = 0; i < d_.jobs.size(); ++i) {
      const CompileJob& job = d_.jobs[i];
      auto& index = job.kind == JobKind::raw         ? (job.vertex_half ? d_.raw_vertex_jobs : d_.raw_jobs)
                    : job.kind == JobKind::optimised ? (job.vertex_half ? d_.optimised_vertex_jobs : d_.optimised_jobs)
                                                     : d_.companion_jobs;
      index[slot_of(job)] = static_cast<int>(i);
    }
  }

  // Where a job's permutation is in the plan's list (raw and optimised IDs of a listed domain
  // are not positions), or a companion's index.
  std::size_t slot_of(const CompileJob& job) const {
    if (job.kind == JobKind::raw) return *d_.plan.raw_position(job.id);
    if (job.kind == JobKind::optimised) return *d_.plan.optimised_position(job.id);
    return job.id;
  }

  // A shader file that is not there is the spec's mistake: said once, at the spec's key and
  // line, rather than once per permutation as a compile error.
  Status check_shader_files() const {
    std::vector<const ShaderFile*> files{&d_.spec.uber};
    if (d_.spec.program_vertex) files.push_back(&*d_.spec.program_vertex);
    for (const CompanionSpec& c : d_.spec.companions) files.push_back(&c.file);
    Diagnostics errors;
    for (const ShaderFile* file : files) {
      std::error_code ec;
      if (std::filesystem::exists(file->path, ec) || ec) continue;  // unreadable: the compile says why
      errors.push_back(Diagnostic{Severity::error, d_.spec.spec_path.string(), file->line, file->column,
                                  (file->spec_key.empty() ? std::string("shader") : file->spec_key) + ": shader file " +
                                      file->path.string() + " does not exist"});
    }
    if (!errors.empty()) return errors;
    return Ok{};
  }

  bool cancelled() const { return build_.cancelled && build_.cancelled(); }

  Status check_blobs(PhaseClock& clock) {
    if (Status s = reflect_blobs(); !s) return s;
    clock.lap("reflect");
    if (Status s = merge(); !s) return s;
    if (Status s = check_program(); !s) return s;
    clock.lap("layout");
    return Ok{};
  }

  std::size_t remote_hits() const {
    return static_cast<std::size_t>(
        std::count_if(d_.sources.begin(), d_.sources.end(), [](const SourceRecord& r) { return r.remote_hit; }));
  }

  // Entries that are each valid SPIR-V can still fail together (a foreign shader with another
  // layout). The server is then not trusted for this build: its entries are compiled here and
  // checked again, so the outcome is what a build without it would give. Only when that passes
  // was the server to blame, and warned about; otherwise the domain's own error stands.
  Status recompile_remote_hits(const Status& failed, PhaseClock& clock) {
    tiers_.set_aside_remote();
    std::vector<bool> compiled(d_.sources.size());
    for (std::size_t i = 0; i < d_.sources.size(); ++i) {
      SourceRecord& record = d_.sources[i];
      if (record.remote_hit) record.remote_hit = record.cache_hit = false, record.blob = -1;
      compiled[i] = !record.cache_hit;
    }
    d_.blobs.clear();
    d_.layout = {};
    if (Status s = compile_sources(); !s) return s;
    // What the first pass compiled now loads from the local cache; the summary counts it compiled.
    for (std::size_t i = 0; i < d_.sources.size(); ++i)
      if (compiled[i]) d_.sources[i].cache_hit = false;
    clock.lap("compile again");
    Status checked = check_blobs(clock);
    if (checked) tiers_.distrust_remote(failed.errors().front().message);
    return checked;
  }

  // A remote entry reaches the local cache only once the whole build has used it: the local
  // cache never holds what the checks would reject. Without a local cache (a merge, --no-cache)
  // there is nothing to keep, and the words are not read back.
  void keep_remote_hits() {
    if (!options_.cache) return;
    parallel_for(d_.sources.size(), build_.jobs, [&](std::size_t s) {
      const SourceRecord& record = d_.sources[s];
      if (!record.remote_hit) return;
      const Blob& blob = d_.blobs[static_cast<std::size_t>(record.blob)];
      // Before strip_blobs(): the blob's hash is that of the words as the server gave them.
      auto words = options_.spill->get(blob.hash);
      if (!words) {
        log("warning: " + words.errors().front().to_string());
        return;
      }
      store_local(record.key, CachedBlob{std::move(words).value(), blob.fell_back, blob.fallback_reason});
      tiers_.kept(record.key);
    });
    tiers_.remember_server_keys();
  }

  Status cancelled_error() const { return make_error("build interrupted"); }

  void log(const std::string& line) const {
    if (build_.log) build_.log(line);
  }

  // Gives job `i` the distinct source with this cache key, adding it if new.
  void assign_source(std::size_t i, const std::string& key, std::map<std::string, int>& by_key) {
    auto [it, fresh] = by_key.try_emplace(key, static_cast<int>(d_.sources.size()));
    if (fresh) d_.sources.push_back({key, i, false, 0.0, -1});
    d_.jobs[i].source = it->second;
  }

  // There are at most as many distinct sources as jobs, and as many in a domain without two
  // equal texts (the generated ones of the scale bench): room for all at once instead of
  // growth by doubling, which holds the old and the new list together. trim_sources() gives
  // back the room of a domain whose jobs share sources.
  void reserve_sources() { d_.sources.reserve(range_.size()); }
  void trim_sources() {
    if (d_.sources.size() < d_.sources.capacity() - d_.sources.capacity() / 4) d_.sources.shrink_to_fit();
  }

  // With an input-set entry whose every file is unchanged, the preprocessed texts (and so
  // their keys) are what they were: take the keys and skip glslang altogether. A shard looks
  // for its own part first (a rerun), then for a whole set; a merge of known shards joins their
  // parts (with a secret), and fails naming each shard whose part is not on the server.
  Result<bool> reuse_inputs() {
    if (options_.input_key.empty()) return false;
    if (build_.role.is_shard()) {
      const std::string part =
          input_set_part_key(options_.input_key, build_.role.place().index, build_.role.place().count);
      if (options_.inputs)
        if (auto set = options_.inputs->load(part); set && take_keys(*set, range_))
          return (taken_ = Taken::local_part, true);
      if (auto set = server_input_set(part); set && take_keys(*set, range_)) return (taken_ = Taken::server_part, true);
    } else if (build_.role.is_merge() && build_.role.shards() > 0 && options_.remote && options_.remote->signs()) {
      auto joined = joined_parts();
      if (!joined) return std::move(joined).take_errors();
      // Files changed since the shards ran: the merge preprocesses, and names what is missing.
      if (!take_keys(*joined, {0, d_.jobs.size()})) return false;
      taken_ = Taken::server_whole;
      return true;
    }
    std::optional<InputSet> set;
    if (options_.inputs) set = options_.inputs->load(options_.input_key);
    bool remote = false;
    if (!set) {
      set = server_input_set(options_.input_key);
      remote = set.has_value();
    }
    if (!set || !take_keys(*set, {0, d_.jobs.size()})) return false;
    taken_ = remote ? Taken::server_whole : Taken::local_whole;
    return true;
  }

  // Takes the keys of this build's jobs (range_) from `set`, which holds those of the jobs in
  // `covered`, when it covers them and every file it records is unchanged.
  bool take_keys(const InputSet& set, JobRange covered) {
    if (set.source_keys.size() != covered.size() || covered.first > range_.first || covered.last < range_.last)
      return false;
    if (!inputs_unchanged(set.files)) return false;
    std::map<std::string, int> by_key;
    reserve_sources();
    for (std::size_t i = range_.first; i < range_.last; ++i)
      assign_source(i, set.source_keys[i - covered.first], by_key);
    trim_sources();
    std::set<std::filesystem::path> dependencies{d_.spec.spec_path.lexically_normal()};
    for (const InputRead& file : set.files)
      if (file.found) dependencies.insert(file.path);
    d_.dependencies.assign(dependencies.begin(), dependencies.end());
    taken_files_ = set.files;
    return true;
  }

  // The signed input set (or part) another machine of the team remembered
  // (RemoteCache::load_input_set): a served build then skips preprocessing too. Checked like a
  // local one before use.
  std::optional<InputSet> server_input_set(const std::string& key) {
    if (!options_.remote) return std::nullopt;
    auto bytes = options_.remote->load_input_set(key);
    if (!bytes) return std::nullopt;
    return decode_input_set(key, *bytes);
  }

  // The merge of N known shards: their N parts of the input set from the server, joined. A part
  // that is not there (or fails its signature or checksum) fails the merge before it fetches an
  // entry, naming the shard to rerun.
  Result<InputSet> joined_parts() {
    const std::uint32_t count = build_.role.shards();
    std::vector<InputSet> parts;
    Diagnostics lacking;
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::string key = input_set_part_key(options_.input_key, i, count);
      RemoteCache::Found found = RemoteCache::Found::no_answer;
      auto bytes = options_.remote->load_input_set(key, &found);
      std::optional<InputSet> part;
      if (bytes) part = decode_input_set(key, *bytes);
      if (part && part->source_keys.size() == shard_range(d_.jobs.size(), i, count).size()) {
        parts.push_back(std::move(*part));
        continue;
      }
      const std::string place = std::to_string(i) + "/" + std::to_string(count);
      const char* what = found == RemoteCache::Found::none        ? "is not on the server"
                         : found == RemoteCache::Found::no_answer ? "was not fetched (the server stopped answering)"
                                                                  : "fails its checks (corrupt, or signed with another "
                                                                    "secret)";
      lacking.push_back(make_error(
          "shard " + place + ": its part of the input set " + what +
          "; rerun it: " + shard_rerun_command(d_.spec.spec_path.string(), place, options_.remote->shown_url())));
    }
    if (!lacking.empty()) {
      Diagnostics errors{make_error(std::to_string(lacking.size()) + " of " + std::to_string(count) +
                                    " shards' parts of the input set are not on the remote cache " +
                                    options_.remote->shown_url() + "; the merge fetched no entry and wrote nothing")};
      errors.insert(errors.end(), lacking.begin(), lacking.end());
      return errors;
    }
    auto joined = join_input_parts(std::move(parts));
    if (!joined) {
      Diagnostics errors = std::move(joined).take_errors();
      for (Diagnostic& e : errors) e.file = d_.spec.spec_path.string();
      return errors;
    }
    return joined;
  }

  // A shard's part of the input set: the files its jobs read and their keys, uploaded (signed;
  // only with a secret) for the merge, and kept in the local cache. A shard that took its part
  // from the server uploads nothing; one whose upload fails fails, since the merge would.
  Status remember_part(const Shard& shard) {
    if (options_.input_key.empty()) return Ok{};
    auto part_set = input_set_of_range();
    if (!part_set) return Ok{};  // a file changed during the build: nothing is remembered (the merge says so)
    const InputSet& part = *part_set;
    const std::string key = input_set_part_key(options_.input_key, shard.index, shard.count);
    if (options_.inputs && taken_ != Taken::local_part)
      if (Status stored = options_.inputs->store(key, part); !stored)
        log("warning: " + stored.errors().front().to_string());
    if (!options_.remote || !options_.remote->signs() || taken_ == Taken::server_part) return Ok{};
    if (options_.remote->store_input_set(key, encode_input_set(key, part))) return Ok{};
    return make_error("shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                      ": its part of the input set was not stored on the remote cache " + options_.remote->shown_url() +
                      " (the warnings above say why); the merge needs it");
  }

  // The input set of this build's jobs (range_): the files read (those of the set it took, or
  // what preprocessing read) and each job's key. nullopt when preprocessing read a file
  // differently in two jobs: nothing may then be remembered.
  std::optional<InputSet> input_set_of_range() {
    InputSet set;
    if (d_.inputs_reused)
      set.files = taken_files_;
    else if (reads_)
      set.files = std::move(*reads_);
    else
      return std::nullopt;
    set.source_keys.reserve(range_.size());
    for (std::size_t j = range_.first; j < range_.last; ++j)
      set.source_keys.push_back(d_.sources[static_cast<std::size_t>(d_.jobs[j].source)].key);
    return set;
  }

  void remember_inputs() {
    if (options_.input_key.empty()) return;
    // An input set from the server is kept here once the build has used it successfully; one
    // from the local cache (or joined from a merge's parts, which has no local cache) is there.
    if (d_.inputs_reused && taken_ != Taken::server_whole) return;
    auto set = input_set_of_range();
    if (!set) return;
    if (d_.inputs_reused) {
      if (options_.inputs) (void)options_.inputs->store(options_.input_key, *set);
      return;
    }
    // Like the content cache: failing to remember only costs time later.
    if (options_.inputs)
      if (Status stored = options_.inputs->store(options_.input_key, *set); !stored)
        log("warning: " + stored.errors().front().to_string());
    if (tiers_.remote_in_use())
      options_.remote->store_input_set(options_.input_key, encode_input_set(options_.input_key, *set));
  }

  // What is kept of each job's preprocessing is the text's cache key, not the text (a compile
  // preprocesses again); the includes and the files read go straight into sets shared by all
  // jobs (merge_reads()' rule: a file read differently by two jobs makes the reads
  // inconsistent). Memory then grows by a key per permutation, not by its text and reads.
  // A shard preprocesses its own jobs only (range_).
  Status preprocess_all() {
    const std::size_t first = range_.first;
    std::vector<Result<std::string>> keys(range_.size(), Result<std::string>(std::string()));
    std::mutex shared_mutex;
    std::set<std::filesystem::path> includes;
    std::map<std::filesystem::path, InputRead> reads;
    bool consistent = true;
    parallel_for(
        range_.size(), build_.jobs,
        [&](std::size_t k) {
          auto start = Clock::now();
          const std::size_t i = first + k;
          auto preprocessed = preprocess(source_of(d_, d_.jobs[i], kinds_));
          if (preprocessed) {
            keys[k] = cache_key(key_parts_, stage_name(d_.jobs[i].stage), key_text(preprocessed->text));
            std::lock_guard lock(shared_mutex);
            includes.insert(preprocessed->includes.begin(), preprocessed->includes.end());
            for (InputRead& read : preprocessed->reads) {
              auto [it, fresh] = reads.try_emplace(read.path, std::move(read));
              if (!fresh && (it->second.found != read.found || it->second.digest != read.digest)) consistent = false;
            }
          } else {
            keys[k] = std::move(preprocessed).take_errors();
          }
          d_.jobs[i].preprocess_ms = milliseconds_since(start);
        },
        build_.cancelled);
    if (cancelled()) return cancelled_error();
    std::vector<JobFailure> failures;
    std::map<std::string, int> by_key;
    std::set<std::filesystem::path> dependencies{d_.spec.spec_path.lexically_normal()};
    dependencies.insert(includes.begin(), includes.end());
    reserve_sources();
    for (std::size_t i = range_.first; i < range_.last; ++i) {
      dependencies.insert(d_.path_of(d_.jobs[i]).lexically_normal());
      if (!keys[i - first]) {
        failures.push_back({i, keys[i - first].errors(), {}});
        continue;
      }
      assign_source(i, *keys[i - first], by_key);
    }
    trim_sources();
    d_.dependencies.assign(dependencies.begin(), dependencies.end());
    if (!failures.empty()) return group_failures(d_, failures, build_.verbose);
    reads_.reset();
    if (consistent) {
      reads_.emplace();
      for (auto& [path, read] : reads) reads_->push_back(std::move(read));
    }
    return Ok{};
  }

  // Locally, then remotely (tiered_cache.h). A remote entry is used only if its SPIR-V
  // validates for this build's target and has an entry point of its stage (entry_check.h); the
  // build then reflects it and checks the layout with the rest, and keeps it locally only once
  // all of that passed (keep_remote_hits).
  std::optional<CachedBlob> load_cached(SourceRecord& record) {
    auto hit = tiers_.load(record.key, fit_check(d_.jobs[record.first_job].stage));
    record.remote_hit = hit && hit->remote;
    record.cache_hit = hit.has_value();
    if (!hit) return std::nullopt;
    return std::move(hit->blob);
  }

  // Remote entries are validated once per distinct blob and stage: many sources share a blob.
  // A signed entry's writer validated it (entry_check.h), so only its stage is checked; that
  // took the merge of a sharded build from validating every blob of the domain again.
  RemoteCache::Check fit_check(Stage stage) {
    if (options_.remote && options_.remote->signs())
      return [stage](const CachedBlob& blob) { return wrong_stage_reason(blob.words, stage); };
    return [this, stage](const CachedBlob& blob) {
      std::string id = sha256_hex(blob.words) + std::string(stage_name(stage));
      {
        std::lock_guard lock(checked_mutex_);
        if (auto found = checked_.find(id); found != checked_.end()) return found->second;
      }
      std::string reason = unfit_reason(blob.words, stage, d_.spec.target_env);
      std::lock_guard lock(checked_mutex_);
      checked_.emplace(std::move(id), reason);
      return reason;
    };
  }

  // The merge's lookup: the server alone (the driver gives a merge no local cache), every entry
  // checked as remote entries are. `why` becomes what the merge reports for a source it lacks.
  std::optional<CachedBlob> load_from_server(SourceRecord& record, char& why) {
    auto found = options_.remote->lookup(record.key, fit_check(d_.jobs[record.first_job].stage));
    record.remote_hit = record.cache_hit = found.blob.has_value();
    why = found.found == RemoteCache::Found::none       ? kMissing
          : found.found == RemoteCache::Found::rejected ? kCorrupt
          : found.found == RemoteCache::Found::entry    ? kFound
                                                        : kUnanswered;
    return std::move(found.blob);
  }

  void store_local(const std::string& key, const CachedBlob& blob) {
    if (!options_.cache) return;
    // A cache that cannot be written only costs time later; the build itself is fine.
    if (Status stored = options_.cache->store(key, blob); !stored)
      log("warning: " + stored.errors().front().to_string());
  }

  // The preprocessed lines of each failed job, so that grouping can count the permutations
  // that stopped at an earlier error but compile a later error's line too. Only failed
  // builds pay for this second preprocessing.
  std::vector<JobFailure> with_lines(std::vector<JobFailure> failures) {
    parallel_for(
        failures.size(), build_.jobs,
        [&](std::size_t i) {
          const CompileJob& job = d_.jobs[failures[i].job];
          if (auto text = preprocess(source_of(d_, job, kinds_)))
            failures[i].lines = live_lines(text->text, d_.path_of(job).lexically_normal().string());
        },
        build_.cancelled);
    return failures;
  }

  // Compiles, optimises and validates a source, and keeps the blob in the local cache.
  Result<CachedBlob> compile_fresh(SourceRecord& record) {
    auto start = Clock::now();
    auto words = compile(source_of(d_, d_.jobs[record.first_job], kinds_));
    if (!words) return std::move(words).take_errors();
    auto optimised = optimise_and_validate(std::move(words).value(), d_.spec.target_env);
    if (!optimised) return std::move(optimised).take_errors();
    record.compile_ms = milliseconds_since(start);
    CachedBlob blob{std::move(optimised->words), optimised->fell_back, std::move(optimised->fallback_reason)};
    store_local(record.key, blob);
    return blob;
  }

  Result<CachedBlob> compile_one(SourceRecord& record) {
    if (auto hit = load_cached(record)) return std::move(*hit);
    auto blob = compile_fresh(record);
    if (blob) tiers_.upload(record.key, *blob);
    return blob;
  }

  Status compile_sources() {
    distinct_.clear();
    distinct_index_.clear();
    spill_errors_.clear();
    std::vector<Result<SourceBlob>> results(d_.sources.size(), Result<SourceBlob>(SourceBlob{}));
    std::vector<char> missing(d_.sources.size(), 0);
    std::atomic<std::size_t> done{0};
    std::mutex log_mutex;
    std::size_t total = d_.sources.size();
    // A merge's threads wait on the server most of the time (measured at 18 features: three
    // fetches in flight per job took the fetching from 20-27 s to 13-17 s on 2 cores).
    const unsigned threads =
        build_.role.is_merge() ? kMergeFetchesPerJob * resolve_thread_count(build_.jobs) : build_.jobs;
    parallel_for(
        total, threads,
        [&](std::size_t i) {
          if (!build_.role.is_merge()) {
            auto blob = compile_one(d_.sources[i]);
            results[i] = blob ? spill(i, std::move(blob).value()) : Result<SourceBlob>(std::move(blob).take_errors());
          } else if (auto hit = load_from_server(d_.sources[i], missing[i])) {
            results[i] = spill(i, std::move(*hit));
          }
          std::size_t finished = ++done;
          report_progress(finished, total, i, log_mutex);
        },
        build_.cancelled);
    if (cancelled()) return cancelled_error();
    if (Status s = refuse_missing(missing); !s) return s;
    std::vector<JobFailure> failures;
    // Every job with a failed source has that source's errors.
    for (std::size_t j = 0; j < d_.jobs.size(); ++j) {
      const auto& result = results[static_cast<std::size_t>(d_.jobs[j].source)];
      if (!result) failures.push_back({j, result.errors(), {}});
    }
    if (!failures.empty()) return group_failures(d_, with_lines(std::move(failures)), build_.verbose);
    if (!spill_errors_.empty()) return spill_errors_;
    // Not needed past this point: freed before store_blobs() adds the blobs.
    distinct_index_ = {};
    store_blobs(results);
    return Ok{};
  }

  // What a distinct blob leaves in memory once its words are in the spill: reflected (the
  // build's checks need that) and, with strip_debug, stripped, as soon as it is made.
  struct DistinctBlob {
    std::string hash;  // of the words as compiled or loaded
    std::size_t word_count = 0;
    std::optional<ReflectionInfo> reflection;  // nullopt: `errors` says why
    std::string stripped_hash;                 // strip_debug: of the words written for the output
    std::size_t stripped_word_count = 0;
    Diagnostics errors;        // of reflection
    Diagnostics strip_errors;  // of strip_debug
  };
  // A source's blob: the distinct blob and what the source's compile said about it.
  struct SourceBlob {
    std::size_t distinct = 0;
    bool fell_back = false;
    std::string fallback_reason;
  };

  // Writes the words of source `s`'s blob to the spill (once per distinct blob) and keeps the
  // rest. The words a remote hit came with are kept there too: keep_remote_hits() reads them.
  SourceBlob spill(std::size_t s, CachedBlob blob) {
    SourceBlob out{0, blob.fell_back, std::move(blob.fallback_reason)};
    std::string hash = sha256_hex(blob.words);
    DistinctBlob* fresh = nullptr;
    {
      std::lock_guard lock(distinct_mutex_);
      auto [it, added] = distinct_index_.try_emplace(hash, distinct_.size());
      if (added) fresh = &distinct_.emplace_back();
      out.distinct = it->second;
    }
    const bool strip = d_.spec.strip_debug;
    if (d_.sources[s].remote_hit && strip) note_spill(options_.spill->put(hash, blob.words));
    if (!fresh) return out;
    DistinctBlob& distinct = *fresh;
    distinct.hash = hash;
    distinct.word_count = blob.words.size();
    auto info = reflect(blob.words, d_.jobs[d_.sources[s].first_job].stage);
    if (!info) {
      distinct.errors = std::move(info).take_errors();
      return out;
    }
    distinct.reflection = std::move(info).value();
    if (!strip) {
      note_spill(options_.spill->put(hash, blob.words));
      return out;
    }
    // After reflection, which reads the names; the caches keep the blobs with them.
    auto stripped = strip_debug_info(blob.words, d_.spec.target_env);
    if (!stripped) {
      distinct.strip_errors = std::move(stripped).take_errors();
      return out;
    }
    distinct.stripped_hash = sha256_hex(*stripped);
    distinct.stripped_word_count = stripped->size();
    note_spill(options_.spill->put(distinct.stripped_hash, *stripped));
    return out;
  }

  void note_spill(Status status) {
    if (status) return;
    std::lock_guard lock(distinct_mutex_);
    if (spill_errors_.empty()) spill_errors_ = std::move(status).take_errors();
  }

  // The merge (require_remote_hits): every distinct source must have come from the server.
  // What it lacks is counted by kind, and per shard when the shards are known, each with the
  // command that puts the shard's entries on the server again.
  Status refuse_missing(const std::vector<char>& why) const {
    const std::size_t total = why.size();
    std::array<std::size_t, 4> counts{};
    for (char w : why) ++counts[static_cast<unsigned char>(w)];
    if (counts[kMissing] + counts[kCorrupt] + counts[kUnanswered] == 0) return Ok{};
    const std::string url = options_.remote->shown_url();
    Diagnostics errors{make_error(std::to_string(total - counts[kFound]) + " of " + std::to_string(total) +
                                  " distinct sources are not on the remote cache " + url + " (" +
                                  lacking_text(counts[kMissing], counts[kCorrupt], counts[kUnanswered]) +
                                  "); --require-remote-hits compiles nothing, so nothing was written")};
    if (build_.role.shards() == 0) {
      errors.push_back(make_error("rerun the shards that filled " + url +
                                  " (with --shards N the merge names each shard that lacks sources)"));
      return errors;
    }
    // A source is named under the shard of its first job: that shard compiled it (others whose
    // jobs share it may have too), so rerunning it puts the entry back.
    std::map<std::uint32_t, std::array<std::size_t, 4>> per_shard;
    for (std::size_t s = 0; s < total; ++s)
      if (why[s] != kFound)
        ++per_shard[shard_of(d_.sources[s].first_job, d_.jobs.size(), build_.role.shards())]
                   [static_cast<unsigned char>(why[s])];
    for (const auto& [shard, n] : per_shard) {
      const std::string place = std::to_string(shard) + "/" + std::to_string(build_.role.shards());
      errors.push_back(make_error("shard " + place + ": " + lacking_text(n[kMissing], n[kCorrupt], n[kUnanswered]) +
                                  "; rerun it: " + shard_rerun_command(d_.spec.spec_path.string(), place, url)));
    }
    return errors;
  }

  // "2 sources missing, 1 corrupt": the kinds that occur.
  static std::string lacking_text(std::size_t missing, std::size_t corrupt, std::size_t unanswered) {
    std::string text;
    auto add = [&](std::size_t n, const std::string& what) {
      if (n == 0) return;
      if (!text.empty()) text += ", ";
      text += std::to_string(n) + (text.empty() ? (n == 1 ? " source " : " sources ") : " ") + what;
    };
    add(missing, "missing");
    add(corrupt, "corrupt");
    add(unanswered, "not fetched (the server stopped answering; the warning above says why)");
    return text;
  }

  // One source of a shard: on_server when the server had it (verified, or offered from the
  // local cache), uploaded when it was compiled here and stored, missing when an upload failed.
  // A compile error is returned as such.
  // The server's copy is read and verified even when the local cache holds the entry: a HEAD
  // would trust a corrupt copy, and the merge would then fail until someone deleted it. A
  // missing or rejected copy is replaced (PUT over it) by the local entry or a fresh compile.
  enum class ShardFate { on_server, uploaded, replaced, missing };
  Result<ShardFate> make_sure_on_server(SourceRecord& record) {
    auto served = options_.remote->lookup(record.key, fit_check(d_.jobs[record.first_job].stage));
    if (served.found == RemoteCache::Found::entry) {
      record.cache_hit = record.remote_hit = true;
      return ShardFate::on_server;
    }
    if (served.found == RemoteCache::Found::no_answer) return ShardFate::missing;
    const bool replacing = served.found == RemoteCache::Found::rejected;
    std::optional<CachedBlob> blob;
    if (options_.cache) blob = options_.cache->load(record.key);
    record.cache_hit = blob.has_value();
    if (!blob) {
      auto fresh = compile_fresh(record);
      if (!fresh) return std::move(fresh).take_errors();
      blob = std::move(fresh).value();
    }
    if (!options_.remote->store(record.key, *blob)) return ShardFate::missing;
    return replacing ? ShardFate::replaced : ShardFate::uploaded;
  }

  // build --shard: the distinct sources of this shard's jobs, each made sure of on the server.
  // GLSL errors are grouped over the shard's permutations, as in a whole build.
  Status compile_shard(const Shard& shard) {
    const std::size_t total = d_.sources.size();
    std::vector<Result<ShardFate>> fates(total, Result<ShardFate>(ShardFate::missing));
    std::atomic<std::size_t> done{0};
    std::mutex log_mutex;
    parallel_for(
        total, build_.jobs,
        [&](std::size_t k) {
          fates[k] = make_sure_on_server(d_.sources[k]);
          report_progress(++done, total, k, log_mutex);
        },
        build_.cancelled);
    if (cancelled()) return cancelled_error();
    std::vector<JobFailure> failures;
    for (std::size_t j = range_.first; j < range_.last; ++j) {
      const auto& fate = fates[static_cast<std::size_t>(d_.jobs[j].source)];
      if (!fate) failures.push_back({j, fate.errors(), {}});
    }
    if (!failures.empty()) return group_failures(d_, with_lines(std::move(failures)), build_.verbose);
    ShardOutcome outcome{shard.index, shard.count, static_cast<std::uint32_t>(total), 0, 0, 0};
    for (const auto& fate : fates) {
      outcome.on_server += *fate == ShardFate::on_server;
      outcome.uploaded += *fate == ShardFate::uploaded || *fate == ShardFate::replaced;
      outcome.replaced += *fate == ShardFate::replaced;
    }
    d_.shard = outcome;
    std::uint32_t missing = outcome.sources - outcome.on_server - outcome.uploaded;
    if (missing == 0) return Ok{};
    return make_error("shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) + ": " +
                      std::to_string(missing) + " of its " + std::to_string(outcome.sources) +
                      " distinct sources are not on the remote cache " + options_.remote->shown_url() +
                      " (uploads failed; the warnings above say why)");
  }

  void report_progress(std::size_t finished, std::size_t total, std::size_t source, std::mutex& mutex) {
    std::lock_guard lock(mutex);
    const SourceRecord& record = d_.sources[source];
    if (build_.verbose) {
      const CompileJob& job = d_.jobs[record.first_job];
      std::string defines;
      for (const std::string& d : d_.defines_of(job)) {
        defines += ' ';
        defines += d;
      }
      log(std::string("[").append(std::to_string(finished)) + "/" + std::to_string(total) + "] " +
          (record.remote_hit  ? "remote   "
           : record.cache_hit ? "cached   "
                              : "compiled ") +
          d_.label_of(job) + (defines.empty() ? "" : ":" + defines));
    } else if (total >= 8 && finished % (total / 4) == 0 && finished != total) {
      log(std::to_string(finished) + "/" + std::to_string(total) + " sources done");
    }
  }

  // Distinct sources can still give equal SPIR-V (a define that changes no code path that
  // survives optimisation); those share one blob. The blobs are in the order of their first
  // source, whichever worker made them first.
  void store_blobs(std::vector<Result<SourceBlob>>& results) {
    std::vector<int> blob_of(distinct_.size(), -1);
    blob_distinct_.clear();
    // Every distinct blob becomes one blob. Reserved, not grown by doubling: the blobs are the
    // biggest record per permutation, and a doubling holds the old and the new list at once.
    d_.blobs.reserve(d_.blobs.size() + distinct_.size());
    blob_distinct_.reserve(distinct_.size());
    for (std::size_t s = 0; s < d_.sources.size(); ++s) {
      SourceBlob& compiled = results[s].value();
      int& blob = blob_of[compiled.distinct];
      if (blob < 0) {
        blob = static_cast<int>(d_.blobs.size());
        DistinctBlob& distinct = distinct_[compiled.distinct];
        d_.blobs.push_back(Blob{distinct.word_count, std::move(distinct.hash),
                                std::move(distinct.reflection).value_or(ReflectionInfo{}), compiled.fell_back,
                                std::move(compiled.fallback_reason)});
        blob_distinct_.push_back(compiled.distinct);
      }
      d_.sources[s].blob = blob;
    }
    for (CompileJob& job : d_.jobs) job.blob = d_.sources[static_cast<std::size_t>(job.source)].blob;
  }

  // Reflection happened as each blob was made (spill()); this reports its errors, blob by blob.
  Status reflect_blobs() {
    Diagnostics errors;
    for (std::size_t distinct : blob_distinct_)
      for (Diagnostic& error : distinct_[distinct].errors) errors.push_back(error);
    if (!errors.empty()) return errors;
    return Ok{};
  }

  // After reflection, which reads the names: the blobs lose their debug instructions. Blobs
  // that differed only in those become one; every job and source follows its blob. The words
  // were stripped as each blob was made (spill()); this renumbers the blobs and reports errors.
  Status strip_blobs() {
    std::vector<Blob> stripped;
    std::vector<int> moved(d_.blobs.size(), -1);
    std::map<std::string, int> by_hash;
    Diagnostics errors;
    for (std::size_t b = 0; b < d_.blobs.size(); ++b) {
      const DistinctBlob& distinct = distinct_[blob_distinct_[b]];
      if (!distinct.strip_errors.empty()) {
        for (const Diagnostic& error : distinct.strip_errors) errors.push_back(error);
        continue;
      }
      const std::string& hash = distinct.stripped_hash;
      auto [it, fresh] = by_hash.try_emplace(hash, static_cast<int>(stripped.size()));
      if (fresh) {
        stripped.push_back(std::move(d_.blobs[b]));
        stripped.back().word_count = distinct.stripped_word_count;
        stripped.back().hash = hash;
      }
      moved[b] = it->second;
    }
    if (!errors.empty()) return errors;
    d_.blobs = std::move(stripped);
    for (CompileJob& job : d_.jobs) job.blob = moved[static_cast<std::size_t>(job.blob)];
    for (SourceRecord& source : d_.sources) source.blob = moved[static_cast<std::size_t>(source.blob)];
    return Ok{};
  }

  Status merge() {
    // Each permutation keeps its own reflection; there is nothing to merge or check.
    if (d_.spec.layout == LayoutMode::per_permutation) return Ok{};
    std::vector<LabelledReflection> labelled;
    std::set<int> seen;
    for (const CompileJob& job : d_.jobs) {
      if (job.kind == JobKind::companion && !d_.spec.companions[job.id].shared_layout) continue;
      if (!seen.insert(job.blob).second) continue;
      std::string label = d_.label_of(job);
      std::vector<std::string> defines = d_.defines_of(job);
      if (job.kind != JobKind::companion && !defines.empty()) {
        label += " (";
        for (std::size_t i = 0; i < defines.size(); ++i) {
          if (i) label += ' ';
          label += defines[i];
        }
        label += ")";
      }
      labelled.push_back(
          {label, job.stage, job.kind != JobKind::companion, &d_.blobs[static_cast<std::size_t>(job.blob)].reflection});
    }
    auto layout = merge_layouts(labelled);
    if (!layout) {
      Diagnostics errors = std::move(layout).take_errors();
      for (Diagnostic& e : errors) e.file = d_.spec.spec_path.string();
      return errors;
    }
    d_.layout = std::move(layout).value();
    return Ok{};
  }

  // The "program" form: every permutation's fragment inputs are among its vertex outputs. A
  // problem is said once with the permutations that have it, as GLSL errors are.
  Status check_program() {
    if (!d_.spec.program_vertex) return Ok{};
    std::map<std::string, std::set<std::size_t>> problems;  // -> fragment jobs
    std::map<std::string, std::string> inputs;              // -> the fragment input it is about
    std::vector<std::string> order;
    for (const CompileJob& job : d_.jobs) {
      if (!job.vertex_half) continue;
      const auto& index = job.kind == JobKind::raw ? d_.raw_jobs : d_.optimised_jobs;
      std::size_t fragment = static_cast<std::size_t>(index[slot_of(job)]);
      for (InterfaceProblem& problem :
           interface_problems(d_.blobs[static_cast<std::size_t>(job.blob)].reflection.outputs,
                              d_.blobs[static_cast<std::size_t>(d_.jobs[fragment].blob)].reflection.inputs)) {
        auto [it, fresh] = problems.try_emplace(problem.message);
        if (fresh) order.push_back(problem.message), inputs[problem.message] = problem.input;
        it->second.insert(fragment);
      }
    }
    Diagnostics errors;
    for (const std::string& problem : order) {
      Diagnostic error = make_error(problem + " (" + where_it_occurs(d_, problems[problem], build_.verbose) + ")");
      // At the input's declaration in the fragment shader, else at the spec.
      std::optional<SourceLocation> at = input_declaration(inputs[problem], {d_.spec.uber.path}, d_.spec.include_dirs);
      error.file = at ? at->file.string() : d_.spec.spec_path.string();
      error.line = at ? at->line : 0;
      errors.push_back(std::move(error));
    }
    if (!errors.empty()) return errors;
    return Ok{};
  }

  // What the merge found of each distinct source (refuse_missing).
  static constexpr char kFound = 0, kMissing = 1, kCorrupt = 2, kUnanswered = 3;
  static constexpr unsigned kMergeFetchesPerJob = 3;

  CompiledDomain& d_;
  const CompileOptions& options_;
  const BuildOptions& build_ = *options_.build;
  JobRange range_;  // the jobs this build preprocesses and compiles: a shard's, else all
  // Where the input set whose keys the build took came from (none: it preprocessed), and its
  // files. A shard that took a whole set still uploads its part; one that took its own part
  // from the server does not.
  enum class Taken { none, local_part, server_part, local_whole, server_whole };
  Taken taken_ = Taken::none;
  std::vector<InputRead> taken_files_;
  CacheKeyParts key_parts_ = current_cache_key_parts();  // with this domain's target
  KindDeclarations kinds_ = kind_declarations(d_.spec);
  std::optional<std::vector<InputRead>> reads_;         // what preprocessing read; nullopt: inconsistent
  TieredCache tiers_{options_.cache, options_.remote};  // the local and remote caches' policy
  std::mutex checked_mutex_;                            // guards checked_
  std::map<std::string, std::string> checked_;          // blob hash + stage -> unfit_reason()
  std::mutex distinct_mutex_;                           // guards the three below
  std::deque<DistinctBlob> distinct_;                   // stable addresses while workers fill them
  std::map<std::string, std::size_t> distinct_index_;   // hash of the words -> distinct_
  Diagnostics spill_errors_;                            // the first failure to write a blob
  std::vector<std::size_t> blob_distinct_;              // d_.blobs -> distinct_, before strip_blobs()
};

}  // namespace

Result<CompiledDomain> compile_domain(DomainSpec spec, PermutationPlan plan, const CompileOptions& options) {
  CompiledDomain domain;
  domain.spec = std::move(spec);
  domain.plan = std::move(plan);
  if (Status status = DomainCompiler(domain, options).run(); !status) return std::move(status).take_errors();
  return domain;
}

}  // namespace shadergen
