// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli job: the robot's side of `benchscope-cli remote` (started by the desk over SSH, rarely by hand).
// `job run` runs one measurement as a job whose results stay in ~/.cache/benchscope/remote/<id>/ and streams its
// events; `job fetch` sends a finished job again; `job list` lists them; `job probe` describes this computer.
#include <sys/utsname.h>

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands/remote_commands.h"
#include "common/args.h"
#include "common/command.h"
#include "common/events_option.h"
#include "kernels/cpu_args.h"
#include "kernels/sweep.h"
#include "remote/events.h"
#include "remote/job_agent.h"
#include "sensors/discovery.h"
#include "util/host_clock.h"

namespace bs::cli {

using commands::find_remote_command;
using commands::remote_command_names;
using commands::RemoteCommand;
namespace {

// The command as main() would run it, in the job's forked child: its text to stderr (stdout carries events).
int run_in_job(const RemoteCommand& rc, std::vector<std::string> args, const std::string& job_dir) {
  // The words the desk checked (commands::check_remote_words adds the same options).
  args = commands::job_words(rc, std::move(args), job_dir + "/" + remote::kJobResultFile);
  const Command* command = find_command(args[0]);
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  int status = 1;
  try {
    if (rc.native_events) {
      status = command->run(rest, std::cout, std::cerr);
    } else {
      status = with_event_stream(rc.name, rest, std::cout,
                                 [&](remote::EventWriter&) { return command->run(rest, std::cerr, std::cerr); });
    }
  } catch (const UsageError& e) {
    std::cerr << "benchscope-cli: error: " << e.what() << '\n';
    status = 2;
  } catch (const std::exception& e) {
    std::cerr << "benchscope-cli: error: " << e.what() << '\n';
    status = 1;
  }
  std::cout.flush();
  std::cerr.flush();
  return status;
}

std::string os_name() {
  std::ifstream in("/etc/os-release");
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("PRETTY_NAME=")) {
      std::string v = line.substr(12);
      if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
      return v;
    }
  return {};
}

// One "robot" event: what this computer is and can measure, for the desk's first contact.
int probe(const ParsedArgs& args, std::ostream& out) {
  remote::EventWriter ev(out);
  const kernels::CpuInfo cpu = cpu_from_args(args);
  nlohmann::json backends = nlohmann::json::array();
  for (const kernels::Backend& b : kernels::available_backends(cpu))
    backends.push_back({{"id", b.id},
                        {"label", b.label},
                        {"device", b.device_name},
                        {"kind", std::string(to_string(b.kind))},
                        {"theoretical_peak_flops", b.theoretical_peak_flops}});
  const std::string root = args.value("--sysfs-root").value_or("/");
  sensors::SensorSet set = sensors::find_sensors({root, sensors::default_nvml_library()});
  nlohmann::json sensors_json = nlohmann::json::array();
  for (const auto& s : set.sensors) {
    const sensors::SensorInfo& i = s->info();
    sensors_json.push_back({{"id", i.id},
                            {"label", i.label},
                            {"kind", std::string(to_string(i.kind))},
                            {"readable", i.readable},
                            {"board_total", i.board_total},
                            {"reason", i.reason}});
  }
  std::string note;
  try {
    note = sensors::select_sensors(set, "auto").note;
  } catch (const std::exception& e) {
    note = std::string("no power recording: ") + e.what();
  }
  utsname u{};
  uname(&u);
  ev.write("robot", {{"host", host_name()},
                     {"arch", std::string(u.machine)},
                     {"cli_version", BENCHSCOPE_VERSION},
                     {"os", os_name()},
                     {"cpu", cpu.model},
                     {"backends", backends},
                     {"sensors", sensors_json},
                     {"sensor_note", note},
                     {"jobs_dir", args.value("--jobs-dir").value_or(remote::default_jobs_dir())}});
  return 0;
}

int job_command(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const auto dashes = std::find(raw.begin(), raw.end(), std::string("--"));
  const std::vector<std::string> own(raw.begin(), dashes);
  std::vector<std::string> command(dashes == raw.end() ? dashes : dashes + 1, raw.end());
  const ParsedArgs args = parse_args(own, {}, {"--id", "--jobs-dir", "--sysfs-root", "--isa", "--name", "--size"});
  if (args.positional.size() != 1) throw UsageError("expected job run, job put, job fetch, job list or job probe");
  const std::string& what = args.positional[0];
  const std::string jobs_dir = args.value("--jobs-dir").value_or(remote::default_jobs_dir());
  if (what == "probe") return probe(args, out);
  if (what == "list") return remote::list_jobs_agent(jobs_dir, out);
  if (what == "fetch") return remote::fetch_job_agent(jobs_dir, args.value("--id").value_or(""), out);
  if (what == "put") {
    const auto id = args.value("--id");
    const auto name = args.value("--name");
    if (!id || !name || !args.value("--size")) throw UsageError("job put needs --id ID --name NAME --size BYTES");
    const double size = args.number("--size", 0);
    if (size < 0 || size != static_cast<double>(static_cast<std::uint64_t>(size)))
      throw UsageError("--size must be a whole number of bytes");
    return remote::put_job_input(jobs_dir, *id, *name, static_cast<std::uint64_t>(size), 0, err);
  }
  if (what != "run") throw UsageError("unknown job action '" + what + "'");
  const auto id = args.value("--id");
  if (!id) throw UsageError("job run needs --id ID");
  const auto rc = find_remote_command(command);
  if (!rc)
    throw UsageError("a job runs one of: " + remote_command_names() + " (got '" +
                     (command.empty() ? std::string() : command[0]) + "')");
  remote::AgentJob job;
  job.id = *id;
  job.jobs_dir = jobs_dir;
  job.command = command;
  job.body = [rc = *rc, command](const std::string& dir) { return run_in_job(rc, command, dir); };
  return remote::run_job_agent(job, out, err);
}

const CommandRegistrar registrar({
    "job",
    "the robot's side of `remote`: run a measurement as a job and stream its events (started over SSH)",
    "usage: benchscope-cli job run --id ID [--jobs-dir DIR] -- COMMAND ARGS...\n"
    "       benchscope-cli job put --id ID --name NAME --size BYTES [--jobs-dir DIR] < FILE\n"
    "       benchscope-cli job fetch [--id ID] [--jobs-dir DIR]\n"
    "       benchscope-cli job list [--jobs-dir DIR]\n"
    "       benchscope-cli job probe [--sysfs-root DIR] [--isa avx512|avx2|sse4|generic]\n"
    "  What `benchscope-cli remote HOST ...` starts on the robot through ssh; its output is the event stream of\n"
    "  docs/remote-events-v1.md. run: runs COMMAND (run flops, record-power, run bandwidth, bench dnn, bench\n"
    "  vision, bench kernels, devices, sensors, headroom, pipeline) with its results in DIR/ID/result.bsw\n"
    "  (DIR: --jobs-dir, default $XDG_CACHE_HOME/benchscope/remote or ~/.cache/benchscope/remote), then sends\n"
    "  them as file events. A line 'cancel' on stdin stops it as Ctrl+C does (the completed part is sent); the end\n"
    "  of stdin (the connection dropped) stops it and everything it started. fetch: sends a finished job again\n"
    "  (the newest without --id). put: receives one input file of job ID before it runs (the desk's frames,\n"
    "  lens or model: BYTES bytes on stdin into DIR/ID/inputs/NAME; nothing half-written is kept).\n"
    "  list: one job event per job. probe: one robot event (host, architecture, version, backends, sensors).",
    job_command,
});

}  // namespace
}  // namespace bs::cli
