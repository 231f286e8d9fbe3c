// command_line/command_line.h - what shadergen's and tilelight's command lines share: the exit
// codes both promise in the README, and the one way a CLI11 parse becomes an exit code.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace command_line {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitError = 1;          // the input or the work failed; the message says why
inline constexpr int kExitUsage = 2;          // the command line itself is wrong (CLI11's own codes vary by error kind)
inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as shells report it

// Parses `args` (without the program name, in order) into `app`. nullopt: parsed, go on.
// Otherwise the exit code to return at once: kExitSuccess after --help or --version (printed on
// `out`), kExitUsage after any other parse error (its message printed on `err`).
inline std::optional<int> parse(CLI::App& app, const std::vector<std::string>& args, std::ostream& out,
                                std::ostream& err) {
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 consumes from the back
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    return app.exit(e, out, err) == 0 ? kExitSuccess : kExitUsage;
  }
  return std::nullopt;
}

}  // namespace command_line
