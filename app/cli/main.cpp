// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli: the headless front end. Subcommands register themselves (command.h); this file only dispatches.
#include <iostream>
#include <string>
#include <vector>

#include "common/args.h"
#include "common/command.h"

namespace {

void print_usage(std::ostream& out) {
  out << "usage: benchscope-cli <command> [arguments]\n\ncommands:\n";
  for (const auto& c : bs::cli::commands()) {
    out << "  " << c.name << std::string(c.name.size() < 12 ? 12 - c.name.size() : 1, ' ') << c.summary << '\n';
  }
  out << "\n`benchscope-cli <command> --help` shows a command's usage; `benchscope-cli --version` the version;\n"
         "`benchscope-cli completion bash` a bash completion script.\n";
}

const bs::cli::CommandRegistrar help_command({
    "help",
    "show the commands, or one command's usage",
    "usage: benchscope-cli help [COMMAND]",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      if (args.empty()) {
        print_usage(out);
        return 0;
      }
      if (const auto* c = bs::cli::find_command(args[0])) {
        out << c->usage << '\n';
        return 0;
      }
      err << "benchscope-cli: error: unknown command '" << args[0] << "'\n";
      return 2;
    },
});

// `COMMAND --help` / `COMMAND -h` anywhere before a "--" asks for that command's usage.
bool asks_for_help(const std::vector<std::string>& args) {
  for (const std::string& a : args) {
    if (a == "--") return false;
    if (a == "--help" || a == "-h") return true;
  }
  return false;
}

// The first line of a command's usage ("usage: benchscope-cli import WORKSPACE PATH... [--keep-going] ...").
std::string usage_line(const bs::cli::Command& c) { return c.usage.substr(0, c.usage.find('\n')); }

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_usage(std::cerr);
    return 2;
  }
  if (args[0] == "--version" || args[0] == "version") {
    std::cout << "benchscope-cli " << BENCHSCOPE_VERSION << '\n';
    return 0;
  }
  if (args[0] == "--help" || args[0] == "-h") args[0] = "help";
  const auto* command = bs::cli::find_command(args[0]);
  if (!command) {
    std::cerr << "benchscope-cli: error: unknown command '" << args[0] << "'\n";
    print_usage(std::cerr);
    return 2;
  }
  args.erase(args.begin());
  if (asks_for_help(args)) {
    std::cout << command->usage << '\n';
    return 0;
  }
  // Every command reports a wrong call the same way: what is wrong, the usage line, where the rest is (exit 2).
  try {
    return command->run(args, std::cout, std::cerr);
  } catch (const bs::cli::UsageError& e) {
    std::cerr << "benchscope-cli: error: " << e.what() << '\n'
              << usage_line(*command) << "\n(benchscope-cli " << command->name << " --help shows the full usage)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "benchscope-cli: error: " << e.what() << '\n';
    return 1;
  }
}
