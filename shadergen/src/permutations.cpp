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

namespace {

std::vector<std::string> defines_for(const DomainSpec& spec, std::uint32_t raw_bits) {
    std::vector<std::string> defines;
    for (const RawFeature& feature : spec.raw_features)
        if (raw_bits & (1u << feature.bit)) defines.push_back(feature.define);
    return defines;
}

int first_impossible_rule(const DomainSpec& spec, std::uint32_t raw_id) {
    for (std::size_t i = 0; i < spec.impossible.size(); ++i)
        if (spec.impossible[i].when.expression.evaluate(raw_id)) return static_cast<int>(i);
    return -1;
}

// The raw features an optimised ID is compiled with: the union over matching variants.
std::uint32_t raw_features_for_optimised(const DomainSpec& spec, std::uint32_t optimised_id) {
    std::uint32_t raw_bits = 0;
    for (const OptimisedVariant& variant : spec.variants)
        if (variant.when.expression.evaluate(optimised_id))
            for (std::uint32_t bit : variant.raw_features) raw_bits |= 1u << bit;
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
        raw.pruned = raw.pruned_by >= 0;
        raw.optimised = apply_rules(spec, id);
        plan.raw.push_back(std::move(raw));
    }
    Diagnostics errors;
    auto raw_names = spec.raw_feature_names();
    auto optimised_names = spec.optimised_bit_names();
    for (std::uint32_t id = 0; id < spec.optimised_count(); ++id) {
        OptimisedPermutation optimised;
        optimised.id = id;
        optimised.raw_equivalent = raw_features_for_optimised(spec, id);
        optimised.defines = defines_for(spec, optimised.raw_equivalent);
        if (plan.raw[optimised.raw_equivalent].pruned) {
            const ImpossibleSet& rule = spec.impossible[static_cast<std::size_t>(plan.raw[optimised.raw_equivalent].pruned_by)];
            errors.push_back(make_error(spec.spec_path.string(), rule.when.line,
                                        "optimised ID " + std::to_string(id) + " (" + describe_bits(optimised_names, id) +
                                            ") is compiled with raw features " +
                                            describe_bits(raw_names, optimised.raw_equivalent) +
                                            ", which the impossible rule \"" + rule.when.text + "\" prunes"));
        }
        plan.optimised.push_back(std::move(optimised));
    }
    for (const RawPermutation& raw : plan.raw)
        if (!raw.pruned) ++plan.optimised[raw.optimised].raw_mapped;
    if (!errors.empty()) return errors;
    return plan;
}

std::string format_lut(const DomainSpec& spec, const PermutationPlan& plan) {
    std::ostringstream out;
    auto raw_names = spec.raw_feature_names();
    auto optimised_names = spec.optimised_bit_names();
    out << "Domain " << spec.name << ": " << spec.raw_count() << " raw IDs -> " << spec.optimised_count()
        << " optimised IDs\n\nraw bits:       ";
    for (std::size_t i = 0; i < raw_names.size(); ++i) out << (i ? ", " : "") << i << "=" << raw_names[i];
    out << "\noptimised bits: ";
    for (std::size_t i = 0; i < optimised_names.size(); ++i) out << (i ? ", " : "") << i << "=" << optimised_names[i];
    out << "\n\nRow = raw ID / 16, column = raw ID % 16; each cell is the optimised ID, '--' = pruned.\n\n      ";
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
            if (raw.pruned) std::snprintf(cell, sizeof cell, "  --");
            else std::snprintf(cell, sizeof cell, " %3u", raw.optimised);
            out << cell;
        }
        out << '\n';
    }
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
        std::snprintf(head, sizeof head, "  raw %4u -> optimised %3u  %s  ", raw.id, raw.optimised,
                      raw.pruned ? "pruned  " : "compiled");
        std::string defines;
        for (const std::string& d : raw.defines) defines += (defines.empty() ? "" : " ") + d;
        out << head << (defines.empty() ? "(no defines)" : defines) << '\n';
    }
    out << "optimised permutations: " << plan.optimised.size() << '\n';
    for (const OptimisedPermutation& o : plan.optimised) {
        char head[64];
        std::snprintf(head, sizeof head, "  optimised %3u  same source as raw %4u  ", o.id, o.raw_equivalent);
        std::string defines;
        for (const std::string& d : o.defines) defines += (defines.empty() ? "" : " ") + d;
        out << head << (defines.empty() ? "(no defines)" : defines) << '\n';
    }
    (void)spec;
    return out.str();
}

std::string format_explanation(const DomainSpec& spec, const PermutationPlan& plan, std::uint32_t raw_id) {
    std::ostringstream out;
    auto raw_names = spec.raw_feature_names();
    auto optimised_names = spec.optimised_bit_names();
    const RawPermutation& raw = plan.raw[raw_id];
    out << "raw ID " << raw_id << " = " << describe_bits(raw_names, raw_id) << "\n";
    for (const RawFeature& f : spec.raw_features) {
        bool set = raw_id & (1u << f.bit);
        out << "  bit " << f.bit << "  " << (set ? "[x] " : "[ ] ") << f.name << " (#define " << f.define << ")";
        if (!f.description.empty()) out << " - " << f.description;
        out << '\n';
    }
    if (raw.pruned) {
        const ImpossibleSet& rule = spec.impossible[static_cast<std::size_t>(raw.pruned_by)];
        out << "\npruned: it matches the impossible rule \"" << rule.when.text << "\"";
        if (!rule.why.empty()) out << " (" << rule.why << ")";
        out << "; no shader is compiled for it. The rules would still map it to optimised ID " << raw.optimised
            << ".\n";
        return out.str();
    }
    out << "\ncompiled with: ";
    for (const std::string& d : raw.defines) out << d << ' ';
    if (raw.defines.empty()) out << "(no defines)";
    out << "\n\noptimised bits:\n";
    for (const OptimisedBit& bit : spec.optimised_bits) {
        bool value = bit.when.expression.evaluate(raw_id);
        out << "  bit " << bit.bit << "  " << (value ? "[x] " : "[ ] ") << bit.name << "  because "
            << (value ? "" : "not ") << "(" << bit.when.expression.to_string(raw_names) << ")\n";
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
