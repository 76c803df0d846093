// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Commands made of subcommands ("bench kernels", "lens circle"): the word picks the body, and a missing or unknown
// word is a usage error listing them, written once instead of a chain of `if (args[0] == ...)` per command.
#include <initializer_list>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace bs::cli {

// One subcommand: its word and its body, which runs with the arguments after the word (out_only<...> from
// common/command.h adapts a body that takes no `err`).
struct Subcommand {
  std::string_view word;
  int (*run)(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
};

// Command::run for a command made of subcommands: runs the one `args[0]` names with the arguments after it. Without
// a word, or with an unknown one, throws UsageError listing them in the order given: "expected 'lens circle',
// 'lens calibrate' or 'lens show'".
int run_subcommand(std::string_view command, std::initializer_list<Subcommand> subcommands,
                   const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace bs::cli
