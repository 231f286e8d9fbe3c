#include "output/manifest.h"

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <sstream>

#include "spec/kind_declarations.h"
#include "spec/stages.h"

namespace shadergen {

std::string blob_relative_path(const Blob& blob) { return "spirv/" + blob.hash.substr(0, 16) + ".spv"; }

namespace {

using Json = nlohmann::ordered_json;

Json stage_list(std::uint32_t stages) {
  Json names = Json::array();
  for (std::uint32_t bit = 1; bit <= static_cast<std::uint32_t>(Stage::callable); bit <<= 1)
    if (stages & bit) names.push_back(stage_name(static_cast<Stage>(bit)));
  return names;
}

// {set, binding, kind, count, stages, name}, plus runtime_sized and input_attachment_index
// where they apply.
Json bindings_json(const std::vector<BindingInfo>& bindings) {
  Json out = Json::array();
  for (const BindingInfo& b : bindings) {
    Json& entry = out.emplace_back(Json::object());
    entry["set"] = b.set;
    entry["binding"] = b.binding;
    entry["kind"] = descriptor_kind_name(b.kind);
    entry["count"] = b.count;
    entry["stages"] = stage_list(b.stages);
    entry["name"] = b.name;
    if (b.runtime_sized) entry["runtime_sized"] = true;
    if (b.kind == DescriptorKind::input_attachment) entry["input_attachment_index"] = b.input_attachment_index;
  }
  return out;
}

Json variables_json(const std::vector<VariableInfo>& variables) {
  Json out = Json::array();
  for (const VariableInfo& v : variables)
    out.push_back(Json{{"location", v.location}, {"components", v.components}, {"name", v.name}});
  return out;
}

// With "layout": "per_permutation", the permutation's own layout: its blob's bindings, push
// constants and outputs.
Json own_layout(const Blob& blob) {
  return Json{{"bindings", bindings_json(blob.reflection.bindings)},
              {"push_constant_size", blob.reflection.push_constant_size},
              {"outputs", variables_json(blob.reflection.outputs)}};
}

void add_blob_fields(Json& entry, const Blob* blob, const DomainSpec& spec) {
  if (!blob) return;
  entry["spirv"] = blob_relative_path(*blob);
  entry["hash"] = blob->hash;
  if (spec.layout == LayoutMode::per_permutation) entry["layout"] = own_layout(*blob);
}

// The "program" form: the permutation's vertex shader beside its fragment shader.
void add_vertex_half(Json& entry, const Blob* blob) {
  if (!blob) return;
  entry["vertex_spirv"] = blob_relative_path(*blob);
  entry["vertex_hash"] = blob->hash;
}

// A feature's kind, constant ID and define style, each only when not the default, so that the
// manifests of variant-only domains stay as they were.
void add_kind(Json& entry, const RawFeature& f) {
  if (f.kind != FeatureKind::variant) entry["kind"] = feature_kind_name(f.kind);
  if (f.kind == FeatureKind::specialization) entry["constant_id"] = f.constant_id;
  if (f.is_variant() && f.define_style == DefineStyle::value) entry["define_style"] = "value";
}

void add_features(Json& manifest, const DomainSpec& spec) {
  Json& raw = manifest["raw_features"] = Json::array();
  for (const RawFeature& f : spec.raw_features) {
    Json& entry = raw.emplace_back(Json{{"name", f.name}, {"bit", f.bit}, {"define", f.define}});
    add_kind(entry, f);
  }
  if (spec.branch_block) {
    Json members = Json::array();
    std::vector<const RawFeature*> branches = spec.branch_features();
    for (std::size_t i = 0; i < branches.size(); ++i)
      members.push_back(Json{{"feature", branches[i]->name}, {"define", branches[i]->define}, {"offset", 4 * i}});
    manifest["branch_block"] = Json{{"set", spec.branch_block->set},
                                    {"binding", spec.branch_block->binding},
                                    {"size", (4 * branches.size() + 15) / 16 * 16},
                                    {"members", std::move(members)}};
  }
  Json& optimised = manifest["optimised_bits"] = Json::array();
  for (const OptimisedBit& b : spec.optimised_bits)
    optimised.push_back(Json{{"name", b.name}, {"bit", b.bit}, {"when", b.when.text}});
  if (spec.ignore_form()) {
    Json& ignored = manifest["optimised_ignore"] = Json::array();
    for (const IgnoreRule& rule : spec.ignored)
      ignored.push_back(Json{{"feature", spec.raw_features[rule.feature].name}, {"when", rule.when.text}});
  }
}

// A raw ID's values of the features of `kind`, in spec order (as the generated code gives them).
Json kind_values(const std::vector<const RawFeature*>& features, std::uint32_t raw_id) {
  Json values = Json::object();
  for (const RawFeature* f : features) {
    const std::uint32_t index = f->index_in(raw_id);
    if (!f->valued())
      values[f->name] = index != 0;
    else if (index < f->values.size())
      values[f->name] = value_number(*f, index);
  }
  return values;
}

// `with_blobs` false: the domain's part only (a spec with "uber_shaders" lists each entry's
// blobs in the entry: uber_shader_raw()). "defines" are as the compiler saw them: a value-style
// boolean as SKY=(0 == 1), not SKY=0, so that a script can rebuild the permutation from them.
Json raw_entry(const CompiledDomain& d, const KindDeclarations& kinds, const RawPermutation& raw,
               bool with_blobs = true) {
  Json entry{
      {"id", raw.id}, {"defines", boolean_value_defines(raw_defines(d.spec, raw.id), kinds)}, {"pruned", raw.pruned}};
  if (std::vector<const RawFeature*> s = d.spec.specialization_features(); !s.empty() && !raw.pruned)
    entry["specialization"] = kind_values(s, raw.id);
  if (std::vector<const RawFeature*> b = d.spec.branch_features(); !b.empty() && !raw.pruned)
    entry["branch_values"] = kind_values(b, raw.id);
  if (d.spec.collapsed) entry["optimised"] = raw.optimised;
  if (!with_blobs) return entry;
  add_blob_fields(entry, raw.pruned ? nullptr : d.raw_blob(raw.id), d.spec);
  add_vertex_half(entry, raw.pruned ? nullptr : d.raw_vertex_blob(raw.id));
  return entry;
}

Json optimised_entry(const CompiledDomain& d, const KindDeclarations& kinds, const OptimisedPermutation& optimised,
                     bool with_blobs = true) {
  Json entry{{"id", optimised.id},
             {"defines", boolean_value_defines(optimised.defines, kinds)},
             {"raw_equivalent", optimised.raw_equivalent},
             {"raw_mapped", optimised.raw_mapped}};
  if (!with_blobs) return entry;
  add_blob_fields(entry, d.optimised_blob(optimised.id), d.spec);
  add_vertex_half(entry, d.optimised_vertex_blob(optimised.id));
  return entry;
}

// An entry's blob of each permutation that has one: {id, spirv, hash}.
Json entry_blobs(const CompiledDomain& d, bool raw) {
  Json list = Json::array();
  auto add = [&](std::uint32_t id, const Blob* blob) {
    if (!blob) return;
    Json& entry = list.emplace_back(Json{{"id", id}});
    add_blob_fields(entry, blob, d.spec);
  };
  if (raw)
    for (const RawPermutation& r : d.plan.raw) add(r.id, r.pruned ? nullptr : d.raw_blob(r.id));
  else
    for (const OptimisedPermutation& o : d.plan.optimised) add(o.id, d.optimised_blob(o.id));
  return list;
}

Json companions_json(const CompiledDomain& d) {
  Json out = Json::array();
  for (std::size_t i = 0; i < d.spec.companions.size(); ++i) {
    const CompanionSpec& c = d.spec.companions[i];
    Json& entry = out.emplace_back(Json{{"name", c.name},
                                        {"stage", stage_name(c.file.stage)},
                                        {"defines", c.defines},
                                        {"shared_layout", c.shared_layout}});
    add_blob_fields(entry, d.companion_blob(i), d.spec);
  }
  return out;
}

std::string_view scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::boolean: return "bool";
    case ScalarType::int32: return "int";
    case ScalarType::uint32: return "uint";
    case ScalarType::float32: return "float";
  }
  return "?";
}

// A float as the double with the shortest decimal form that reads back as the same float
// (0.1f is written 0.1, not 0.10000000149011612).
double shortest_double(float value) {
  char text[32];
  auto [end, ec] = std::to_chars(text, text + sizeof text - 1, value);
  *end = '\0';
  return ec == std::errc() ? std::strtod(text, nullptr) : static_cast<double>(value);
}

// The default as JSON of its own type: bool, integer, or (for float) a JSON float.
Json default_json(const SpecConstantInfo& c) {
  switch (c.type) {
    case ScalarType::boolean: return c.default_bits != 0;
    case ScalarType::int32: return static_cast<std::int32_t>(c.default_bits);
    case ScalarType::uint32: return c.default_bits;
    case ScalarType::float32: {
      float f = 0;
      std::memcpy(&f, &c.default_bits, sizeof f);
      return shortest_double(f);
    }
  }
  return nullptr;
}

void add_workgroup(Json& entry, const ReflectionInfo& r) {
  entry["local_size"] = Json(r.local_size);
  Json& ids = entry["local_size_ids"] = Json::array();
  for (std::uint32_t id : r.local_size_ids) ids.push_back(id == Reflection::kNoConstant ? Json(nullptr) : Json(id));
}

Json specialization_constants_json(const ReflectionInfo& r) {
  Json out = Json::array();
  for (const SpecConstantInfo& c : r.specialization_constants)
    out.push_back(
        Json{{"id", c.id}, {"name", c.name}, {"type", scalar_type_name(c.type)}, {"default", default_json(c)}});
  return out;
}

// A distinct blob with its own reflection: what a permutation needs when it has a pipeline
// layout of its own, its work-group size and its specialization constants.
Json blob_entry(const Blob& blob, Stage stage, const BlobServes* serves) {
  const ReflectionInfo& r = blob.reflection;
  Json entry{{"spirv", blob_relative_path(blob)},     {"stage", stage_name(stage)},
             {"bindings", bindings_json(r.bindings)}, {"push_constant_size", r.push_constant_size},
             {"inputs", variables_json(r.inputs)},    {"outputs", variables_json(r.outputs)}};
  if (has_workgroup(stage)) add_workgroup(entry, r);
  entry["specialization_constants"] = specialization_constants_json(r);
  if (serves && serves->raw_ids > 0)
    entry["serves"] =
        Json{{"raw_ids", serves->raw_ids}, {"pipelines", serves->pipelines}, {"branch_values", serves->branch_values}};
  return entry;
}

std::vector<Stage> blob_stages(const CompiledDomain& d) {
  std::vector<Stage> stages(d.blobs.size(), Stage::fragment);
  for (const CompileJob& job : d.jobs) stages[static_cast<std::size_t>(job.blob)] = job.stage;
  return stages;
}

// Writes a JSON object exactly as dump(2) does, a member at a time, and the members that are
// long arrays an element at a time: a Json tree of every permutation at once took more memory
// than the rest of the build.
//
// Two-space indentation, keys in insertion order, "\n" line ends and a final newline. UTF-8 is
// written as it is. The spec reader accepts only UTF-8; should a byte that is not UTF-8 reach
// here from elsewhere (an optimiser's message), it becomes U+FFFD: the output stays valid JSON
// and writing never throws.
class ObjectWriter {
 public:
  explicit ObjectWriter(std::ostream& out) : out_(out) { out_ << '{'; }

  void member(const std::string& key, const Json& value) {
    open(key);
    write_indented(value, 2);
  }

  // `element(i)` gives the array's element i.
  template <class Element>
  void array(const std::string& key, std::size_t count, const Element& element) {
    open(key);
    if (count == 0) {
      out_ << "[]";
      return;
    }
    out_ << "[\n";
    for (std::size_t i = 0; i < count; ++i) {
      out_ << "    ";
      write_indented(element(i), 4);
      out_ << (i + 1 < count ? ",\n" : "\n");
    }
    out_ << "  ]";
  }

  void finish() { out_ << (empty_ ? "}\n" : "\n}\n"); }

 private:
  void open(const std::string& key) {
    out_ << (empty_ ? "\n  " : ",\n  ") << Json(key).dump(-1, ' ', false, Json::error_handler_t::replace) << ": ";
    empty_ = false;
  }

  // `value` dumped on its own, every line after the first indented by `indent` more spaces.
  void write_indented(const Json& value, std::size_t indent) {
    const std::string text = value.dump(2, ' ', false, Json::error_handler_t::replace);
    const std::string pad(indent, ' ');
    for (std::size_t start = 0;;) {
      std::size_t newline = text.find('\n', start);
      if (newline == std::string::npos) {
        out_.write(text.data() + start, static_cast<std::streamsize>(text.size() - start));
        return;
      }
      out_.write(text.data() + start, static_cast<std::streamsize>(newline + 1 - start));
      out_ << pad;
      start = newline + 1;
    }
  }

  std::ostream& out_;
  bool empty_ = true;
};

Json layout_json(const MergedLayout& layout) {
  Json push_constants = Json::array();
  for (const PushConstantInfo& p : layout.push_constants)
    push_constants.push_back(Json{{"size", p.size}, {"stages", stage_list(p.stages)}});
  return Json{{"bindings", bindings_json(layout.bindings)}, {"push_constants", std::move(push_constants)}};
}

}  // namespace

namespace {

// The manifest's members about the domain as a whole (not its blobs).
Json domain_members(const CompiledDomain& d) {
  Json m = Json::object();
  m["format"] = 1;
  m["generator"] = "shadergen " SHADERGEN_VERSION;
  m["domain"] = d.spec.name;
  if (d.spec.entry.empty()) {
    m["uber_shader"] = d.spec.uber.path.filename().string();
    m["stage"] = stage_name(d.spec.uber.stage);
  }
  if (d.spec.program_vertex) m["vertex_shader"] = d.spec.program_vertex->path.filename().string();
  m["target_env"] = target_env_name(d.spec.target_env);
  m["collapsed"] = d.spec.collapsed;
  m["layout"] = d.spec.layout == LayoutMode::shared ? "shared" : "per_permutation";
  // Only when not the default, so the manifests of "all" domains stay as they were.
  if (d.spec.compile == CompileSet::optimised) m["compile"] = "optimised";
  // Only with a variants file: then "raw" and "optimised" hold the listed IDs and the ones they
  // map to, not every ID of the 2^raw_bits.
  if (d.spec.listed()) {
    m["raw_bits"] = d.spec.raw_bits();
    m["variants_file"] = d.spec.variants_path.filename().string();
  }
  // The fixed defines every shader was compiled with (spec, --define, CMake DEFINES), in order.
  m["defines"] = d.spec.defines;
  add_features(m, d.spec);
  return m;
}

// One entry of "uber_shaders": its shader, blobs by permutation, companions, layout and blobs.
Json uber_shader_entry(const CompiledDomain& d) {
  Json entry{{"name", d.spec.entry},
             {"uber_shader", d.spec.uber.path.filename().string()},
             {"stage", stage_name(d.spec.uber.stage)},
             {"raw", entry_blobs(d, true)},
             {"optimised", entry_blobs(d, false)},
             {"companions", companions_json(d)},
             {"pipeline_layout", layout_json(d.layout)}};
  const std::vector<Stage> stages = blob_stages(d);
  const std::vector<BlobServes> serves = blob_serves(d);
  Json& blobs = entry["blobs"] = Json::array();
  for (std::size_t i = 0; i < d.blobs.size(); ++i) blobs.push_back(blob_entry(d.blobs[i], stages[i], &serves[i]));
  return entry;
}

}  // namespace

void write_manifest(std::span<const CompiledDomain> entries, std::ostream& out) {
  const CompiledDomain& d = entries.front();
  const bool several = !d.spec.entry.empty();
  ObjectWriter writer(out);
  const Json members = domain_members(d);
  for (const auto& [key, value] : members.items()) writer.member(key, value);
  const KindDeclarations kinds = kind_declarations(d.spec);
  writer.array("raw", d.plan.raw.size(), [&](std::size_t i) { return raw_entry(d, kinds, d.plan.raw[i], !several); });
  writer.array("optimised", d.plan.optimised.size(),
               [&](std::size_t i) { return optimised_entry(d, kinds, d.plan.optimised[i], !several); });
  if (several) {
    writer.array("uber_shaders", entries.size(), [&](std::size_t i) { return uber_shader_entry(entries[i]); });
    writer.finish();
    return;
  }
  writer.member("companions", companions_json(d));
  writer.member("pipeline_layout", layout_json(d.layout));
  const std::vector<Stage> stages = blob_stages(d);
  const std::vector<BlobServes> serves = blob_serves(d);
  writer.array("blobs", d.blobs.size(), [&](std::size_t i) { return blob_entry(d.blobs[i], stages[i], &serves[i]); });
  writer.finish();
}

void write_manifest(const CompiledDomain& d, std::ostream& out) { write_manifest(std::span(&d, 1), out); }

std::string write_manifest(const CompiledDomain& d) {
  std::ostringstream out;
  write_manifest(d, out);
  return std::move(out).str();
}

namespace {

Json stage_counts(const CompiledDomain& d) {
  std::uint32_t pruned = 0, hits = 0, fallbacks = 0;
  for (const RawPermutation& raw : d.plan.raw) pruned += raw.pruned;
  for (const SourceRecord& s : d.sources) hits += s.cache_hit;
  for (const Blob& b : d.blobs) fallbacks += b.fell_back;
  Json counts = Json::object();
  counts["raw"] = d.plan.raw.size();
  counts["pruned"] = pruned;
  counts["canonical"] = d.jobs.size();
  counts["unique_sources"] = d.sources.size();
  counts["cache_hits"] = hits;
  counts["unique_blobs"] = d.blobs.size();
  counts["optimiser_fallbacks"] = fallbacks;
  return counts;
}

Json remote_counts(const RemoteCacheStats& remote) {
  return Json{
      {"fetched", remote.fetched}, {"missed", remote.missed}, {"uploaded", remote.uploaded}, {"failed", remote.failed}};
}

Json permutation_timing(const CompiledDomain& d, const CompileJob& job) {
  const SourceRecord& source = d.sources[static_cast<std::size_t>(job.source)];
  const Blob& blob = d.blobs[static_cast<std::size_t>(job.blob)];
  Json entry{{"permutation", d.label_of(job)},
             {"source", job.source},
             {"compiled_here", source.first_job == static_cast<std::size_t>(&job - d.jobs.data())},
             {"cache_hit", source.cache_hit},
             {"preprocess_ms", job.preprocess_ms},
             {"compile_ms", source.compile_ms},
             {"spirv_bytes", blob.word_count * 4}};
  if (blob.fell_back) entry["optimiser_fallback"] = blob.fallback_reason;
  return entry;
}

}  // namespace

namespace {

Json stats_members(const CompiledDomain& d) {
  std::uint32_t recompiled = 0;
  for (const CompileJob& job : d.jobs) recompiled += !d.sources[static_cast<std::size_t>(job.source)].cache_hit;
  Json s = Json::object();
  s["stages"] = stage_counts(d);
  s["recompiled_permutations"] = recompiled;
  s["reused_permutations"] = static_cast<std::uint32_t>(d.jobs.size()) - recompiled;
  s["inputs_reused"] = d.inputs_reused;
  if (d.remote) s["remote_cache"] = remote_counts(*d.remote);
  Json& phases = s["phases_ms"] = Json::object();
  for (const PhaseTime& phase : d.phases) phases[phase.name] = phase.ms;
  return s;
}

}  // namespace

void write_stats(std::span<const CompiledDomain> entries, double seconds, std::ostream& out) {
  ObjectWriter writer(out);
  if (!entries.front().spec.entry.empty()) {
    // "uber_shaders": each entry's counts, phases and permutations, as one build gives them.
    writer.member("seconds", seconds);
    writer.array("uber_shaders", entries.size(), [&](std::size_t e) {
      const CompiledDomain& d = entries[e];
      Json entry = stats_members(d);
      entry["name"] = d.spec.entry;
      Json& list = entry["permutations"] = Json::array();
      for (const CompileJob& job : d.jobs) list.push_back(permutation_timing(d, job));
      return entry;
    });
    writer.finish();
    return;
  }
  const CompiledDomain& d = entries.front();
  Json s = stats_members(d);
  s["seconds"] = seconds;
  for (const auto& [key, value] : s.items()) writer.member(key, value);
  writer.array("permutations", d.jobs.size(), [&](std::size_t i) { return permutation_timing(d, d.jobs[i]); });
  writer.finish();
}

void write_stats(const CompiledDomain& d, double seconds, std::ostream& out) {
  write_stats(std::span(&d, 1), seconds, out);
}

std::string write_stats(const CompiledDomain& d, double seconds) {
  std::ostringstream out;
  write_stats(d, seconds, out);
  return std::move(out).str();
}

namespace {
std::string escape_make(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}
}  // namespace

std::string write_depfile(const std::string& target, std::span<const CompiledDomain> entries) {
  std::set<std::filesystem::path> dependencies;
  for (const CompiledDomain& d : entries) dependencies.insert(d.dependencies.begin(), d.dependencies.end());
  std::string out = escape_make(target) + ":";
  for (const auto& dep : dependencies) {
    std::error_code ec;
    auto absolute = std::filesystem::absolute(dep, ec);
    out += " \\\n  " + escape_make((ec ? dep : absolute).lexically_normal().string());
  }
  return out + "\n";
}

std::string write_depfile(const std::string& target, const CompiledDomain& d) {
  return write_depfile(target, std::span(&d, 1));
}

}  // namespace shadergen
