// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The desk's side of a remote measurement: starts `benchscope-cli job run` on the robot through ssh, hands every
// event to the caller as it arrives (progress, sweep points, power readings), receives the result files into a
// local staging folder and checks them (size and hash). Any failure throws RemoteError with a sentence that names
// the host and what happened (ssh's words, the remote error, the line of garbage); the staging folder may then hold
// part of a file but nothing else is touched: importing is the caller's next step, and only after success.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "remote/events.h"
#include "remote/ssh.h"
#include "util/cancel.h"

namespace bs::remote {

class RemoteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Stops a remote job from another thread (tokens owned by the caller, either may be null). `cancel` asks the
// robot to stop as Ctrl+C would (what completed comes home and is imported); `abort` drops the connection (the
// robot stops everything and keeps what it has, to be fetched later).
struct JobControl {
  const CancelToken* cancel = nullptr;
  const CancelToken* abort = nullptr;
  bool cancelled() const { return cancel && cancel->cancelled(); }
  bool aborted() const { return abort && abort->cancelled(); }
};

struct JobHandlers {
  std::function<void(const Event&)> on_event;                     // every event but "file"
  std::function<void(const std::string& line)> on_remote_stderr;  // the robot's text (its CLI's messages)
};

// A job that came home.
struct RemoteJob {
  std::string id;
  std::string status;  // "done", "failed", "cancelled", "interrupted"
  int exit_status = 0;
  nlohmann::json record;            // the "job" event: command, cli_version, host, arch, started, dir
  std::vector<std::string> files;   // the staged result files (local paths), checked
  std::string error;                // the measurement's own error event, if any
  std::string remote_command_line;  // what ssh ran on the robot
};

// Sends the desk's file `local_path` to the robot as input `name` of job `id` (`job put`, before the job runs;
// core/remote/job_agent.h). Throws RemoteError naming the host, the file and what went wrong.
void send_job_input(const SshTarget& t, const std::string& id, const std::string& name, const std::string& local_path,
                    const JobControl& control);

// The staged file of that name (kJobResultFile, kJobOutputFile) among job.files, or empty.
std::string staged_file(const RemoteJob& job, const std::string& name);

// The words of the robot's command line for each action.
std::vector<std::string> job_run_words(const SshTarget& t, const std::string& id,
                                       const std::vector<std::string>& command);

// Runs `command` (e.g. {"run", "flops", "--workers", "1,2,4"}) on the robot as job `id` and receives its results
// into `staging_dir` (created). Throws RemoteError on any failure; returns normally also when the measurement
// failed or was cancelled there (see status).
RemoteJob run_remote_job(const SshTarget& t, const std::string& id, const std::vector<std::string>& command,
                         const std::string& staging_dir, const JobHandlers& handlers, const JobControl& control);
// Receives a finished job's results again (`id` empty: the robot's newest job).
RemoteJob fetch_remote_job(const SshTarget& t, const std::string& id, const std::string& staging_dir,
                           const JobHandlers& handlers, const JobControl& control);
// The robot's jobs (each "job" event's fields), oldest first.
std::vector<nlohmann::json> list_remote_jobs(const SshTarget& t, const JobControl& control);

// A plain remote command: its stdout, stderr and exit status (255: ssh's own failure). Throws RemoteError only
// when ssh cannot be started here.
struct RemoteOutput {
  std::string out, err;
  int status = 0;
};
RemoteOutput run_remote_command(const SshTarget& t, const std::string& command_line, const JobControl& control);

}  // namespace bs::remote
