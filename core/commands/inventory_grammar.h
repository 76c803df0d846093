// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The words of the two commands that say what a computer has — `benchscope-cli devices` (processors, GPUs, their
// empirical ceilings) and `benchscope-cli sensors` (its power sensors) — read and written side by side like every
// command a robot runs for the desk (commands/remote_commands.h): the CLI reads its command line with *_from_words,
// `remote ROBOT devices|sensors` checks the words through them before they go. What only the running computer can
// check (a /proc tree exists, an instruction set is known there) stays with the CLI.
#include <optional>
#include <string>
#include <vector>

#include "commands/words.h"

namespace bs::commands {

struct DevicesSettings {
  bool json = false;                      // --json
  bool table = false;                     // --table: the bundled device table instead of this computer
  bool measure_ceilings = false;          // --measure-ceilings
  std::optional<std::string> isa;         // --isa
  std::optional<std::string> workspace;   // --workspace WS: the ceilings measured are stored there
  std::optional<std::string> proc_root;   // --proc-root DIR: another computer's /proc (an ARM board's, in tests)
  std::optional<std::string> sysfs_root;  // --sysfs-root DIR (with --proc-root)
  bool operator==(const DevicesSettings&) const = default;
};

struct SensorsSettings {
  bool json = false;                      // --json
  std::optional<std::string> sysfs_root;  // --sysfs-root DIR (default /)
  bool operator==(const SensorsSettings&) const = default;
};

std::vector<std::string> to_words(const DevicesSettings& settings);  // ["devices", ...]
std::vector<std::string> to_words(const SensorsSettings& settings);  // ["sensors", ...]
// The words after the command's name. Throw UsageError naming the option or the argument.
DevicesSettings devices_from_words(const std::vector<std::string>& words);
SensorsSettings sensors_from_words(const std::vector<std::string>& words);

}  // namespace bs::commands
