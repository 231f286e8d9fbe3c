#include "base/closest_name.h"

#include <algorithm>
#include <vector>

namespace shadergen {
namespace {

// Optimal string alignment distance: edits, a swap of neighbours counting as one, so "biuld"
// is one edit from "build".
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

bool extends(std::string_view longer, std::string_view shorter) {
  // "--" alone is no shared stem: "--x" does not extend to every option.
  std::size_t stem = shorter.size() - (shorter.rfind("--", 0) == 0 ? 2 : 0);
  return stem >= 2 && longer.size() > shorter.size() && longer.substr(0, shorter.size()) == shorter;
}

}  // namespace

std::optional<std::string> closest_name(std::string_view given, const std::vector<std::string>& known) {
  std::optional<std::string> best;
  std::size_t best_distance = 3;
  bool tie = false;
  for (const std::string& name : known) {
    std::size_t distance = extends(given, name) || extends(name, given) ? 1 : edit_distance(given, name);
    if (distance < best_distance) {
      best = name, best_distance = distance, tie = false;
    } else if (distance == best_distance && best) {
      tie = true;
    }
  }
  return tie ? std::nullopt : best;
}

}  // namespace shadergen
