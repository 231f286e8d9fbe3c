#include "error_grouping.h"

#include <algorithm>
#include <map>
#include <set>

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

std::string describe_job(const CompileJob& job) {
    std::string text = job.label();
    if (job.kind != JobKind::companion)
        text += job.defines.empty() ? " (no defines)" : " with " + join(job.defines, " ");
    return text;
}

bool has_all(const CompileJob& job, const std::set<std::string>& defines) {
    return std::all_of(defines.begin(), defines.end(), [&](const std::string& d) {
        return std::find(job.defines.begin(), job.defines.end(), d) != job.defines.end();
    });
}

// "those with SOFT_SHADOW" when the failing raw permutations are exactly the ones with a set
// of defines; otherwise nothing (the example permutation still names one).
std::string pattern(const std::vector<CompileJob>& jobs, const std::set<std::size_t>& failing_raw) {
    if (failing_raw.empty()) return {};
    std::set<std::string> common(jobs[*failing_raw.begin()].defines.begin(), jobs[*failing_raw.begin()].defines.end());
    for (std::size_t index : failing_raw) {
        std::set<std::string> mine(jobs[index].defines.begin(), jobs[index].defines.end());
        std::set<std::string> kept;
        std::set_intersection(common.begin(), common.end(), mine.begin(), mine.end(), std::inserter(kept, kept.end()));
        common = std::move(kept);
    }
    for (std::size_t i = 0; i < jobs.size(); ++i)
        if (jobs[i].kind == JobKind::raw && has_all(jobs[i], common) && !failing_raw.count(i)) return {};
    if (common.empty()) return "all of them";
    return "those with " + join(std::vector<std::string>(common.begin(), common.end()), " and ");
}

std::string where_it_occurs(const std::vector<CompileJob>& jobs, const std::set<std::size_t>& failing) {
    std::size_t raw_total = 0, optimised_total = 0;
    for (const CompileJob& job : jobs) {
        raw_total += job.kind == JobKind::raw;
        optimised_total += job.kind == JobKind::optimised;
    }
    std::set<std::size_t> raw, optimised;
    std::vector<std::string> companions;
    for (std::size_t index : failing) {
        if (jobs[index].kind == JobKind::raw) raw.insert(index);
        if (jobs[index].kind == JobKind::optimised) optimised.insert(index);
        if (jobs[index].kind == JobKind::companion) companions.push_back(jobs[index].label());
    }
    std::vector<std::string> parts;
    if (!raw.empty()) {
        std::string text = std::to_string(raw.size()) + " of " + std::to_string(raw_total) + " raw permutations";
        if (std::string p = pattern(jobs, raw); !p.empty()) text += ": " + p;
        parts.push_back(text);
    }
    if (!optimised.empty())
        parts.push_back(std::to_string(optimised.size()) + " of " + std::to_string(optimised_total) +
                        " optimised permutations");
    for (const std::string& c : companions) parts.push_back(c);
    const CompileJob& example = jobs[*failing.begin()];
    return "in " + join(parts, "; ") + (failing.size() > 1 || example.kind != JobKind::companion
                                             ? "; e.g. " + describe_job(example)
                                             : "");
}

}  // namespace

Diagnostics group_failures(const std::vector<CompileJob>& jobs, const std::vector<JobFailure>& failures) {
    // Key on the whole located message so the same error at the same line groups together.
    std::map<std::string, std::pair<Diagnostic, std::set<std::size_t>>> groups;
    std::vector<std::string> order;
    for (const JobFailure& failure : failures) {
        for (const Diagnostic& error : failure.errors) {
            std::string key = error.to_string();
            auto [it, fresh] = groups.try_emplace(key, error, std::set<std::size_t>{});
            if (fresh) order.push_back(key);
            it->second.second.insert(failure.job);
        }
    }
    // Report in source order (file, then line) so the first error printed comes first in the file.
    std::sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) {
        const Diagnostic& x = groups.at(a).first;
        const Diagnostic& y = groups.at(b).first;
        return std::tie(x.file, x.line, x.message) < std::tie(y.file, y.line, y.message);
    });
    Diagnostics out;
    for (const std::string& key : order) {
        auto& [error, failing] = groups.at(key);
        Diagnostic grouped = error;
        grouped.message += " (" + where_it_occurs(jobs, failing) + ")";
        out.push_back(std::move(grouped));
    }
    return out;
}

}  // namespace shadergen
