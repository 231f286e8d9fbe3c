#include "shadergen/cli.h"

#include <command_line/command_line.h>
#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <iostream>
#include <new>
#include <optional>

#include "cli/build_command.h"
#include "cli/suggest.h"
#include "cli/version.h"
#include "cli/view_commands.h"

namespace shadergen {
namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_signal(int) { g_interrupted.store(true); }

int run_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"shadergen " SHADERGEN_VERSION
               " - compiles an uber-shader and a permutation-domain spec into every permutation as validated "
               "SPIR-V, a manifest and generated C++ (lookup table + registry).",
               "shadergen"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text());
  BuildCommandLine build_line;
  CLI::App* build_command = add_build_command(app, build_line);
  ViewArgs view_args;
  const ViewCommands view_commands = add_view_commands(app, view_args);

  if (auto problem = misspelt_name(app, args)) {
    err << "shadergen: error: " << *problem << '\n';
    return command_line::kExitUsage;
  }
  if (auto exit_code = command_line::parse(app, args, out, err)) return *exit_code;
  if (*build_command) return run_build(build_line, g_interrupted, out, err);
  return run_view(view_commands, view_args, out, err);
}

}  // namespace

// The library reports what it expects as diagnostics; what is left is the unexpected (out of
// memory in a compile job, a failed thread start), which still deserves a message and exit 1
// rather than std::terminate. The output folder is only replaced at the very end of a build, so
// it is left as it was.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    return run_command(args, out, err);
  } catch (const std::bad_alloc&) {
    err << "shadergen: error: out of memory\n";
  } catch (const std::exception& e) {
    err << "shadergen: error: " << e.what() << '\n';
  }
  return command_line::kExitError;
}

int run_cli(int argc, char** argv) {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::vector<std::string> args(argv + 1, argv + argc);
  return run_cli(args, std::cout, std::cerr);
}

}  // namespace shadergen
