// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/power_words.h"

namespace bs::commands {

void write_power(const PowerWords& power, std::vector<std::string>& words) {
  if (power.sensor != "none") words.insert(words.end(), {"--power", power.sensor});
  if (power.interval_ms) words.insert(words.end(), {"--power-interval-ms", number_word(*power.interval_ms)});
  if (power.sysfs_root) words.insert(words.end(), {"--sysfs-root", *power.sysfs_root});
}

PowerWords read_power(const Words& words) {
  PowerWords p;
  p.sensor = words.value("--power").value_or("none");
  if (words.value("--power-interval-ms")) p.interval_ms = words.number("--power-interval-ms", 100);
  p.sysfs_root = words.value("--sysfs-root");
  if (p.sensor == "none" && (p.interval_ms || p.sysfs_root))
    throw UsageError("--power-interval-ms and --sysfs-root need --power");
  if (p.interval_ms && !(*p.interval_ms >= 1 && *p.interval_ms <= 60000))
    throw UsageError("the sample interval must be 1..60000 ms");
  return p;
}

}  // namespace bs::commands
