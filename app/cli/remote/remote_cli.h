// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The desk's side of `benchscope-cli remote`: the options it takes out of a command line before the rest goes to
// the robot, the robot it names, and running, fetching and importing a job with the robot's progress printed.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "remote/robots.h"

namespace bs::cli {

// Options of the desk, taken from anywhere before a "--" (what follows is record-power's command).
struct DeskOptions {
  std::optional<std::string> ssh_config, remote_cli, workspace, platform, id;
  bool quiet = false;  // --desk-quiet: no progress lines (the robot's --quiet is the robot's)
};
DeskOptions take_desk_options(std::vector<std::string>& args);

// The robot `name` as stored (its config file and CLI path), with the options given now winning.
remote::SshTarget target_for(const remote::RobotList& robots, const std::string& name, const DeskOptions& o);

// Checks the robot and prints what it is, or the problem and its fix (records the contact). Returns the check.
// `sysfs_root`: where the robot's sensors are looked for (a measurement's --sysfs-root).
remote::RobotCheck check_and_print(remote::RobotList& robots, const remote::SshTarget& target, std::ostream& out,
                                   std::ostream& err, bool describe, const std::string& sysfs_root = {});

// Runs `command` on the robot as a job, prints its progress, imports its results into --workspace. Exit status.
int run_remote(remote::RobotList& robots, const remote::SshTarget& target, const std::vector<std::string>& command,
               const DeskOptions& o, std::ostream& out, std::ostream& err);
// Fetches job `id` (empty: the newest) again and imports it. Exit status.
int fetch_remote(remote::RobotList& robots, const remote::SshTarget& target, const std::string& id,
                 const DeskOptions& o, std::ostream& out, std::ostream& err);

}  // namespace bs::cli
