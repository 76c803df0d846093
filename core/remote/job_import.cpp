// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/job_import.h"

#include <filesystem>
#include <map>
#include <stdexcept>

#include "remote/job_agent.h"
#include "store/home_batch.h"
#include "store/record_kinds.h"
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
  // Every kind by its rule (store/record_kinds.h): stamped with the robot's provenance and renamed, or left on the
  // robot with a warning.
  for_each_record_kind([&](const auto& kind) {
    for (auto& stored : (ws.*kind.read)()) {
      auto& item = stored.*kind.item;
      if constexpr (from_robot_v<decltype(kind)> == FromRobot::StaysOnRobot) {
        by_import[stored.import_id].warnings.push_back(result_file + ": " + kind.words.one + " '" + item.label +
                                                       "' left out: " + kind.words.many + " stay on the robot (" +
                                                       stored.path + ")");
      } else {
        stamp(item.provenance, o);
        rename_platform(item, platform);
        (by_import[stored.import_id].*kind.in_batch).push_back(std::move(item));
      }
    }
  });
  std::vector<ImportBatch> batches;
  for (auto& [id, b] : by_import)
    if (!b.empty()) batches.push_back(std::move(b));
  return batches;
}

std::vector<HomeBatch> job_homes(const std::vector<std::string>& staged_files, const RemoteOrigin& origin,
                                 const std::string& platform) {
  std::string result;
  for (const std::string& f : staged_files)
    if (fs::path(f).filename() == kJobResultFile) result = f;
  if (result.empty()) throw std::runtime_error("the robot sent no results (no " + std::string(kJobResultFile) + ")");
  const std::string remote_hash = file_content_hash(result);
  std::vector<ImportBatch> batches = job_batches(result, origin, platform);
  if (batches.empty()) throw std::runtime_error("the robot's job holds nothing to import");
  std::vector<HomeBatch> homes;
  for (std::size_t i = 0; i < batches.size(); ++i)
    homes.push_back({std::move(batches[i]), job_batch_hash(origin, i, remote_hash)});
  return homes;
}

namespace {

JobImport counted(const std::vector<HomeBatch>& homes, std::vector<std::int64_t> ids) {
  JobImport out;
  out.import_ids = std::move(ids);
  for (const HomeBatch& h : homes) {
    out.counts.add(h.batch);
    out.warnings.insert(out.warnings.end(), h.batch.warnings.begin(), h.batch.warnings.end());
  }
  return out;
}

}  // namespace

JobImport bring_job_home(Workspace& ws, const std::vector<std::string>& staged_files, const RemoteOrigin& origin,
                         const std::string& platform) {
  const std::vector<HomeBatch> homes = job_homes(staged_files, origin, platform);
  return counted(homes, bring_home(ws, homes));
}

JobImport bring_job_home(const std::string& workspace_path, const std::vector<std::string>& staged_files,
                         const RemoteOrigin& origin, const std::string& platform) {
  // Everything is read and checked before the workspace is opened: a job that cannot be imported creates nothing.
  const std::vector<HomeBatch> homes = job_homes(staged_files, origin, platform);
  return counted(homes, bring_home(workspace_path, homes));
}

}  // namespace bs::remote
