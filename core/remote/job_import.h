// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Bringing a robot's results home: the job's result workspace (received into a staging folder) becomes import
// batches of the desk's workspace, one per import the robot made, every run, power log, result set, pipeline run,
// inference run, control-loop headroom measurement and sustained run stamped with where it came from (the robot as
// named at the desk, its host name, architecture and devices, the command line run there, its BenchScope version, the
// job id) and put under the platform name the user confirmed. They are stored in ONE transaction: a failure (a full
// disk, a duplicate) stores nothing.
#include <cstdint>
#include <string>
#include <vector>

#include "remote/job_client.h"
#include "remote/robot_check.h"
#include "store/import_batch.h"

namespace bs {
class Workspace;
}

namespace bs::remote {

struct RemoteOrigin {
  std::string destination;   // as the desk named the robot: "jetson", "lab@10.0.0.7"
  std::string hostname;      // the robot's own name
  std::string arch;          // uname -m
  std::string devices;       // RobotInfo::devices_text()
  std::string command_line;  // what ran there: "benchscope-cli run flops --workers 1,2,4 ..."
  std::string cli_version;   // the robot's BenchScope
  std::string job_id;
  // The desk's files carried to the robot for the job, "desk path -> robot path; ..." (empty: none).
  std::string desk_files;
};

// Where a job's results came from: the robot as named (`target`), what the job's record and the check say about
// it, and the command line (`command` run by the robot's CLI).
RemoteOrigin origin_of(const SshTarget& target, const RemoteJob& job, const RobotInfo& info,
                       const std::vector<std::string>& command);

// The provenance settings an origin adds ("remote host", ...), in this order.
std::vector<std::pair<std::string, std::string>> origin_settings(const RemoteOrigin& origin);

// Reads the job's result workspace `result_file` into batches (frames are left out with a warning: a robot's
// frame files stay on the robot). `platform` empty keeps the names the robot gave (its host name). Throws
// WorkspaceError naming the file when it cannot be read (e.g. written by a newer BenchScope).
std::vector<ImportBatch> job_batches(const std::string& result_file, const RemoteOrigin& origin,
                                     const std::string& platform);
// The content hash under which batch `index` of a job is stored: the same job fetched twice is a duplicate.
std::string job_batch_hash(const RemoteOrigin& origin, std::size_t index, const std::string& remote_hash);

struct JobImport {
  std::vector<std::int64_t> import_ids;
  std::size_t runs = 0, power_traces = 0, result_sets = 0, pipeline_runs = 0, dnn_runs = 0, headroom = 0,
              sustain_runs = 0;
  std::vector<std::string> warnings;
  std::string summary() const;  // "3 runs, 1 power log"
};

// Stores the batches of a job's staged files (the result workspace among them) in the open workspace `ws`, in one
// transaction. Throws WorkspaceError (nothing stored) or std::runtime_error when the job brought nothing.
JobImport store_job(Workspace& ws, const std::vector<std::string>& staged_files, const RemoteOrigin& origin,
                    const std::string& platform);
// Stores the batches of a job's staged files (the result workspace among them) in the workspace at
// `workspace_path` (created when missing) in one transaction. Throws WorkspaceError (nothing stored; a workspace
// that did not exist is not left behind) or std::runtime_error when the job brought nothing to import.
JobImport import_job(const std::string& workspace_path, const std::vector<std::string>& staged_files,
                     const RemoteOrigin& origin, const std::string& platform);

}  // namespace bs::remote
