// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/job_import.h"

#include <filesystem>
#include <map>
#include <stdexcept>

#include "remote/job_agent.h"
#include "store/workspace.h"

namespace fs = std::filesystem;

namespace bs::remote {
namespace {

void stamp(Provenance& p, const RemoteOrigin& o) {
  for (auto& kv : origin_settings(o)) {
    std::erase_if(p.settings, [&](const auto& s) { return s.first == kv.first; });
    p.settings.push_back(std::move(kv));
  }
  if (p.host.empty()) p.host = o.hostname;
}

template <class T>
void rename_platform(T& item, const std::string& platform) {
  if (!platform.empty()) item.platform = platform;
}

}  // namespace

RemoteOrigin origin_of(const SshTarget& target, const RemoteJob& job, const RobotInfo& info,
                       const std::vector<std::string>& command) {
  RemoteOrigin o;
  o.destination = target.destination;
  o.hostname = job.record.value("host", info.hostname);
  o.arch = job.record.value("arch", info.arch);
  o.devices = info.devices_text();
  std::vector<std::string> words = {target.remote_cli};
  words.insert(words.end(), command.begin(), command.end());
  o.command_line = shell_command(words);
  o.cli_version = job.record.value("cli_version", info.cli_version);
  o.job_id = job.id;
  return o;
}

std::vector<std::pair<std::string, std::string>> origin_settings(const RemoteOrigin& o) {
  std::vector<std::pair<std::string, std::string>> settings = {
      {"remote host", o.destination}, {"remote host name", o.hostname},   {"remote architecture", o.arch},
      {"remote devices", o.devices},  {"remote command", o.command_line}, {"remote BenchScope", o.cli_version},
      {"remote job", o.job_id}};
  if (!o.desk_files.empty()) settings.emplace_back("remote inputs from the desk", o.desk_files);
  return settings;
}

std::string job_batch_hash(const RemoteOrigin& o, std::size_t index, const std::string& remote_hash) {
  return content_hash("benchscope-remote-job\n" + o.destination + "\n" + o.job_id + "\n" + std::to_string(index) +
                      "\n" + remote_hash);
}

std::vector<ImportBatch> job_batches(const std::string& result_file, const RemoteOrigin& o,
                                     const std::string& platform) {
  const Workspace ws(result_file, Workspace::OpenMode::ReadOnly);
  if (!ws.damage().empty())
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         result_file + ": the robot's results are damaged: " + describe(ws.damage().front()));
  std::map<std::int64_t, ImportBatch> by_import;
  const std::string prefix = "remote " + o.destination + " job " + o.job_id + ": ";
  for (const ImportRecord& r : ws.imports()) {
    ImportBatch& b = by_import[r.id];
    b.source_path = prefix + r.path;
    b.format = r.format;
  }
  for (StoredRun s : ws.runs()) {
    stamp(s.run.provenance, o);
    rename_platform(s.run, platform);
    by_import[s.import_id].runs.push_back(std::move(s.run));
  }
  for (StoredResultSet s : ws.result_sets()) {
    stamp(s.set.provenance, o);
    rename_platform(s.set, platform);
    by_import[s.import_id].result_sets.push_back(std::move(s.set));
  }
  for (StoredPowerTrace s : ws.power_traces()) {
    stamp(s.trace.provenance, o);
    rename_platform(s.trace, platform);
    by_import[s.import_id].power_traces.push_back(std::move(s.trace));
  }
  for (StoredPipelineRun s : ws.pipeline_runs()) {
    stamp(s.run.provenance, o);
    rename_platform(s.run, platform);
    by_import[s.import_id].pipeline_runs.push_back(std::move(s.run));
  }
  for (StoredDnnRun s : ws.dnn_runs()) {
    stamp(s.run.provenance, o);
    rename_platform(s.run, platform);
    by_import[s.import_id].dnn_runs.push_back(std::move(s.run));
  }
  for (StoredHeadroom s : ws.headroom_measurements()) {
    stamp(s.measurement.provenance, o);
    rename_platform(s.measurement, platform);
    by_import[s.import_id].headroom.push_back(std::move(s.measurement));
  }
  for (StoredSustainRun s : ws.sustain_runs()) {
    stamp(s.run.provenance, o);
    rename_platform(s.run, platform);
    by_import[s.import_id].sustain_runs.push_back(std::move(s.run));
  }
  for (const StoredFrame& f : ws.frames())
    by_import[f.import_id].warnings.push_back(result_file + ": frame '" + f.frame.label +
                                              "' left out: frames stay on the robot (" + f.path + ")");
  std::vector<ImportBatch> batches;
  for (auto& [id, b] : by_import)
    if (!b.empty()) batches.push_back(std::move(b));
  return batches;
}

std::string JobImport::summary() const {
  std::string s;
  const auto add = [&](std::size_t n, const char* one, const char* many) {
    if (n) s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + (n == 1 ? one : many);
  };
  add(runs, "run", "runs");
  add(power_traces, "power log", "power logs");
  add(result_sets, "result set", "result sets");
  add(pipeline_runs, "pipeline run", "pipeline runs");
  add(dnn_runs, "inference run", "inference runs");
  add(headroom, "headroom measurement", "headroom measurements");
  add(sustain_runs, "sustained run", "sustained runs");
  return s.empty() ? "nothing" : s;
}

namespace {

// The job's batches with their hashes, and the counts for the summary.
struct PreparedJob {
  std::vector<ImportBatch> batches;
  std::vector<std::string> hashes;
};

PreparedJob prepare(const std::vector<std::string>& staged_files, const RemoteOrigin& origin,
                    const std::string& platform) {
  std::string result;
  for (const std::string& f : staged_files)
    if (fs::path(f).filename() == kJobResultFile) result = f;
  if (result.empty()) throw std::runtime_error("the robot sent no results (no " + std::string(kJobResultFile) + ")");
  const std::string remote_hash = file_content_hash(result);
  PreparedJob p;
  p.batches = job_batches(result, origin, platform);
  if (p.batches.empty()) throw std::runtime_error("the robot's job holds nothing to import");
  for (std::size_t i = 0; i < p.batches.size(); ++i) p.hashes.push_back(job_batch_hash(origin, i, remote_hash));
  return p;
}

JobImport store_prepared(Workspace& ws, const PreparedJob& p) {
  JobImport out;
  std::vector<Workspace::HashedBatch> hashed;
  for (std::size_t i = 0; i < p.batches.size(); ++i) {
    const ImportBatch& b = p.batches[i];
    hashed.push_back({&b, p.hashes[i]});
    out.runs += b.runs.size();
    out.power_traces += b.power_traces.size();
    out.result_sets += b.result_sets.size();
    out.pipeline_runs += b.pipeline_runs.size();
    out.dnn_runs += b.dnn_runs.size();
    out.headroom += b.headroom.size();
    out.sustain_runs += b.sustain_runs.size();
    out.warnings.insert(out.warnings.end(), b.warnings.begin(), b.warnings.end());
  }
  out.import_ids = ws.add_imports(hashed);
  return out;
}

}  // namespace

JobImport store_job(Workspace& ws, const std::vector<std::string>& staged_files, const RemoteOrigin& origin,
                    const std::string& platform) {
  return store_prepared(ws, prepare(staged_files, origin, platform));
}

JobImport import_job(const std::string& workspace_path, const std::vector<std::string>& staged_files,
                     const RemoteOrigin& origin, const std::string& platform) {
  // Everything is read and checked before the workspace is opened: a job that cannot be imported creates nothing.
  const PreparedJob p = prepare(staged_files, origin, platform);
  std::error_code ec;
  const bool existed = fs::exists(workspace_path, ec);
  JobImport out;
  try {
    Workspace ws(workspace_path);
    out = store_prepared(ws, p);
  } catch (...) {
    // A workspace this import would have created is not left behind empty.
    if (!existed) {
      fs::remove(workspace_path, ec);
      fs::remove(workspace_path + "-wal", ec);
      fs::remove(workspace_path + "-shm", ec);
    }
    throw;
  }
  return out;
}

}  // namespace bs::remote
