// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace bs::cli {

// One `benchscope-cli <name> ...` subcommand. Each lives in its own cmd_<name>.cpp and registers itself with a
// static CommandRegistrar, so adding a command touches no other file.
// run() returns the process exit code: 0 success, 1 failure (bad input, regression found, ...), 2 usage error.
struct Command {
  std::string name;
  std::string summary;  // one line for `benchscope-cli help`
  std::string usage;    // full usage text for `benchscope-cli help <name>`
  std::function<int(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)> run;
};

// Command::run for a body that writes only to `out` (it takes no `err`), so a registration names the function
// itself instead of wrapping it in a lambda: `out_only<run_devices>`.
template <int (*Run)(const std::vector<std::string>& args, std::ostream& out)>
int out_only(const std::vector<std::string>& args, std::ostream& out, std::ostream& /*err*/) {
  return Run(args, out);
}

void register_command(Command command);
const std::vector<Command>& commands();  // sorted by name
const Command* find_command(std::string_view name);

struct CommandRegistrar {
  explicit CommandRegistrar(Command command) { register_command(std::move(command)); }
};

}  // namespace bs::cli
