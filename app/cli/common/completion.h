// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shell completion generated from the command registry, so a new command (or a new option in a command's usage
// text) completes without anyone editing a script by hand.
#include <string>
#include <vector>

#include "common/command.h"

namespace bs::cli {

// The options a command's usage text names ("--json", "--out", ...), sorted, each once.
std::vector<std::string> options_in_usage(const std::string& usage);

// A bash script that completes command names after `benchscope-cli`, a command's options after a word starting
// with "-" (plus --help), command names after `help`, and file names otherwise.
std::string bash_completion(const std::vector<Command>& commands);

}  // namespace bs::cli
