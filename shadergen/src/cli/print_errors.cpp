#include "cli/print_errors.h"

#include <command_line/command_line.h>

namespace shadergen {

int print_errors(const Diagnostics& errors, std::ostream& err) {
  for (const Diagnostic& d : errors) err << (d.file.empty() ? "shadergen: " : "") << d.to_string() << '\n';
  return command_line::kExitError;
}

}  // namespace shadergen
