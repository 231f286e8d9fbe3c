#include "cache/source_key.h"

namespace shadergen {
namespace {

bool is_blank(std::string_view line) { return line.find_first_not_of(" \t\r\f\v") == std::string_view::npos; }

bool is_line_directive(std::string_view line) {
  std::size_t start = line.find_first_not_of(" \t");
  if (start == std::string_view::npos || line[start] != '#') return false;
  std::size_t word = line.find_first_not_of(" \t", start + 1);
  return word != std::string_view::npos && line.substr(word, 4) == "line" &&
         (word + 4 == line.size() || line[word + 4] == ' ' || line[word + 4] == '\t');
}

}  // namespace

std::string key_text(std::string_view preprocessed) {
  std::string out;
  out.reserve(preprocessed.size());
  while (!preprocessed.empty()) {
    std::size_t end = preprocessed.find('\n');
    std::string_view line = preprocessed.substr(0, end);
    if (!is_blank(line) && !is_line_directive(line)) {
      out += line;
      out += '\n';
    }
    preprocessed.remove_prefix(end == std::string_view::npos ? preprocessed.size() : end + 1);
  }
  return out;
}

}  // namespace shadergen
