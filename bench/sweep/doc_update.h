#pragma once
// Refreshes the sweep's tables inside a markdown document (docs/results.md), so a re-run
// updates the page without pasting: each table sits between two marker lines,
//   <!-- sweep:<id> -->
//   ...replaced...
//   <!-- /sweep:<id> -->
// (markdown renderers show neither). Text outside the markers is kept byte for byte.

#include <map>
#include <string>

namespace tilelight::sweep {

// Returns `document` with the lines between each pair of markers replaced by `sections[id]`
// (a trailing newline is added if it lacks one). Every id in `sections` must have its pair of
// markers; markers for ids not in `sections` are left alone. Throws tilelight::Error:
//   "<name>: no '<!-- sweep:<id> -->' line" / "<name>: no '<!-- /sweep:<id> -->' line after
//   '<!-- sweep:<id> -->'"
std::string replace_marked_sections(const std::string& document, const std::map<std::string, std::string>& sections,
                                    const std::string& name);

}  // namespace tilelight::sweep
