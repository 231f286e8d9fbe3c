#include "shadergen/permutations.h"

#include <cstdio>
#include <sstream>

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

namespace {

// Boolean features set: "DEFINE"; valued features: "DEFINE=value" (none when the field holds
// no value, which only pruned IDs do).
std::vector<std::string> defines_for(const DomainSpec& spec, std::uint32_t raw_bits) {
  std::vector<std::string> defines;
  for (const RawFeature& feature : spec.raw_features) {
    std::uint32_t index = feature.index_in(raw_bits);
    if (!feature.valued() && index) defines.push_back(feature.define);
    if (feature.valued() && index < feature.values.size())
      defines.push_back(feature.define + "=" + feature.values[index]);
  }
  return defines;
}

int first_unvalued_feature(const DomainSpec& spec, std::uint32_t raw_id) {
  for (std::size_t i = 0; i < spec.raw_features.size(); ++i) {
    const RawFeature& f = spec.raw_features[i];
    if (f.valued() && f.index_in(raw_id) >= f.values.size()) return static_cast<int>(i);
  }
  return -1;
}

int first_impossible_rule(const DomainSpec& spec, std::uint32_t raw_id) {
  for (std::size_t i = 0; i < spec.impossible.size(); ++i)
    if (spec.impossible[i].when.expression.evaluate(raw_id)) return static_cast<int>(i);
  return -1;
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

}  // namespace

Result<PermutationPlan> expand(const DomainSpec& spec) {
  PermutationPlan plan;
  for (std::uint32_t id = 0; id < spec.raw_count(); ++id) {
    RawPermutation raw;
    raw.id = id;
    raw.defines = defines_for(spec, id);
    raw.pruned_by = first_impossible_rule(spec, id);
    raw.unvalued = first_unvalued_feature(spec, id);
    raw.pruned = raw.pruned_by >= 0 || raw.unvalued >= 0;
    raw.optimised = spec.collapsed ? apply_rules(spec, id) : id;
    plan.raw.push_back(std::move(raw));
  }
  Diagnostics errors;
  auto optimised_names = spec.optimised_bit_names();
  for (std::uint32_t id = 0; id < spec.optimised_count(); ++id) {
    OptimisedPermutation optimised;
    optimised.id = id;
    std::uint32_t conflict = 0;
    optimised.raw_equivalent = raw_features_for_optimised(spec, id, conflict);
    optimised.defines = defines_for(spec, optimised.raw_equivalent);
    if (conflict) {
      std::string names;
      for (const RawFeature& f : spec.raw_features)
        if (f.mask() & conflict) names += (names.empty() ? "" : ", ") + f.name;
      errors.push_back(make_error(spec.spec_path.string(), 0,
                                  "optimised ID " + std::to_string(id) + " (" + describe_bits(optimised_names, id) +
                                      ") matches variants that give " + names + " different values"));
    } else if (plan.raw[optimised.raw_equivalent].pruned_by >= 0) {
      const ImpossibleSet& rule =
          spec.impossible[static_cast<std::size_t>(plan.raw[optimised.raw_equivalent].pruned_by)];
      errors.push_back(make_error(spec.spec_path.string(), rule.when.line,
                                  "optimised ID " + std::to_string(id) + " (" + describe_bits(optimised_names, id) +
                                      ") is compiled with raw features " +
                                      describe_raw(spec, optimised.raw_equivalent) + ", which the impossible rule \"" +
                                      rule.when.text + "\" prunes"));
    }
    plan.optimised.push_back(std::move(optimised));
  }
  if (spec.collapsed)
    for (const RawPermutation& raw : plan.raw)
      if (!raw.pruned) ++plan.optimised[raw.optimised].raw_mapped;
  if (!errors.empty()) return errors;
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

std::string format_lut(const DomainSpec& spec, const PermutationPlan& plan) {
  std::ostringstream out;
  auto optimised_names = spec.optimised_bit_names();
  if (spec.collapsed)
    out << "Domain " << spec.name << ": " << spec.raw_count() << " raw IDs -> " << spec.optimised_count()
        << " optimised IDs\n\nraw bits:       " << raw_bit_legend(spec) << "\noptimised bits: ";
  else
    out << "Domain " << spec.name << ": " << spec.raw_count()
        << " raw IDs, not collapsed (no \"optimised\" section): every compiled raw ID is its own permutation\n\n"
           "raw bits:       "
        << raw_bit_legend(spec);
  for (std::size_t i = 0; i < optimised_names.size(); ++i) out << (i ? ", " : "") << i << "=" << optimised_names[i];
  out << "\n\nRow = raw ID / 16, column = raw ID % 16; each cell is the "
      << (spec.collapsed ? "optimised ID" : "permutation (the raw ID itself)") << ", '--' = pruned.\n\n      ";
  for (int c = 0; c < 16; ++c) {
    char cell[8];
    std::snprintf(cell, sizeof cell, " %3d", c);
    out << cell;
  }
  out << '\n';
  for (std::uint32_t row = 0; row * 16 < spec.raw_count(); ++row) {
    char label[16];
    std::snprintf(label, sizeof label, "%4u: ", row * 16);
    out << label;
    for (std::uint32_t c = 0; c < 16 && row * 16 + c < spec.raw_count(); ++c) {
      const RawPermutation& raw = plan.raw[row * 16 + c];
      char cell[8];
      if (raw.pruned)
        std::snprintf(cell, sizeof cell, "  --");
      else
        std::snprintf(cell, sizeof cell, " %3u", raw.optimised);
      out << cell;
    }
    out << '\n';
  }
  if (!spec.collapsed) return out.str();
  out << "\noptimised ID  raw IDs mapped  compiled with\n";
  for (const OptimisedPermutation& o : plan.optimised) {
    char line[64];
    std::snprintf(line, sizeof line, "%12u  %14u  ", o.id, o.raw_mapped);
    std::string defines;
    for (const std::string& d : o.defines) defines += (defines.empty() ? "" : " ") + d;
    out << line << (defines.empty() ? "(no defines)" : defines) << '\n';
  }
  return out.str();
}

std::string format_list(const DomainSpec& spec, const PermutationPlan& plan) {
  std::ostringstream out;
  std::size_t pruned = 0;
  for (const RawPermutation& raw : plan.raw) pruned += raw.pruned;
  out << "raw permutations: " << plan.raw.size() << " (" << pruned << " pruned, " << plan.raw.size() - pruned
      << " compiled)\n";
  for (const RawPermutation& raw : plan.raw) {
    char head[64];
    if (spec.collapsed)
      std::snprintf(head, sizeof head, "  raw %4u -> optimised %3u  %s  ", raw.id, raw.optimised,
                    raw.pruned ? "pruned  " : "compiled");
    else
      std::snprintf(head, sizeof head, "  raw %4u  %s  ", raw.id, raw.pruned ? "pruned  " : "compiled");
    std::string defines;
    for (const std::string& d : raw.defines) defines += (defines.empty() ? "" : " ") + d;
    out << head << (defines.empty() ? "(no defines)" : defines) << '\n';
  }
  if (!spec.collapsed) return out.str() + "optimised permutations: none (not collapsed)\n";
  out << "optimised permutations: " << plan.optimised.size() << '\n';
  for (const OptimisedPermutation& o : plan.optimised) {
    char head[64];
    std::snprintf(head, sizeof head, "  optimised %3u  same source as raw %4u  ", o.id, o.raw_equivalent);
    std::string defines;
    for (const std::string& d : o.defines) defines += (defines.empty() ? "" : " ") + d;
    out << head << (defines.empty() ? "(no defines)" : defines) << '\n';
  }
  return out.str();
}

std::string format_explanation(const DomainSpec& spec, const PermutationPlan& plan, std::uint32_t raw_id) {
  std::ostringstream out;
  auto optimised_names = spec.optimised_bit_names();
  const RawPermutation& raw = plan.raw[raw_id];
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
  out << "\ncompiled with: ";
  for (const std::string& d : raw.defines) out << d << ' ';
  if (raw.defines.empty()) out << "(no defines)";
  if (!spec.collapsed) {
    out << "\n\nnot collapsed: raw ID " << raw_id << " is its own permutation\n";
    return out.str();
  }
  out << "\n\noptimised bits:\n";
  for (const OptimisedBit& bit : spec.optimised_bits) {
    bool value = bit.when.expression.evaluate(raw_id);
    out << "  bit " << bit.bit << "  " << (value ? "[x] " : "[ ] ") << bit.name << "  because " << (value ? "" : "not ")
        << "(" << bit.when.expression.to_string() << ")\n";
  }
  const OptimisedPermutation& o = plan.optimised[raw.optimised];
  out << "\n-> optimised ID " << raw.optimised << " = " << describe_bits(optimised_names, raw.optimised)
      << "\n   compiled with: ";
  for (const std::string& d : o.defines) out << d << ' ';
  if (o.defines.empty()) out << "(no defines)";
  out << "\n   (" << o.raw_mapped << (o.raw_mapped == 1 ? " raw ID uses" : " raw IDs share") << " this shader)\n";
  return out.str();
}

}  // namespace shadergen
