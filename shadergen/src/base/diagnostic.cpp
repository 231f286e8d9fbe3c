#include "shadergen/diagnostic.h"

namespace shadergen {

std::string Diagnostic::to_string() const {
  std::string text;
  if (!file.empty()) {
    text += file;
    if (line > 0) {
      text += ':' + std::to_string(line);
      if (column > 0) text += ':' + std::to_string(column);
    }
    text += ": ";
  }
  switch (severity) {
    case Severity::error: text += "error: "; break;
    case Severity::warning: text += "warning: "; break;
    case Severity::note: text += "note: "; break;
  }
  text += message;
  return text;
}

Diagnostic make_error(std::string file, int line, std::string message) {
  return Diagnostic{Severity::error, std::move(file), line, 0, std::move(message)};
}

Diagnostic make_error(std::string message) { return Diagnostic{Severity::error, {}, 0, 0, std::move(message)}; }

}  // namespace shadergen
