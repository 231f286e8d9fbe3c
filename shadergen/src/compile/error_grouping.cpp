#include "compile/error_grouping.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

namespace shadergen {
namespace {

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string text;
  for (const std::string& item : items) {
    if (!text.empty()) text.append(separator);
    text.append(item);
  }
  return text;
}

std::string describe_job(const CompiledDomain& domain, const CompileJob& job) {
  std::string text = domain.label_of(job);
  if (job.kind == JobKind::companion) return text;
  std::vector<std::string> defines = domain.defines_of(job);
  return text + (defines.empty() ? " (no defines)" : " with " + join(defines, " "));
}

// A variant feature's setting as diagnostics name it: the spec's name, with the define in
// brackets where it differs ("SHADOW_SOFT [SOFT_SHADOW]", "SHADING=PBR [SHADING_MODEL=PBR]").
std::string feature_text(const RawFeature& f, std::uint32_t index) {
  if (!f.valued()) return f.name == f.define ? f.name : f.name + " [" + f.define + "]";
  const std::string& value = f.values[index];
  return f.name == f.define ? f.name + "=" + value : f.name + "=" + value + " [" + f.define + "=" + value + "]";
}

// The variant features whose setting every raw ID of `ids` shares: {feature, value index}.
std::vector<std::pair<const RawFeature*, std::uint32_t>> shared_settings(const DomainSpec& spec,
                                                                         const std::set<std::uint32_t>& ids) {
  std::vector<std::pair<const RawFeature*, std::uint32_t>> shared;
  for (const RawFeature& f : spec.raw_features) {
    if (!f.is_variant()) continue;
    const std::uint32_t first = f.index_in(*ids.begin());
    if (first >= std::max<std::size_t>(f.values.size(), 2)) continue;
    if (std::all_of(ids.begin(), ids.end(), [&](std::uint32_t id) { return f.index_in(id) == first; }))
      shared.emplace_back(&f, first);
  }
  return shared;
}

// True when the raw IDs holding every one of `settings` are exactly `ids` among `all`.
bool exactly(const std::vector<std::pair<const RawFeature*, std::uint32_t>>& settings,
             const std::set<std::uint32_t>& ids, const std::set<std::uint32_t>& all) {
  for (std::uint32_t id : all) {
    const bool holds =
        std::all_of(settings.begin(), settings.end(), [&](const auto& s) { return s.first->index_in(id) == s.second; });
    if (holds != (ids.count(id) > 0)) return false;
  }
  return true;
}

// "those with SHADOW_SOFT [SOFT_SHADOW] and SKY" when the failing raw IDs are exactly the ones
// with some variant features on (or valued ones at a value), "..., without SUN_LIGHT" when the
// features they all lack are needed too, "all of them", or nothing (the example still names one).
std::string pattern(const CompiledDomain& domain, const std::set<std::size_t>& failing_raw) {
  if (failing_raw.empty()) return {};
  std::set<std::uint32_t> ids, all;
  for (std::size_t index : failing_raw) ids.insert(domain.jobs[index].id);
  for (const CompileJob& job : domain.jobs)
    if (job.kind == JobKind::raw) all.insert(job.id);
  if (ids == all) return "all of them";
  std::vector<std::pair<const RawFeature*, std::uint32_t>> with, without;
  for (const auto& setting : shared_settings(domain.spec, ids))
    (setting.first->valued() || setting.second != 0 ? with : without).push_back(setting);
  std::vector<std::string> with_text, without_text;
  for (const auto& [f, index] : with) with_text.push_back(feature_text(*f, index));
  if (!with.empty() && exactly(with, ids, all)) return "those with " + join(with_text, " and ");
  std::vector<std::pair<const RawFeature*, std::uint32_t>> both = with;
  both.insert(both.end(), without.begin(), without.end());
  if (without.empty() || !exactly(both, ids, all)) return {};
  for (const auto& [f, index] : without)
    without_text.push_back(f->name == f->define ? f->name : f->name + " [" + f->define + "]");
  return (with.empty() ? "those " : "those with " + join(with_text, " and ") + ", ") + "without " +
         join(without_text, " or ");
}

// In a "program" each permutation has two shaders: " (vertex shader)", " (fragment shader)" or
// " (both shaders)" for the failing jobs; nothing otherwise.
std::string halves(const std::vector<CompileJob>& jobs, const std::set<std::size_t>& failing) {
  bool program = std::any_of(jobs.begin(), jobs.end(), [](const CompileJob& j) { return j.vertex_half; });
  if (!program) return {};
  bool vertex = false, fragment = false;
  for (std::size_t index : failing) {
    if (jobs[index].kind == JobKind::companion) continue;
    (jobs[index].vertex_half ? vertex : fragment) = true;
  }
  if (!vertex && !fragment) return {};
  return vertex && fragment ? " (both shaders)" : vertex ? " (vertex shader)" : " (fragment shader)";
}

}  // namespace

std::string where_it_occurs(const CompiledDomain& domain, const std::set<std::size_t>& failing, bool every_example) {
  const std::vector<CompileJob>& jobs = domain.jobs;
  // Permutations are counted by ID: a program's two shaders of one raw ID are one permutation.
  std::set<std::uint32_t> raw_total, optimised_total, raw_ids, optimised_ids;
  for (const CompileJob& job : jobs) {
    if (job.kind == JobKind::raw) raw_total.insert(job.id);
    if (job.kind == JobKind::optimised) optimised_total.insert(job.id);
  }
  std::set<std::size_t> raw;
  std::vector<std::string> companions;
  for (std::size_t index : failing) {
    const CompileJob& job = jobs[index];
    if (job.kind == JobKind::raw) raw.insert(index), raw_ids.insert(job.id);
    if (job.kind == JobKind::optimised) optimised_ids.insert(job.id);
    if (job.kind == JobKind::companion) companions.push_back(domain.label_of(job));
  }
  std::vector<std::string> parts;
  std::string half = halves(jobs, failing);
  if (!raw.empty()) {
    std::string text =
        std::to_string(raw_ids.size()) + " of " + std::to_string(raw_total.size()) + " raw permutations" + half;
    std::string p = pattern(domain, raw);
    if (!p.empty()) text += ": " + p;
    parts.push_back(text);
  }
  if (!optimised_ids.empty())
    parts.push_back(std::to_string(optimised_ids.size()) + " of " + std::to_string(optimised_total.size()) +
                    " optimised permutations" + (raw.empty() ? half : ""));
  for (const std::string& c : companions) parts.push_back(c);
  const CompileJob& example = jobs[*failing.begin()];
  std::string text = "in " + join(parts, "; ");
  // With no shared define set, -v lists every permutation; otherwise one example says enough.
  bool listed = every_example && failing.size() > 1 && pattern(domain, raw).empty();
  if (listed) {
    std::vector<std::string> all;
    all.reserve(failing.size());
    for (std::size_t index : failing) all.push_back(describe_job(domain, jobs[index]));
    return text + "; namely " + join(all, ", ");
  }
  return text +
         (failing.size() > 1 || example.kind != JobKind::companion ? "; e.g. " + describe_job(domain, example) : "");
}

LiveLines live_lines(std::string_view text, const std::string& main_file) {
  // glslang's output opens with the preamble's one kept line, the include extension that
  // shadergen switches on; the shader's own line 1 follows it.
  constexpr std::string_view kPreamble = "#extension GL_GOOGLE_include_directive : require\n";
  if (text.substr(0, kPreamble.size()) == kPreamble) text.remove_prefix(kPreamble.size());
  LiveLines lines;
  std::string file = main_file;
  int line = 1;
  while (!text.empty()) {
    std::size_t end = text.find('\n');
    std::string_view current = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    std::size_t start = current.find_first_not_of(" \t");
    if (start != std::string_view::npos && current.substr(start, 5) == "#line") {
      std::string_view rest = current.substr(start + 5);
      std::size_t digits = rest.find_first_of("0123456789");
      if (digits != std::string_view::npos) line = std::atoi(std::string(rest.substr(digits)).c_str());
      std::size_t open = rest.find('"'), close = rest.rfind('"');
      if (open != std::string_view::npos && close > open) file = std::string(rest.substr(open + 1, close - open - 1));
      continue;
    }
    if (start != std::string_view::npos) lines[{file, line}] = std::string(current.substr(start));
    ++line;
  }
  return lines;
}

namespace {

struct Group {
  Diagnostic error;
  std::set<std::size_t> failing;  // job indices
  std::size_t rank = 0;           // smallest position among a failure's kept messages
  std::string line_text;          // the line as a failure that reported it saw it
};

// The failure's messages less glslang's follow-on ones at a place already reported.
std::vector<const Diagnostic*> kept_messages(const JobFailure& failure) {
  std::set<std::pair<std::string, int>> places;
  std::vector<const Diagnostic*> kept;
  for (const Diagnostic& error : failure.errors)
    if (error.line == 0 || places.insert({error.file, error.line}).second) kept.push_back(&error);
  return kept;
}

}  // namespace

Diagnostics group_failures(const CompiledDomain& domain, const std::vector<JobFailure>& failures, bool every_example) {
  // Key on the whole located message so the same error at the same line groups together.
  std::map<std::string, Group> groups;
  std::vector<std::string> order;
  for (const JobFailure& failure : failures) {
    std::vector<const Diagnostic*> kept = kept_messages(failure);
    for (std::size_t rank = 0; rank < kept.size(); ++rank) {
      const Diagnostic& error = *kept[rank];
      std::string key = error.to_string();
      auto [it, fresh] = groups.try_emplace(key, Group{error, {}, rank, {}});
      if (fresh) order.push_back(key);
      it->second.failing.insert(failure.job);
      it->second.rank = std::min(it->second.rank, rank);
      auto line = failure.lines.find({error.file, error.line});
      if (line != failure.lines.end()) it->second.line_text = line->second;
    }
  }
  // A failure that stopped earlier still hits an error whose line it compiles unchanged.
  for (auto& [key, group] : groups) {
    if (group.line_text.empty()) continue;
    for (const JobFailure& failure : failures) {
      auto line = failure.lines.find({group.error.file, group.error.line});
      if (line != failure.lines.end() && line->second == group.line_text) group.failing.insert(failure.job);
    }
  }
  // First errors first (what a permutation stopped at), then source order.
  std::sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) {
    const Group& x = groups.at(a);
    const Group& y = groups.at(b);
    return std::tie(x.rank, x.error.file, x.error.line, x.error.message) <
           std::tie(y.rank, y.error.file, y.error.line, y.error.message);
  });
  Diagnostics out;
  for (const std::string& key : order) {
    const Diagnostic& error = groups.at(key).error;
    const std::set<std::size_t>& failing = groups.at(key).failing;
    Diagnostic grouped = error;
    grouped.message += " (" + where_it_occurs(domain, failing, every_example) + ")";
    out.push_back(std::move(grouped));
  }
  return out;
}

}  // namespace shadergen
