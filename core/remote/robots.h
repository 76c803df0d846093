// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The robots the desk knows: the Host entries of the user's SSH config (without wildcards) and the ones added by
// hand, each with how to reach it, its last contact (what the check found) and what ran there. Kept in
// $XDG_CONFIG_HOME/benchscope/robots.json (~/.config/...), shared by the CLI and the GUI, written atomically. No
// secret is ever stored: ssh and its agent keep the keys.
#include <string>
#include <vector>

#include "remote/robot_check.h"
#include "remote/ssh.h"

namespace bs::remote {

struct RobotRun {
  std::string date;  // ISO 8601 UTC, when it started
  std::string job_id;
  std::string command;  // "run flops --workers 1,2,4"
  std::string outcome;  // "imported 3 runs into lab.bsw", "failed: ...", "cancelled: ..."
};

struct Robot {
  std::string name;  // the SSH destination: a Host alias or user@host
  bool from_ssh_config = false;
  bool added = false;       // added by the user (kept even when the SSH config no longer has it)
  std::string config_file;  // ssh -F for this robot; empty: ssh's own
  std::string remote_cli;   // empty: benchscope-cli
  std::string platform;     // the platform name its results get in a workspace (empty: its host name)
  // The last contact.
  std::string last_contact;  // ISO 8601 UTC; empty: never
  bool last_ok = false;
  std::string last_problem;
  std::string hostname, arch, cli_version, devices;
  std::vector<RobotRun> runs;  // newest last, at most kMaxRuns
  SshTarget target() const;
};

inline constexpr std::size_t kMaxRobotRuns = 50;

// A job's entry in the robots list, worded once for the GUI and the CLI (#52): the command as its whole line
// ("run flops --workers 1,2,4", as `remote` was given it), started now; the outcome is set when the job ends.
RobotRun robot_run_started(const std::string& job_id, const std::vector<std::string>& command);
// What became of a job's results: `what` ("imported 3 runs into lab.bsw", "nothing to import"), after the job's
// status when it ended early ("cancelled, imported ...", "interrupted, nothing to import"): its results are partial.
std::string robot_run_outcome(const std::string& job_status, const std::string& what);

// The Host names of an SSH config file (and the files it Includes), without patterns (*, ?, !) and in file
// order; a missing file gives none.
std::vector<std::string> ssh_config_hosts(const std::string& config_path);
// ~/.ssh/config.
std::string default_ssh_config();
// $XDG_CONFIG_HOME/benchscope/robots.json, else ~/.config/benchscope/robots.json.
std::string default_robots_file();

class RobotList {
 public:
  // Reads `file` (a missing one is an empty list); throws std::runtime_error naming the file when it is not a
  // robots list.
  explicit RobotList(std::string file = default_robots_file());
  // The stored robots, plus the Hosts of `ssh_config` that are not stored yet (from_ssh_config set).
  std::vector<Robot> all(const std::string& ssh_config = default_ssh_config()) const;
  const Robot* find(const std::string& name) const;
  // Adds or updates (by name) and saves.
  void put(const Robot& robot);
  bool remove(const std::string& name);  // saves; false when it was not there
  void record_check(const std::string& name, const RobotCheck& check, const SshTarget& target);
  void record_run(const std::string& name, const RobotRun& run);
  const std::string& file() const { return file_; }

 private:
  Robot& entry(const std::string& name);
  void save() const;
  std::string file_;
  std::vector<Robot> robots_;
};

}  // namespace bs::remote
