// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli record-power`'s words (the computer's power sensors for S seconds or while a command runs), read
// and written side by side like every command a robot runs for the desk (commands/remote_commands.h). Which sensors
// exist and whether the command can be started are the running computer's to say (the CLI).
#include <optional>
#include <string>
#include <vector>

#include "commands/words.h"

namespace bs::commands {

struct RecordPowerSettings {
  std::optional<std::string> out;         // --out FILE.csv
  std::optional<std::string> workspace;   // --workspace W.bsw (one of the two is required)
  std::string sensor = "auto";            // --sensor ID[,ID...]|auto
  double interval_ms = 100;               // --interval-ms, 1 to 60000
  std::optional<std::string> sysfs_root;  // --sysfs-root DIR (default /)
  std::optional<double> seconds;          // --seconds S, more than 0 and at most a week; or
  std::vector<std::string> command;       // -- COMMAND ARGS...: recorded while it runs (exactly one of the two)
  bool quiet = false;                     // --quiet
  std::optional<std::string> events;      // --events jsonl
  bool operator==(const RecordPowerSettings&) const = default;
};

// ["record-power", "--sensor", "auto", "--interval-ms", "100", ..., "--", COMMAND...]: the sampling spelled out (the
// robot's defaults may differ), the command last, after "--", untouched.
std::vector<std::string> to_words(const RecordPowerSettings& settings);
// The words after "record-power"; everything after the first "--" is the command. Throws UsageError naming the
// option and the accepted range.
RecordPowerSettings record_power_from_words(const std::vector<std::string>& words);

}  // namespace bs::commands
