// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/events_words.h"

namespace bs::commands {

std::optional<std::string> read_events(const Words& words) {
  std::optional<std::string> events = words.value("--events");
  if (events && *events != "jsonl") throw UsageError("--events takes jsonl (got '" + *events + "')");
  return events;
}

}  // namespace bs::commands
