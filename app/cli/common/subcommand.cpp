// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/subcommand.h"

#include "common/args.h"

namespace bs::cli {

int run_subcommand(std::string_view command, std::initializer_list<Subcommand> subcommands,
                   const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (!args.empty())
    for (const Subcommand& s : subcommands)
      if (args[0] == s.word) return s.run({args.begin() + 1, args.end()}, out, err);
  std::string words;
  std::size_t left = subcommands.size();
  for (const Subcommand& s : subcommands) {
    words += "'" + std::string(command) + " " + std::string(s.word) + "'";
    --left;
    words += left > 1 ? ", " : left == 1 ? " or " : "";
  }
  throw UsageError("expected " + words);
}

}  // namespace bs::cli
