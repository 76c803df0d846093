// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The measurements a robot runs for the desk (`benchscope-cli remote HOST COMMAND ...`), how the robot's job agent
// runs each: with its own event stream (--events jsonl) or wrapped in start/end events, and whether its results go
// to the job's result workspace (--workspace) to come home; and each one's grammar, through which the desk checks
// the words before they go, so a robot never refuses what the desk let through.
#include <optional>
#include <string>
#include <vector>

namespace bs::commands {

// The words after the command's name read by its grammar and written back (throws UsageError naming the option).
using CanonicalWords = std::vector<std::string> (*)(const std::vector<std::string>& words);

struct RemoteCommand {
  std::string name;  // "run flops", "record-power"
  int words = 1;     // how many words name it
  bool native_events = false;
  bool workspace = false;  // takes --workspace, so its results come home
  CanonicalWords grammar = nullptr;
};

const std::vector<RemoteCommand>& remote_commands();
// The command that `args` starts with, or none.
std::optional<RemoteCommand> find_remote_command(const std::vector<std::string>& args);
// "run flops, record-power, ..." for messages.
std::string remote_command_names();
// The words the robot's job agent runs for `args` (the command's name first): the job's own options go right after
// the name, before any "--" (record-power's command): --workspace `result_workspace` for a command whose results
// come home, --events jsonl for one that streams its own events.
std::vector<std::string> job_words(const RemoteCommand& command, std::vector<std::string> args,
                                   const std::string& result_workspace);
// Reads `args` (the command's name first) through its grammar with the job's own options added, as the robot will:
// throws UsageError for words the robot's CLI would refuse.
void check_remote_words(const RemoteCommand& command, const std::vector<std::string>& args);

}  // namespace bs::commands
