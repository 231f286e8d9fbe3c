// shadergen/cli.h - the command line, as a library function so tests can run it in process.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace shadergen {

// Runs `shadergen <args...>` (args excludes the program name), printing results on `out` and
// diagnostics and progress on `err`. Returns the process exit code: 0 success, 1 a build or
// input error, 2 bad usage, 130 interrupted. It does not throw: an unexpected exception (out of
// memory included) is printed as "shadergen: error: ..." and gives 1.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// main(): installs SIGINT/SIGTERM handlers that stop a build cleanly, then runs the above.
int run_cli(int argc, char** argv);

}  // namespace shadergen
