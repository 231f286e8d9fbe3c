#include "doc_update.h"

#include "tilelight/base/error.h"

namespace tilelight::sweep {
namespace {

// Offset just past the end of the line that is exactly `line`, searching from `from`, or npos.
std::size_t after_line(const std::string& text, const std::string& line, std::size_t from) {
  for (std::size_t at = text.find(line, from); at != std::string::npos; at = text.find(line, at + 1)) {
    const bool starts_line = at == 0 || text[at - 1] == '\n';
    const std::size_t end = at + line.size();
    if (starts_line && (end == text.size() || text[end] == '\n')) return end == text.size() ? end : end + 1;
  }
  return std::string::npos;
}

}  // namespace

std::string replace_marked_sections(const std::string& document, const std::map<std::string, std::string>& sections,
                                    const std::string& name) {
  std::string out = document;
  for (const auto& [id, content] : sections) {
    const std::string open = "<!-- sweep:" + id + " -->";
    const std::string close = "<!-- /sweep:" + id + " -->";
    const std::size_t begin = after_line(out, open, 0);
    if (begin == std::string::npos) throw Error(name + ": no '" + open + "' line");
    const std::size_t close_end = after_line(out, close, begin);
    if (close_end == std::string::npos) throw Error(name + ": no '" + close + "' line after '" + open + "'");
    const std::size_t end = out.rfind(close, close_end);  // start of the closing line
    std::string replacement = content;
    if (!replacement.empty() && replacement.back() != '\n') replacement += '\n';
    out.replace(begin, end - begin, replacement);
  }
  return out;
}

}  // namespace tilelight::sweep
