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
#include "store/home_batch.h"
#include "store/import_batch.h"
#include "store/record_kinds.h"

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
  RecordCounts counts;  // what the job brought, per record kind
  std::vector<std::string> warnings;
  std::string summary() const { return counts.summary(); }  // "3 runs, 1 power log"
};

// A job's staged files (the result workspace among them) as the imports they bring home, each under its hash. Throws
// WorkspaceError naming the file, or std::runtime_error when the job brought nothing to import.
std::vector<HomeBatch> job_homes(const std::vector<std::string>& staged_files, const RemoteOrigin& origin,
                                 const std::string& platform);

// A robot's job comes home: its imports stored in ONE transaction (store/home_batch.h's bring_home), in the open
// workspace `ws` (the GUI) or the one at `workspace_path` (the CLI's --workspace; created when missing, and not left
// behind when nothing could be stored). Throws as job_homes() does, or WorkspaceError (nothing stored).
JobImport bring_job_home(Workspace& ws, const std::vector<std::string>& staged_files, const RemoteOrigin& origin,
                         const std::string& platform);
JobImport bring_job_home(const std::string& workspace_path, const std::vector<std::string>& staged_files,
                         const RemoteOrigin& origin, const std::string& platform);

}  // namespace bs::remote
