// print_errors.h - how the command line prints a library's diagnostics.
#pragma once

#include <ostream>

#include "shadergen/diagnostic.h"

namespace shadergen {

// One line per diagnostic on `err` ("file:line: error: ..."; "shadergen: error: ..." when it
// names no file). Returns command_line::kExitError, so a command can `return print_errors(...)`.
int print_errors(const Diagnostics& errors, std::ostream& err);

}  // namespace shadergen
