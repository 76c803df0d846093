// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remote_cli.h"

#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>

#include "analysis/stats/units.h"
#include "commands/remote_commands.h"
#include "common/args.h"
#include "common/signals.h"
#include "remote/job_agent.h"
#include "remote/job_client.h"
#include "remote/job_import.h"
#include "remote/remote_inputs.h"
#include "store/workspace.h"
#include "util/host_clock.h"
#include "util/text.h"

namespace fs = std::filesystem;

namespace bs::cli {

using commands::check_remote_words;
using commands::find_remote_command;
using commands::remote_command_names;
using commands::RemoteCommand;
namespace {

// A private folder for the files coming home, removed with everything in it however the job ends.
class Staging {
 public:
  Staging() {
    std::string pattern = (fs::temp_directory_path() / "benchscope-remote-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw std::runtime_error("cannot make a staging folder in " + fs::temp_directory_path().string());
    path_ = pattern;
  }
  ~Staging() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The value of `option` in a command's words (before a "--"), or empty.
std::string option_value(const std::vector<std::string>& words, const std::string& option) {
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (words[i] == "--") break;
    if (words[i] == option && i + 1 < words.size()) return words[i + 1];
    if (words[i].starts_with(option + "=")) return words[i].substr(option.size() + 1);
  }
  return {};
}

// Prints the robot's events as they come: progress on one line redrawn in place, each point, the result.
struct Printer {
  std::string host;
  std::ostream& out;
  std::ostream& err;
  bool quiet = false;
  // A line redrawn in place is for a terminal; a log or a pipe gets the points only.
  bool progress_in_place = isatty(2) != 0;
  bool progress_open = false;
  std::size_t power_readings = 0;

  void close_progress() {
    if (progress_open) err << '\n';
    progress_open = false;
  }
  void on_event(const remote::Event& e) {
    const nlohmann::json& b = e.body;
    if (e.type == "progress" && !quiet && progress_in_place) {
      char line[160];
      std::snprintf(line, sizeof line, "\r%s: %5.1f %% %s          ", host.c_str(), b.value("fraction", 0.0) * 100,
                    b.value("step", "").c_str());
      err << line << std::flush;
      progress_open = true;
    } else if (e.type == "point" && !quiet) {
      close_progress();
      err << host << ": D = " << b.value("dims", 0) << ", W = " << b.value("workers", 0LL) << ": "
          << format_si(b.value("flops", 0.0), "FLOPS") << " (n = " << b.value("seconds", nlohmann::json::array()).size()
          << ")\n";
    } else if (e.type == "interval" && !quiet) {  // sustain --json: each interval as the robot completes it
      close_progress();
      const auto rate = b.find("rate");
      char line[240];
      if (rate != b.end() && rate->is_number())
        std::snprintf(line, sizeof line, "%s: sustain %.1f s: %.4g %s\n", host.c_str(), b.value("t_s", 0.0),
                      rate->get<double>(), b.value("rate_unit", "").c_str());
      else
        std::snprintf(line, sizeof line, "%s: sustain %.1f s: no work counted\n", host.c_str(), b.value("t_s", 0.0));
      err << line;
    } else if (e.type == "power") {
      ++power_readings;
    } else if (e.type == "message") {
      close_progress();
      err << host << ": " << b.value("text", "") << '\n';
    } else if (e.type == "result") {
      close_progress();
      if (const auto peaks = b.find("peaks"); peaks != b.end() && peaks->is_array())
        for (const auto& p : *peaks)
          out << host << " " << p.value("backend", "") << ", D = " << p.value("dims", 0) << ": peak "
              << format_si(p.value("peak_flops", 0.0), "FLOPS") << " \xC2\xB1 "
              << format_si(p.value("sd_flops", 0.0), "FLOPS") << " (n = " << p.value("n", 0)
              << ") at W = " << p.value("workers_at_peak", 0LL) << " [variant " << p.value("variant", "") << "]\n";
      if (b.contains("energy_j") && b["energy_j"].is_number()) {
        char line[200];
        std::snprintf(line, sizeof line, "%s: %.3f J over %.3f s, mean %.3f W (%zu samples, %s)\n", host.c_str(),
                      b["energy_j"].get<double>(), b.value("seconds", 0.0), b.value("mean_power_w", 0.0),
                      b.value("samples", std::size_t{0}), b.value("sensor", "").c_str());
        out << line;
      }
    }
  }
  void on_stderr(const std::string& line) {
    close_progress();
    err << host << ": " << line << '\n';
  }
};

int import_and_report(remote::RobotList& robots, const remote::SshTarget& target, const remote::RemoteJob& job,
                      const remote::RobotInfo& info, const std::vector<std::string>& command, const DeskOptions& o,
                      const std::string& verb, std::ostream& out, std::ostream& err,
                      const std::string& desk_files = {}) {
  const std::string host = target.destination;
  remote::RobotRun record = remote::robot_run_started(job.id, command);
  const std::string& what = record.command;
  const auto remember = [&](const std::string& outcome) {
    record.outcome = remote::robot_run_outcome(job.status, outcome);
    try {
      robots.record_run(host, record);
    } catch (const std::exception& e) {
      err << "benchscope-cli: warning: " << e.what() << '\n';
    }
  };
  if (job.status == "failed") {
    err << "benchscope-cli: error: " << host << ": " << what << " failed on the robot (status " << job.exit_status
        << (job.error.empty() ? std::string() : ": " + job.error) << "); nothing was imported\n";
    remember("failed: " + job.error);
    return 1;
  }
  const bool partial = job.status == "cancelled" || job.status == "interrupted";
  if (partial) err << host << ": job " << job.id << " was " << job.status << "; what it completed comes home\n";
  const std::string results = remote::staged_file(job, remote::kJobResultFile);
  const std::string output = remote::staged_file(job, remote::kJobOutputFile);
  // A fetch prints what the robot printed (a run showed it as it came): the answer of a text-only command.
  if (verb == "fetched" && !output.empty()) {
    std::ifstream in(output, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    out << "== " << host << ", job " << job.id << " (" << what << "): its output, as the robot printed it\n"
        << text << (text.ends_with('\n') ? "" : "\n") << "== end of the output of job " << job.id << '\n';
  }
  const std::string fetch_again = "`benchscope-cli remote " + host + " fetch " + job.id + "`";
  if (results.empty()) {
    const auto rc = find_remote_command(command);
    const std::string kept =
        output.empty() ? std::string()
                       : "; the robot keeps its output as job " + job.id + ": " + fetch_again + " prints it again";
    if (rc && rc->workspace)
      err << host << ": " << what << " completed nothing to import" << kept << '\n';
    else
      err << host << ": " << what << " leaves no results to import (it prints its figures only" << kept << ")\n";
    remember("nothing to import");
    return partial ? 1 : 0;
  }
  if (!o.workspace) {
    err << host << ": results kept on the robot as job " << job.id
        << " (give --workspace W.bsw to import them; `benchscope-cli remote " << host << " fetch " << job.id
        << " --workspace W.bsw` later)\n";
    remember("not imported");
    return partial ? 1 : 0;
  }
  remote::RemoteOrigin origin = remote::origin_of(target, job, info, command);
  origin.desk_files = desk_files;
  const remote::Robot* stored = robots.find(host);
  const std::string platform = o.platform ? *o.platform : stored && !stored->platform.empty() ? stored->platform : "";
  try {
    const remote::JobImport imported = remote::bring_job_home(*o.workspace, job.files, origin, platform);
    for (const std::string& w : imported.warnings) err << "benchscope-cli: warning: " << w << '\n';
    const std::string named = platform.empty() ? "'" + origin.hostname +
                                                     "' (the robot's host name; --platform NAME "
                                                     "renames it)"
                                               : "'" + platform + "'";
    out << verb << " " << imported.summary() << " from " << host << " (" << origin.hostname << ", " << origin.arch
        << ", BenchScope " << origin.cli_version << ", job " << job.id << ") into " << *o.workspace << " as platform "
        << named << '\n';
    remember("imported " + imported.summary() + " into " + *o.workspace);
  } catch (const std::exception& e) {
    err << "benchscope-cli: error: " << host << ": the results came home but were not imported: " << e.what()
        << "; the workspace is unchanged (`benchscope-cli remote " << host << " fetch " << job.id << "` tries again)\n";
    remember(std::string("not imported: ") + e.what());
    return 1;
  }
  return partial ? 1 : 0;
}

}  // namespace

DeskOptions take_desk_options(std::vector<std::string>& args) {
  DeskOptions o;
  const std::pair<const char*, std::optional<std::string> DeskOptions::*> valued[] = {
      {"--ssh-config", &DeskOptions::ssh_config},
      {"--remote-cli", &DeskOptions::remote_cli},
      {"--workspace", &DeskOptions::workspace},
      {"--platform", &DeskOptions::platform},
      {"--id", &DeskOptions::id}};
  std::vector<std::string> rest;
  std::size_t i = 0;
  for (; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--") break;
    if (a == "--desk-quiet") {
      o.quiet = true;
      continue;
    }
    bool taken = false;
    for (const auto& [name, field] : valued) {
      const std::string n(name);
      if (a == n) {
        if (i + 1 >= args.size()) throw UsageError(n + " needs a value");
        o.*field = args[++i];
        taken = true;
      } else if (a.starts_with(n + "=")) {
        o.*field = a.substr(n.size() + 1);
        taken = true;
      }
      if (taken) break;
    }
    if (!taken) rest.push_back(a);
  }
  rest.insert(rest.end(), args.begin() + static_cast<std::ptrdiff_t>(i), args.end());
  args = std::move(rest);
  if (o.platform && o.platform->empty()) throw UsageError("--platform needs a name");
  return o;
}

remote::SshTarget target_for(const remote::RobotList& robots, const std::string& name, const DeskOptions& o) {
  remote::SshTarget t;
  if (const remote::Robot* r = robots.find(name)) t = r->target();
  t.destination = name;
  if (o.ssh_config) t.config_file = *o.ssh_config;
  if (o.remote_cli) t.remote_cli = *o.remote_cli;
  try {
    remote::check_destination(name);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return t;
}

remote::RobotCheck check_and_print(remote::RobotList& robots, const remote::SshTarget& target, std::ostream& out,
                                   std::ostream& err, bool describe, const std::string& sysfs_root) {
  const remote::JobControl control{&interrupt_token(), nullptr};
  remote::RobotCheck c = remote::check_robot(target, control, sysfs_root);
  try {
    robots.record_check(target.destination, c, target);
  } catch (const std::exception& e) {
    err << "benchscope-cli: warning: " << e.what() << '\n';
  }
  for (const std::string& noise : c.info.login_noise)
    err << "benchscope-cli: warning: " << target.destination << " prints '" << noise.substr(0, 100)
        << "' on every non-interactive login (a login script such as ~/.bashrc); BenchScope copes, scp may not\n";
  if (!c.ok) {
    err << "benchscope-cli: error: " << c.problem << '\n';
    if (!c.fix.empty()) err << "  to install it, run at this desk:\n    " << c.fix << '\n';
    return c;
  }
  const remote::RobotInfo& i = c.info;
  if (!describe) {
    err << target.destination << ": " << i.hostname << " (" << i.arch << "), BenchScope " << i.cli_version << '\n';
    return c;
  }
  out << target.destination << ": reachable; host name " << i.hostname << ", " << i.arch
      << (i.os.empty() ? "" : ", " + i.os) << ", BenchScope " << i.cli_version << '\n';
  out << "  CPU: " << i.cpu << '\n';
  for (const remote::RobotBackend& b : i.backends)
    out << "  backend " << b.id << ": " << b.label << " on " << b.device << " (" << b.kind << ", peak "
        << format_si(b.theoretical_peak_flops, "FLOPS") << ")\n";
  bool any = false;
  for (const remote::RobotSensor& s : i.sensors) {
    out << "  power sensor " << s.id << " (" << s.kind << " " << s.label << (s.board_total ? ", board total" : "")
        << "): " << (s.readable ? "readable" : "NOT READABLE: " + s.reason) << '\n';
    any = true;
  }
  if (!any) out << "  power sensors: none found\n";
  out << "  --power auto records: " << i.sensor_note << '\n';
  out << "  jobs kept in " << i.jobs_dir << '\n';
  return c;
}

int run_remote(remote::RobotList& robots, const remote::SshTarget& target, const std::vector<std::string>& command,
               const DeskOptions& o, std::ostream& out, std::ostream& err) {
  const auto rc = find_remote_command(command);
  if (!rc)
    throw UsageError("a robot runs one of: " + remote_command_names() + " (got '" +
                     (command.empty() ? std::string() : command[0]) + "')");
  for (const std::string& a : command) {
    if (a == "--") break;
    if (a == "--events" || a.starts_with("--events=") || a == "--workspace")
      throw UsageError(a +
                       " is the desk's to give: the robot streams its events and its results come home to the "
                       "desk's --workspace");
  }
  // The words go through the command's grammar here, as the robot's CLI will read them: a mistake is refused before
  // any file is sent or any job started.
  check_remote_words(*rc, command);
  const std::string id = o.id.value_or(remote::new_job_id());
  try {
    remote::check_job_id(id);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--id: ") + e.what());
  }
  // The robot's description names the sensors the measurement reads (its --sysfs-root), for the provenance.
  const remote::RobotCheck check =
      check_and_print(robots, target, out, err, false, option_value(command, "--sysfs-root"));
  if (!check.ok) return 1;
  // The desk's frames, lens and model files the command names go first, into the job's inputs folder there.
  const CarriedCommand carried =
      carry_desk_files(command, check.info.jobs_dir + "/" + id + "/" + remote::kJobInputsFolder);
  for (const CarriedFile& f : carried.files) {
    if (!o.quiet) err << target.destination << ": sending " << f.local_path << '\n';
    try {
      remote::send_job_input(target, id, f.name, f.local_path, {&interrupt_token(), nullptr});
    } catch (const remote::RemoteError& e) {
      err << "benchscope-cli: error: " << e.what() << "; nothing ran\n";
      return 1;
    }
  }
  Staging staging;
  Printer printer{target.destination, out, err, o.quiet};
  remote::JobHandlers handlers;
  handlers.on_event = [&](const remote::Event& e) { printer.on_event(e); };
  handlers.on_remote_stderr = [&](const std::string& line) { printer.on_stderr(line); };
  const remote::JobControl control{&interrupt_token(), nullptr};
  if (!o.quiet) err << target.destination << ": job " << id << ": " << join(command, " ") << '\n';
  remote::RemoteJob job;
  try {
    job = remote::run_remote_job(target, id, carried.command, staging.path(), handlers, control);
  } catch (const remote::RemoteError& e) {
    printer.close_progress();
    err << "benchscope-cli: error: " << e.what() << '\n';
    try {
      remote::RobotRun record = remote::robot_run_started(id, command);
      record.outcome = std::string("failed: ") + e.what();
      robots.record_run(target.destination, record);
    } catch (const std::exception&) {  // the list is a convenience; the error above is what matters
    }
    return 1;
  }
  printer.close_progress();
  if (printer.power_readings > 0 && !o.quiet)
    err << target.destination << ": " << printer.power_readings << " power readings streamed\n";
  // What ran there names the robot's copies; the provenance also says which desk files they are.
  std::string desk_files;
  for (const CarriedFile& f : carried.files)
    desk_files += (desk_files.empty() ? "" : "; ") + f.local_path + " -> " + f.name;
  return import_and_report(robots, target, job, check.info, carried.command, o, "imported", out, err, desk_files);
}

int fetch_remote(remote::RobotList& robots, const remote::SshTarget& target, const std::string& id,
                 const DeskOptions& o, std::ostream& out, std::ostream& err) {
  const remote::RobotCheck check = check_and_print(robots, target, out, err, false);
  if (!check.ok) return 1;
  Staging staging;
  Printer printer{target.destination, out, err, true};
  remote::JobHandlers handlers;
  handlers.on_remote_stderr = [&](const std::string& line) { printer.on_stderr(line); };
  const remote::JobControl control{&interrupt_token(), nullptr};
  remote::RemoteJob job;
  try {
    job = remote::fetch_remote_job(target, id, staging.path(), handlers, control);
  } catch (const remote::RemoteError& e) {
    err << "benchscope-cli: error: " << e.what() << '\n';
    return 1;
  }
  std::vector<std::string> command;
  if (const auto c = job.record.find("command"); c != job.record.end() && c->is_array())
    for (const auto& w : *c)
      if (w.is_string()) command.push_back(w.get<std::string>());
  err << target.destination << ": job " << job.id << " (" << join(command, " ") << ", started "
      << job.record.value("started", "") << "): " << job.status << '\n';
  return import_and_report(robots, target, job, check.info, command, o, "fetched", out, err);
}

}  // namespace bs::cli
