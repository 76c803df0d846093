// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// --events jsonl: the word of every command that can send its run as BenchScope's event stream
// (docs/remote-events-v1.md) on stdout, as a robot's job does. Read alike by each grammar that takes it.
#include <optional>
#include <string>

#include "commands/words.h"

namespace bs::commands {

// The value of --events: none, or "jsonl"; another value is a UsageError "--events takes jsonl (got '...')".
std::optional<std::string> read_events(const Words& words);

}  // namespace bs::commands
