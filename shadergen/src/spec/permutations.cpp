#include "shadergen/permutations.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "shadergen/registry.h"

namespace shadergen {

std::uint32_t apply_rules(const DomainSpec& spec, std::uint32_t raw_id) {
  std::uint32_t optimised = 0;
  for (const OptimisedBit& bit : spec.optimised_bits)
    if (bit.when.expression.evaluate(raw_id)) optimised |= 1u << bit.bit;
  return optimised;
}

std::string describe_bits(const std::vector<std::string>& names, std::uint32_t bits) {
  std::string text;
  for (std::uint32_t i = 0; i < names.size(); ++i)
    if (bits & (1u << i)) text += (text.empty() ? "" : " | ") + names[i];
  return text.empty() ? "(none)" : text;
}

std::string describe_raw(const DomainSpec& spec, std::uint32_t raw_id) {
  std::string text;
  for (const RawFeature& f : spec.raw_features) {
    std::uint32_t index = f.index_in(raw_id);
    if (!f.valued() && !index) continue;
    text += (text.empty() ? "" : " | ") + f.name;
    if (f.valued()) text += "=" + (index < f.values.size() ? f.values[index] : std::string("?"));
  }
  return text.empty() ? "(none)" : text;
}

int first_impossible_rule(const DomainSpec& spec, std::uint32_t raw_id) {
  for (std::size_t i = 0; i < spec.impossible.size(); ++i)
    if (spec.impossible[i].when.expression.evaluate(raw_id)) return static_cast<int>(i);
  return -1;
}

namespace {

int first_unvalued_feature(const DomainSpec& spec, std::uint32_t raw_id) {
  for (std::size_t i = 0; i < spec.raw_features.size(); ++i) {
    const RawFeature& f = spec.raw_features[i];
    if (f.valued() && f.index_in(raw_id) >= f.values.size()) return static_cast<int>(i);
  }
  return -1;
}

RawPermutation classify(const DomainSpec& spec, std::uint32_t id) {
  RawPermutation raw;
  raw.id = id;
  raw.pruned_by = first_impossible_rule(spec, id);
  raw.unvalued = first_unvalued_feature(spec, id);
  raw.pruned = raw.pruned_by >= 0 || raw.unvalued >= 0;
  // The ignore form numbers its optimised IDs once every raw ID is known (expand()).
  raw.optimised = !spec.collapsed ? id : spec.ignore_form() ? 0 : apply_rules(spec, id);
  return raw;
}

// The raw features an optimised ID is compiled with: the union over matching variants. Two
// variants giving one valued feature different values is a conflict: `conflict` gets its mask.
std::uint32_t raw_features_for_optimised(const DomainSpec& spec, std::uint32_t optimised_id, std::uint32_t& conflict) {
  std::uint32_t raw_bits = 0, assigned = 0;
  for (const OptimisedVariant& variant : spec.variants) {
    if (!variant.when.expression.evaluate(optimised_id)) continue;
    for (const FeatureSetting& setting : variant.raw_features) {
      if ((assigned & setting.mask) && (raw_bits & setting.mask) != setting.bits) conflict |= setting.mask;
      raw_bits = (raw_bits & ~setting.mask) | setting.bits;
      assigned |= setting.mask;
    }
  }
  return raw_bits;
}

// The optimised permutation `id`, or the error that forbids building it.
Result<OptimisedPermutation> optimised_permutation(const DomainSpec& spec, std::uint32_t id) {
  OptimisedPermutation optimised;
  optimised.id = id;
  std::uint32_t conflict = 0;
  optimised.raw_equivalent = raw_features_for_optimised(spec, id, conflict);
  optimised.defines = raw_defines(spec, optimised.raw_equivalent);
  auto names = spec.optimised_bit_names();
  if (conflict) {
    std::string features;
    for (const RawFeature& f : spec.raw_features)
      if (f.mask() & conflict) features += (features.empty() ? "" : ", ") + f.name;
    return make_error(spec.spec_path.string(), 0,
                      "optimised ID " + std::to_string(id) + " (" + describe_bits(names, id) +
                          ") matches variants that give " + features + " different values");
  }
  if (int rule_index = first_impossible_rule(spec, optimised.raw_equivalent); rule_index >= 0) {
    const ImpossibleSet& rule = spec.impossible[static_cast<std::size_t>(rule_index)];
    return make_error(spec.spec_path.string(), rule.when.line,
                      "optimised ID " + std::to_string(id) + " (" + describe_bits(names, id) +
                          ") is compiled with raw features " + describe_raw(spec, optimised.raw_equivalent) +
                          ", which the impossible rule \"" + rule.when.text + "\" prunes");
  }
  return optimised;
}

std::uint64_t text_length(const std::vector<const Rule*>& rules) {
  std::uint64_t length = 0;
  for (const Rule* rule : rules) length += rule->text.size() + 1;
  return length;
}

// The work expansion would do, against kMaxExpansionWork: raw IDs times the characters of the
// rules evaluated for each, plus optimised IDs (at most) times the variants' characters.
Status check_expansion_work(const DomainSpec& spec) {
  std::vector<const Rule*> per_raw, per_optimised;
  for (const ImpossibleSet& set : spec.impossible) per_raw.push_back(&set.when);
  for (const OptimisedBit& bit : spec.optimised_bits) per_raw.push_back(&bit.when);
  for (const OptimisedVariant& variant : spec.variants) per_optimised.push_back(&variant.when);
  const std::uint64_t raw_ids = spec.listed() ? spec.listed_raw_ids.size() : spec.raw_space();
  const std::uint64_t optimised_ids =
      spec.listed() ? std::min<std::uint64_t>(raw_ids, spec.optimised_count()) : spec.optimised_count();
  const std::uint64_t work = raw_ids * text_length(per_raw) + optimised_ids * text_length(per_optimised);
  if (work <= kMaxExpansionWork) return Ok{};
  return make_error(spec.spec_path.string(), 0,
                    "expanding the domain would evaluate its rules for " + std::to_string(raw_ids) + " raw IDs and " +
                        std::to_string(optimised_ids) + " optimised IDs, " + std::to_string(work) +
                        " rule characters in all; the limit is " + std::to_string(kMaxExpansionWork) +
                        ": shorten the impossible, optimised-bit and variant rules, or build fewer raw IDs");
}

// The raw IDs to expand: all of them, or the listed ones.
Result<std::vector<RawPermutation>> raw_permutations(const DomainSpec& spec) {
  std::vector<RawPermutation> raw;
  if (spec.listed()) {
    if (Status ok = check_expansion_work(spec); !ok) return std::move(ok).take_errors();
    raw.reserve(spec.listed_raw_ids.size());
    for (std::uint32_t id : spec.listed_raw_ids) raw.push_back(classify(spec, id));
    return raw;
  }
  if (spec.raw_bits() > kMaxEnumeratedRawBits)
    return make_error(spec.spec_path.string(), 0,
                      "the raw features take " + std::to_string(spec.raw_bits()) + " bits, " +
                          std::to_string(spec.raw_space()) + " raw IDs: past 2^" +
                          std::to_string(kMaxEnumeratedRawBits) + " (" +
                          std::to_string(std::uint64_t{1} << kMaxEnumeratedRawBits) +
                          ") raw IDs a domain lists the combinations it builds in a variants file (spec key "
                          "\"variants_file\", or build --variants FILE)");
  if (Status ok = check_expansion_work(spec); !ok) return std::move(ok).take_errors();
  raw.reserve(static_cast<std::size_t>(spec.raw_space()));
  for (std::uint64_t id = 0; id < spec.raw_space(); ++id) raw.push_back(classify(spec, static_cast<std::uint32_t>(id)));
  return raw;
}

// The optimised IDs to build: every one when enumerated, else those a listed raw ID maps to.
std::vector<std::uint32_t> optimised_ids(const DomainSpec& spec, const std::vector<RawPermutation>& raw) {
  std::vector<std::uint32_t> ids;
  if (!spec.listed()) {
    for (std::uint32_t id = 0; id < spec.optimised_count(); ++id) ids.push_back(id);
    return ids;
  }
  if (!spec.collapsed) return ids;
  for (const RawPermutation& r : raw)
    if (!r.pruned) ids.push_back(r.optimised);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

}  // namespace

std::vector<std::string> raw_defines(const DomainSpec& spec, std::uint32_t raw_id) {
  std::vector<std::string> defines;
  for (const RawFeature& feature : spec.raw_features) {
    // A specialization or branch feature is no define: one text serves all its values.
    if (!feature.is_variant()) continue;
    std::uint32_t index = feature.index_in(raw_id);
    const bool value_style = feature.define_style == DefineStyle::value;
    if (!feature.valued() && (index || value_style))
      defines.push_back(value_style ? feature.define + (index ? "=1" : "=0") : feature.define);
    if (feature.valued() && index < feature.values.size())
      defines.push_back(feature.define + "=" + feature.values[index]);
  }
  return defines;
}

std::optional<std::size_t> PermutationPlan::raw_position(std::uint32_t id) const { return position_by_id(raw, id); }
std::optional<std::size_t> PermutationPlan::optimised_position(std::uint32_t id) const {
  return position_by_id(optimised, id);
}
const RawPermutation* PermutationPlan::find_raw(std::uint32_t id) const {
  std::optional<std::size_t> at = raw_position(id);
  return at ? &raw[*at] : nullptr;
}
const OptimisedPermutation* PermutationPlan::find_optimised(std::uint32_t id) const {
  std::optional<std::size_t> at = optimised_position(id);
  return at ? &optimised[*at] : nullptr;
}

namespace {

// The raw combination the optimised shader of `raw_id` is compiled with in the ignore form: its
// variant features less those an ignore rule drops (a field cleared: off, or the first value).
std::uint32_t kept_features(const DomainSpec& spec, std::uint32_t raw_id) {
  std::uint32_t kept = raw_id & spec.variant_mask();
  for (const IgnoreRule& rule : spec.ignored)
    if (rule.when.expression.evaluate(raw_id)) kept &= ~spec.raw_features[rule.feature].mask();
  return kept;
}

// The ignore form: one optimised ID per distinct kept combination, in the order of the smallest
// raw ID reaching it (the raw IDs ascend), so no optimised ID is unreachable.
Status number_ignore_form(const DomainSpec& spec, PermutationPlan& plan) {
  std::map<std::uint32_t, std::uint32_t> ids;  // kept combination -> optimised ID
  for (RawPermutation& r : plan.raw) {
    if (r.pruned) continue;
    const std::uint32_t kept = kept_features(spec, r.id);
    auto [it, fresh] = ids.try_emplace(kept, static_cast<std::uint32_t>(plan.optimised.size()));
    if (fresh) {
      if (plan.optimised.size() == std::size_t{1} << kMaxOptimisedBits)
        return make_error(spec.spec_path.string(), 0,
                          "the \"ignore\" collapse keeps more than " + std::to_string(1u << kMaxOptimisedBits) +
                              " distinct combinations; ignore more features, or use \"bits\"");
      if (int rule = first_impossible_rule(spec, kept); rule >= 0)
        return make_error(spec.spec_path.string(), spec.impossible[static_cast<std::size_t>(rule)].when.line,
                          "raw ID " + std::to_string(r.id) + " (" + describe_raw(spec, r.id) +
                              ") would be drawn with " + describe_raw(spec, kept) +
                              " once its ignored features are dropped, which the impossible rule \"" +
                              spec.impossible[static_cast<std::size_t>(rule)].when.text + "\" prunes");
      OptimisedPermutation o;
      o.id = it->second;
      o.raw_equivalent = kept;
      o.defines = raw_defines(spec, kept);
      plan.optimised.push_back(std::move(o));
    }
    r.optimised = it->second;
    ++plan.optimised[it->second].raw_mapped;
  }
  return Ok{};
}

}  // namespace

Result<PermutationPlan> expand(const DomainSpec& spec) {
  PermutationPlan plan;
  auto raw = raw_permutations(spec);
  if (!raw) return std::move(raw).take_errors();
  plan.raw = std::move(raw).value();
  if (spec.ignore_form()) {
    if (Status numbered = number_ignore_form(spec, plan); !numbered) return std::move(numbered).take_errors();
    return plan;
  }
  Diagnostics errors;
  for (std::uint32_t id : optimised_ids(spec, plan.raw)) {
    auto optimised = optimised_permutation(spec, id);
    if (!optimised) {
      if (errors.size() < kMaxSpecErrors) errors.push_back(optimised.errors().front());
      continue;
    }
    plan.optimised.push_back(std::move(optimised).value());
  }
  if (!errors.empty()) return errors;
  if (spec.collapsed)
    for (const RawPermutation& r : plan.raw)
      if (!r.pruned) ++plan.optimised[*plan.optimised_position(r.optimised)].raw_mapped;
  return plan;
}

namespace {

// "3" for a one-bit feature, "3-4" for a field.
std::string bit_span(const RawFeature& f) {
  return f.width == 1 ? std::to_string(f.bit) : std::to_string(f.bit) + "-" + std::to_string(f.bit + f.width - 1);
}

std::string value_list(const RawFeature& f) {
  std::string text;
  for (const std::string& v : f.values) text += (text.empty() ? "" : ", ") + v;
  return text;
}

// "0=FOG, 1-2=TAA_QUALITY (0, 1, 2)".
std::string raw_bit_legend(const DomainSpec& spec) {
  std::string text;
  for (const RawFeature& f : spec.raw_features) {
    text += (text.empty() ? "" : ", ") + bit_span(f) + "=" + f.name;
    if (f.valued()) text += " (" + value_list(f) + ")";
  }
  return text;
}

}  // namespace

namespace {

// "Domain X: 128 raw IDs -> 32 optimised IDs", with the legend of the bits.
void lut_heading(std::ostringstream& out, const DomainSpec& spec, const PermutationPlan& plan) {
  out << "Domain " << spec.name << ": " << spec.raw_space() << " raw IDs";
  if (spec.listed())
    out << " (" << spec.raw_bits() << " bits), " << plan.raw.size() << " listed in " << spec.variants_path.string();
  if (spec.ignore_form())
    out << " -> " << plan.optimised.size() << " optimised IDs (the reachable combinations, ignored features dropped)";
  else if (spec.collapsed)
    out << " -> " << spec.optimised_count() << " optimised IDs" << (spec.listed() ? ", " : "")
        << (spec.listed() ? std::to_string(plan.optimised.size()) + " built" : "");
  else
    out << ", not collapsed (no \"optimised\" section): every compiled raw ID is its own permutation";
  out << "\n\nraw bits:       " << raw_bit_legend(spec);
  if (!spec.collapsed) return;
  if (spec.ignore_form()) {
    out << "\nignored:        ";
    for (std::size_t i = 0; i < spec.ignored.size(); ++i)
      out << (i ? "; " : "") << spec.raw_features[spec.ignored[i].feature].name << " when "
          << spec.ignored[i].when.text;
    if (spec.ignored.empty()) out << "(nothing: every combination of variant features is its own optimised ID)";
    return;
  }
  auto optimised_names = spec.optimised_bit_names();
  out << "\noptimised bits: ";
  for (std::size_t i = 0; i < optimised_names.size(); ++i) out << (i ? ", " : "") << i << "=" << optimised_names[i];
}

// Every raw ID, 16 to a row.
void lut_grid(std::ostringstream& out, const DomainSpec& spec, const PermutationPlan& plan) {
  out << "\n\nRow = raw ID / 16, column = raw ID % 16; each cell is the "
      << (spec.collapsed ? "optimised ID" : "permutation (the raw ID itself)") << ", '--' = pruned.\n\n      ";
  for (int c = 0; c < 16; ++c) {
    char cell[8];
    std::snprintf(cell, sizeof cell, " %3d", c);
    out << cell;
  }
  out << '\n';
  for (std::size_t row = 0; row * 16 < plan.raw.size(); ++row) {
    char label[32];
    std::snprintf(label, sizeof label, "%4zu: ", row * 16);
    out << label;
    for (std::size_t c = 0; c < 16 && row * 16 + c < plan.raw.size(); ++c) {
      const RawPermutation& raw = plan.raw[row * 16 + c];
      char cell[16];
      if (raw.pruned)
        std::snprintf(cell, sizeof cell, "  --");
      else
        std::snprintf(cell, sizeof cell, " %3u", raw.optimised);
      out << cell;
    }
    out << '\n';
  }
}

// A listed domain's table: one row per listed raw ID (a grid of 2^32 cells would mean nothing).
void lut_rows(std::ostringstream& out, const DomainSpec& spec, const PermutationPlan& plan) {
  out << "\n\nOne row per listed raw ID (IDs not listed are not built).\n\n"
      << (spec.collapsed ? "      raw ID  optimised ID  features\n" : "      raw ID  features\n");
  for (const RawPermutation& raw : plan.raw) {
    char head[48];
    if (spec.collapsed)
      std::snprintf(head, sizeof head, "%12u  %12u  ", raw.id, raw.optimised);
    else
      std::snprintf(head, sizeof head, "%12u  ", raw.id);
    out << head << describe_raw(spec, raw.id) << '\n';
  }
}

std::string joined_defines(const std::vector<std::string>& defines) {
  std::string text;
  for (const std::string& d : defines) text += (text.empty() ? "" : " ") + d;
  return text.empty() ? "(no defines)" : text;
}

}  // namespace

std::string format_lut(const DomainSpec& spec, const PermutationPlan& plan) {
  std::ostringstream out;
  lut_heading(out, spec, plan);
  if (spec.listed())
    lut_rows(out, spec, plan);
  else
    lut_grid(out, spec, plan);
  if (!spec.collapsed) return out.str();
  out << "\noptimised ID  raw IDs mapped  compiled with\n";
  for (const OptimisedPermutation& o : plan.optimised) {
    char line[64];
    std::snprintf(line, sizeof line, "%12u  %14u  ", o.id, o.raw_mapped);
    out << line << joined_defines(o.defines) << '\n';
  }
  return out.str();
}

std::string format_list(const DomainSpec& spec, const PermutationPlan& plan) {
  std::ostringstream out;
  std::size_t pruned = 0;
  for (const RawPermutation& raw : plan.raw) pruned += raw.pruned;
  out << "raw permutations: " << plan.raw.size() << " (" << pruned << " pruned, " << plan.raw.size() - pruned
      << " compiled";
  if (spec.listed())
    out << "; the ones " << spec.variants_path.string() << " lists, of " << spec.raw_space() << " raw IDs";
  out << ")\n";
  for (const RawPermutation& raw : plan.raw) {
    char head[64];
    if (spec.collapsed)
      std::snprintf(head, sizeof head, "  raw %4u -> optimised %3u  %s  ", raw.id, raw.optimised,
                    raw.pruned ? "pruned  " : "compiled");
    else
      std::snprintf(head, sizeof head, "  raw %4u  %s  ", raw.id, raw.pruned ? "pruned  " : "compiled");
    out << head << joined_defines(raw_defines(spec, raw.id)) << '\n';
  }
  if (!spec.collapsed) return out.str() + "optimised permutations: none (not collapsed)\n";
  out << "optimised permutations: " << plan.optimised.size() << '\n';
  for (const OptimisedPermutation& o : plan.optimised) {
    char head[64];
    std::snprintf(head, sizeof head, "  optimised %3u  same source as raw %4u  ", o.id, o.raw_equivalent);
    out << head << joined_defines(o.defines) << '\n';
  }
  return out.str();
}

std::string format_explanation(const DomainSpec& spec, const PermutationPlan& plan, std::uint32_t raw_id) {
  std::ostringstream out;
  auto optimised_names = spec.optimised_bit_names();
  const RawPermutation* held = plan.find_raw(raw_id);
  const RawPermutation raw = held ? *held : classify(spec, raw_id);
  out << "raw ID " << raw_id << " = " << describe_raw(spec, raw_id) << "\n";
  for (const RawFeature& f : spec.raw_features) {
    std::uint32_t index = f.index_in(raw_id);
    if (!f.valued()) {
      out << "  bit " << f.bit << "  " << (index ? "[x] " : "[ ] ") << f.name << " (#define " << f.define << ")";
    } else {
      out << "  bits " << bit_span(f) << "  " << f.name << " = "
          << (index < f.values.size() ? f.values[index] + " (#define " + f.define + " " + f.values[index] + ")"
                                      : "? (index " + std::to_string(index) + " holds no value)")
          << "; values: " << value_list(f);
    }
    if (!f.description.empty()) out << " - " << f.description;
    out << '\n';
  }
  if (raw.pruned && raw.pruned_by < 0) {
    const RawFeature& f = spec.raw_features[static_cast<std::size_t>(raw.unvalued)];
    out << "\npruned: bits " << bit_span(f) << " hold index " << f.index_in(raw_id) << ", but " << f.name << " has "
        << f.values.size() << " values; no shader is compiled for it.\n";
    return out.str();
  }
  if (raw.pruned) {
    const ImpossibleSet& rule = spec.impossible[static_cast<std::size_t>(raw.pruned_by)];
    out << "\npruned: it matches the impossible rule \"" << rule.when.text << "\"";
    if (!rule.why.empty()) out << " (" << rule.why << ")";
    out << "; no shader is compiled for it.";
    if (spec.collapsed) out << " The rules would still map it to optimised ID " << raw.optimised << ".";
    out << "\n";
    return out.str();
  }
  const std::vector<std::string> defines = raw_defines(spec, raw_id);
  if (!held)
    out << "\nnot built: " << spec.variants_path.string() << " does not list it; the lookups say \"none\" for it.\n";
  out << (held ? "\ncompiled with: " : "would be compiled with: ");
  for (const std::string& d : defines) out << d << ' ';
  if (defines.empty()) out << "(no defines)";
  if (!spec.collapsed) {
    out << "\n\nnot collapsed: raw ID " << raw_id << " is its own permutation\n";
    return out.str();
  }
  if (spec.ignore_form()) {
    out << "\n\nignored:\n";
    for (const IgnoreRule& rule : spec.ignored) {
      bool value = rule.when.expression.evaluate(raw_id);
      out << "  " << (value ? "[x] " : "[ ] ") << spec.raw_features[rule.feature].name << "  because "
          << (value ? "" : "not ") << "(" << rule.when.expression.to_string() << ")\n";
    }
    out << "\n-> optimised ID " << raw.optimised;
  } else {
    out << "\n\noptimised bits:\n";
    for (const OptimisedBit& bit : spec.optimised_bits) {
      bool value = bit.when.expression.evaluate(raw_id);
      out << "  bit " << bit.bit << "  " << (value ? "[x] " : "[ ] ") << bit.name << "  because "
          << (value ? "" : "not ") << "(" << bit.when.expression.to_string() << ")\n";
    }
    out << "\n-> optimised ID " << raw.optimised << " = " << describe_bits(optimised_names, raw.optimised);
  }
  const OptimisedPermutation* built = plan.find_optimised(raw.optimised);
  if (!built) {
    out << "\n   not built: no listed raw ID maps to it\n";
    return out.str();
  }
  const OptimisedPermutation& o = *built;
  out << "\n   compiled with: ";
  for (const std::string& d : o.defines) out << d << ' ';
  if (o.defines.empty()) out << "(no defines)";
  out << "\n   (" << o.raw_mapped << (o.raw_mapped == 1 ? " raw ID uses" : " raw IDs share") << " this shader)\n";
  return out.str();
}

}  // namespace shadergen
