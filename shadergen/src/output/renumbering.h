// renumbering.h - whether a build gives raw IDs other optimised IDs than the output it replaces.
//
// The collapse is over variant features only, so turning a variant into a specialization
// constant or a branch (or back) can renumber the optimised IDs; so can an edit of the optimised
// rules. Anything keyed by optimised ID (a pipeline cache on disk) then points at other shaders,
// and nothing fails: the build summary says so instead (docs/cli.md, "shadergen build").
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "shadergen/domain.h"
#include "shadergen/permutations.h"

namespace shadergen {

// What the manifest of the previous output says about the numbering.
struct PreviousNumbering {
  std::map<std::string, std::string> kinds;                    // feature name -> "variant", ...
  std::vector<std::pair<std::uint32_t, std::uint32_t>> table;  // raw ID -> optimised ID, as listed
};

// Read from the manifest at `manifest_path`, only up to the end of its "raw" array (its blobs
// after it are not read). Empty when there is none, it cannot be read, or it is not collapsed.
PreviousNumbering previous_numbering(const std::filesystem::path& manifest_path);

struct Renumbering {
  std::uint32_t raw_ids = 0;          // raw IDs in both builds whose optimised ID changed
  std::vector<std::string> features;  // "SOFT (variant -> specialization)", in spec order
};

// How `plan` renumbers what `previous` recorded; raw_ids 0 when nothing changed (or the domain is
// not collapsed: there the optimised ID of a raw ID is the raw ID itself). `features` names the
// features that moved between variant and another kind, the usual cause.
Renumbering renumbering(const PreviousNumbering& previous, const DomainSpec& spec, const PermutationPlan& plan);

}  // namespace shadergen
