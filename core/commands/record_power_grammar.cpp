// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/record_power_grammar.h"

#include <algorithm>

#include "commands/events_words.h"

namespace bs::commands {

std::vector<std::string> to_words(const RecordPowerSettings& s) {
  std::vector<std::string> a = {"record-power", "--sensor", s.sensor, "--interval-ms", number_word(s.interval_ms)};
  write_option(a, "--sysfs-root", s.sysfs_root);
  write_option(a, "--out", s.out);
  write_option(a, "--workspace", s.workspace);
  if (s.seconds) a.insert(a.end(), {"--seconds", number_word(*s.seconds)});
  if (s.quiet) a.push_back("--quiet");
  write_option(a, "--events", s.events);
  if (!s.command.empty()) {
    a.push_back("--");
    a.insert(a.end(), s.command.begin(), s.command.end());
  }
  return a;
}

RecordPowerSettings record_power_from_words(const std::vector<std::string>& words) {
  // Everything after "--" is the command to run, untouched by the option reading (its own options are its own).
  const auto dashes = std::find(words.begin(), words.end(), std::string("--"));
  RecordPowerSettings s;
  s.command.assign(dashes == words.end() ? dashes : dashes + 1, words.end());
  const Words args =
      read_words({words.begin(), dashes}, {"--quiet"},
                 {"--out", "--workspace", "--sensor", "--interval-ms", "--sysfs-root", "--seconds", "--events"});
  if (!args.positional.empty())
    throw UsageError("unexpected argument '" + args.positional[0] + "' (a command goes after --)");
  s.out = args.value("--out");
  s.workspace = args.value("--workspace");
  if (!s.out && !s.workspace) throw UsageError("--out FILE.csv or --workspace W.bsw is required");
  if (args.value("--seconds").has_value() == !s.command.empty())
    throw UsageError("give either --seconds S or -- COMMAND ARGS...");
  if (args.value("--seconds")) {
    const double seconds = args.number("--seconds", 0);
    if (!(seconds > 0 && seconds <= 7 * 24 * 3600)) throw UsageError("--seconds must be > 0");
    s.seconds = seconds;
  }
  s.interval_ms = args.number("--interval-ms", 100);
  if (!(s.interval_ms >= 1 && s.interval_ms <= 60000)) throw UsageError("the sample interval must be 1..60000 ms");
  s.sensor = args.value("--sensor").value_or("auto");
  s.sysfs_root = args.value("--sysfs-root");
  s.quiet = args.has("--quiet");
  s.events = read_events(args);
  return s;
}

}  // namespace bs::commands
