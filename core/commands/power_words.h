// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// --power SENSOR|auto|none, --power-interval-ms M and --sysfs-root DIR: the words of every command that can record
// the computer's own power while it runs. Which sensor exists is the running computer's business (the CLI finds
// it); the words only have to say the same thing on both sides.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "commands/words.h"

namespace bs::commands {

struct PowerWords {
  std::string sensor = "none";            // --power: a sensor id, "auto" (the board or package total) or "none"
  std::optional<double> interval_ms;      // --power-interval-ms, 1 .. 60000 (the recorder's default: 100)
  std::optional<std::string> sysfs_root;  // --sysfs-root (default "/")
  bool operator==(const PowerWords&) const = default;
};

inline const std::set<std::string> kPowerWordOptions = {"--power", "--power-interval-ms", "--sysfs-root"};

// Appends the options that differ from "no power recorded" (an interval or root given alone is written too, so the
// reader refuses it as the CLI always did).
void write_power(const PowerWords& power, std::vector<std::string>& words);
// Throws UsageError for an interval outside 1 .. 60000 ms, or an interval or root without --power.
PowerWords read_power(const Words& words);

}  // namespace bs::commands
