// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The robot's side of a remote measurement (`benchscope-cli job ...`, started by the desk over SSH). The agent
// runs the measurement as a child process in a process group of its own, with its results written into a job
// folder (`~/.cache/benchscope/remote/<id>/`), and forwards the child's events on stdout. It reads its stdin: a
// line "cancel" stops the measurement as Ctrl+C would (the completed part is kept and sent home); the END of
// stdin (the desk gone, the connection dropped) stops it too, and then nothing is left running: the group gets
// SIGTERM, then SIGKILL. When the child has ended the agent sends the result files as "file" events and a
// "job_end" event; the folder stays, so `remote HOST fetch ID` can send them again.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace bs::remote {

// $XDG_CACHE_HOME/benchscope/remote, else $HOME/.cache/benchscope/remote.
std::string default_jobs_dir();
// Throws std::invalid_argument unless `id` is 1..64 letters, digits, '-', '_' and '.' (not leading).
void check_job_id(const std::string& id);
// A fresh id from the desk's clock and randomness: "20261130-101502-3f9a1c".
std::string new_job_id();

// The file a job leaves its results in (a BenchScope workspace) and its record.
inline constexpr const char* kJobResultFile = "result.bsw";
inline constexpr const char* kJobRecordFile = "job.json";
// What the measurement printed (its stderr: the tables of `bench vision`, `bench kernels`, `devices`), kept with the
// job and sent home with its results, so that a command whose answer is text can be fetched again. Up to
// kJobOutputLimit bytes; the rest is left out and a last line says so.
inline constexpr const char* kJobOutputFile = "output.txt";
inline constexpr std::size_t kJobOutputLimit = 16u << 20;

struct AgentJob {
  std::string id;
  std::string jobs_dir;
  std::vector<std::string> command;  // what the desk asked for, e.g. {"run", "flops", "--workers", "1,2"}
  // Runs the measurement in the forked child, with stdout going to the agent; returns the exit status. Gets the
  // job's folder (where its results go).
  std::function<int(const std::string& job_dir)> body;
  int stdin_fd = 0;  // where "cancel" comes from
};

// A job's input files (issue #44: the frames, lens and model files a measurement on the desk names) are sent
// before it runs, one `job put` each, into <jobs_dir>/<id>/inputs/. kJobInputLimit bounds each file.
inline constexpr const char* kJobInputsFolder = "inputs";
inline constexpr std::uint64_t kJobInputLimit = std::uint64_t{4} << 30;
// Throws std::invalid_argument unless `name` is a plain file name (1 to 128 letters, digits, '-', '_', '.'; not
// leading '.'), optionally in one numbered folder ("3/capture.raw").
void check_input_name(const std::string& name);
// Receives input `name` of job `id`: exactly `size` bytes read from `fd` (the desk's, through ssh), written under a
// temporary name and renamed when whole. Refused for a job that has run, a size over the limit, a stream that ends
// early; nothing half-written stays. Returns 0, or 1 after a sentence on `err` naming the file and the reason.
int put_job_input(const std::string& jobs_dir, const std::string& id, const std::string& name, std::uint64_t size,
                  int fd, std::ostream& err);

// Runs the job and writes its events to `out` (the agent's stdout); the child's stderr goes to `err`. Returns 0
// when the job ran (whatever its outcome: job_end says), 1 when it could not start (an event says why).
int run_job_agent(const AgentJob& job, std::ostream& out, std::ostream& err);
// Sends a finished job's record and files again ("job", "file"..., "job_end"); `id` empty: the newest job.
int fetch_job_agent(const std::string& jobs_dir, const std::string& id, std::ostream& out);
// One "job" event per job in the folder, newest last, with its status.
int list_jobs_agent(const std::string& jobs_dir, std::ostream& out);

}  // namespace bs::remote
