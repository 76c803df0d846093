// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli remote: run a measurement on a robot over SSH, watch it from the desk and bring the results home.
#include <ostream>

#include "commands/remote_commands.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "remote/job_client.h"
#include "remote/remote_cli.h"
#include "remote/robots.h"

namespace bs::cli {
namespace {

int list_robots(const remote::RobotList& robots, const DeskOptions& o, std::ostream& out) {
  const std::vector<remote::Robot> all = robots.all(o.ssh_config.value_or(remote::default_ssh_config()));
  if (all.empty()) {
    out << "no robots: add one with `benchscope-cli remote add HOST`, or give it a Host entry in "
        << o.ssh_config.value_or(remote::default_ssh_config()) << '\n';
    return 0;
  }
  TextTable table({"robot", "from", "last contact", "host name", "arch", "BenchScope", "last run"});
  for (const remote::Robot& r : all) {
    std::string from = r.from_ssh_config ? "ssh config" : "";
    if (r.added) from += std::string(from.empty() ? "" : ", ") + "added";
    const std::string contact =
        r.last_contact.empty() ? "never" : r.last_contact + (r.last_ok ? "" : " (FAILED: see check)");
    std::string last;
    if (!r.runs.empty()) {
      const remote::RobotRun& run = r.runs.back();
      const std::string command = run.command.size() > 40 ? run.command.substr(0, 37) + "..." : run.command;
      last = run.date + " " + command + ": " + run.outcome;
    }
    table.add({r.name, from, contact, r.hostname, r.arch, r.cli_version, last});
  }
  table.print(out);
  out << "(" << robots.file() << ")\n";
  return 0;
}

int jobs(const remote::SshTarget& target, std::ostream& out, std::ostream& err) {
  const remote::JobControl control{&interrupt_token(), nullptr};
  std::vector<nlohmann::json> list;
  try {
    list = remote::list_remote_jobs(target, control);
  } catch (const remote::RemoteError& e) {
    err << "benchscope-cli: error: " << e.what() << '\n';
    return 1;
  }
  if (list.empty()) {
    out << target.destination << ": no jobs\n";
    return 0;
  }
  TextTable table({"job", "started", "status", "command", "result bytes"});
  for (const nlohmann::json& j : list) {
    std::string command;
    if (const auto c = j.find("command"); c != j.end() && c->is_array())
      for (const auto& w : *c) command += (command.empty() ? "" : " ") + w.get<std::string>();
    std::uint64_t bytes = 0;
    if (const auto f = j.find("files"); f != j.end() && f->is_array())
      for (const auto& x : *f) bytes += x.value("size", std::uint64_t{0});
    table.add({j.value("id", ""), j.value("started", ""), j.value("status", ""), command.substr(0, 80),
               std::to_string(bytes)});
  }
  table.print(out);
  return 0;
}

int remote_command(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  std::vector<std::string> args = raw;
  const DeskOptions o = take_desk_options(args);
  if (args.empty()) throw UsageError("expected a robot (user@host or a Host of ~/.ssh/config), list, add or remove");
  remote::RobotList robots;
  const std::string first = args[0];
  if (first == "list") {
    if (args.size() != 1) throw UsageError("remote list takes no argument");
    return list_robots(robots, o, out);
  }
  if (first == "add" || first == "remove") {
    if (args.size() != 2) throw UsageError("remote " + first + " takes one robot");
    if (first == "remove") {
      if (!robots.remove(args[1])) {
        err << "benchscope-cli: error: " << args[1] << " is not in the robots list " << robots.file()
            << " (robots of the SSH config are listed while their Host entry is there)\n";
        return 1;
      }
      out << "removed " << args[1] << " from " << robots.file() << '\n';
      return 0;
    }
    remote::Robot r;
    if (const remote::Robot* stored = robots.find(args[1])) r = *stored;
    r.name = args[1];
    r.added = true;
    try {
      remote::check_destination(r.name);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    if (o.ssh_config) r.config_file = *o.ssh_config;
    if (o.remote_cli) r.remote_cli = *o.remote_cli;
    if (o.platform) r.platform = *o.platform;
    robots.put(r);
    out << "added " << r.name << " to " << robots.file() << "; `benchscope-cli remote " << r.name
        << " check` contacts it\n";
    return 0;
  }
  const remote::SshTarget target = target_for(robots, first, o);
  if (args.size() < 2) throw UsageError("expected what to do on " + first + ": check, jobs, fetch [ID] or a command");
  const std::string action = args[1];
  if (action == "check") {
    if (args.size() != 2) throw UsageError("remote HOST check takes no argument");
    return check_and_print(robots, target, out, err, true).ok ? 0 : 1;
  }
  if (action == "jobs") return jobs(target, out, err);
  if (action == "fetch") {
    if (args.size() > 3) throw UsageError("remote HOST fetch takes one job id at most");
    return fetch_remote(robots, target, args.size() == 3 ? args[2] : o.id.value_or(""), o, out, err);
  }
  return run_remote(robots, target, std::vector<std::string>(args.begin() + 1, args.end()), o, out, err);
}

const CommandRegistrar registrar({
    "remote",
    "run a measurement on a robot over SSH, follow it live and import its results with their provenance",
    "usage: benchscope-cli remote HOST COMMAND ARGS... [--workspace W.bsw] [--platform NAME] [--id ID]\n"
    "       benchscope-cli remote HOST check\n"
    "       benchscope-cli remote HOST fetch [ID] [--workspace W.bsw] [--platform NAME]\n"
    "       benchscope-cli remote HOST jobs\n"
    "       benchscope-cli remote list | add HOST | remove HOST\n"
    "         [--ssh-config FILE] [--remote-cli PATH] [--desk-quiet]\n"
    "  HOST: user@host or a Host of ~/.ssh/config; the system's ssh is used in batch mode (your keys, agent,\n"
    "  ProxyJump; never a password). COMMAND: run flops, record-power, run bandwidth, bench dnn, bench vision,\n"
    "  bench kernels, devices, sensors, headroom, pipeline (its frame files are the robot's; --synthetic needs\n"
    "  none), with their own options. Each run first checks the robot\n"
    "  (architecture, BenchScope there: missing or older than this one gives the command that installs it), then\n"
    "  runs COMMAND there as a job, prints its progress, points and power readings as they come and imports its\n"
    "  results into --workspace in one transaction, each with the robot's host name, architecture, devices, the\n"
    "  command line and its BenchScope version, as platform NAME (default: the robot's host name). Ctrl+C asks the\n"
    "  robot to stop; what it completed comes home. A dropped connection leaves the workspace as it was: the robot\n"
    "  keeps the job (~/.cache/benchscope/remote/ID), and fetch brings it home later. check: what the robot is and\n"
    "  can measure. jobs: the jobs kept there. list: the robots known here (the SSH config's Hosts and those added,\n"
    "  with their last contact and what ran there); add keeps --ssh-config, --remote-cli and --platform for one.",
    remote_command,
});

}  // namespace
}  // namespace bs::cli
