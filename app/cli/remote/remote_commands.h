// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The measurements a robot runs for the desk (`benchscope-cli remote HOST COMMAND ...`), and how the robot's job
// agent runs each: with its own event stream (--events jsonl) or wrapped in start/end events, and whether its
// results go to the job's result workspace (--workspace) to come home.
#include <optional>
#include <string>
#include <vector>

namespace bs::cli {

struct RemoteCommand {
  std::string name;  // "run flops", "record-power"
  int words = 1;     // how many words name it
  bool native_events = false;
  bool workspace = false;  // takes --workspace, so its results come home
};

const std::vector<RemoteCommand>& remote_commands();
// The command that `args` starts with, or none.
std::optional<RemoteCommand> find_remote_command(const std::vector<std::string>& args);
// "run flops, record-power, ..." for messages.
std::string remote_command_names();

}  // namespace bs::cli
