// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Minimal, strict argument parsing shared by the subcommands: unknown options are usage errors (exit 2). The reader
// itself is core's (commands/words.h), the one the robot-runnable commands' grammars read with too.
#include <set>
#include <string>
#include <vector>

#include "commands/words.h"

namespace bs::cli {

using UsageError = commands::UsageError;
using ParsedArgs = commands::Words;

// `flags` take no value; `valued` take the next argument (or --opt=value).
inline ParsedArgs parse_args(const std::vector<std::string>& args, const std::set<std::string>& flags,
                             const std::set<std::string>& valued) {
  return commands::read_words(args, flags, valued);
}

}  // namespace bs::cli
