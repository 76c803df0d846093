// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli record-power: record the on-board power sensors for S seconds or while a command runs.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <ostream>
#include <thread>

#include "analysis/power/phase_energy.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "power/power_args.h"
#include "sensors/recording_csv.h"

extern char** environ;

namespace bs::cli {
namespace {

int record_power(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  // Everything after "--" is the command to run, untouched by our option parsing.
  const auto dashes = std::find(raw.begin(), raw.end(), std::string("--"));
  const std::vector<std::string> own(raw.begin(), dashes);
  const std::vector<std::string> command(dashes == raw.end() ? dashes : dashes + 1, raw.end());
  const ParsedArgs args =
      parse_args(own, {"--quiet"}, {"--out", "--sensor", "--interval-ms", "--sysfs-root", "--seconds"});
  if (!args.positional.empty())
    throw UsageError("unexpected argument '" + args.positional[0] + "' (a command goes after --)");
  const auto path = args.value("--out");
  if (!path) throw UsageError("--out FILE.csv is required");
  const bool timed = args.value("--seconds").has_value();
  if (timed == !command.empty()) throw UsageError("give either --seconds S or -- COMMAND ARGS...");
  const double seconds = args.number("--seconds", 0);
  if (timed && !(seconds > 0 && seconds <= 7 * 24 * 3600)) throw UsageError("--seconds must be > 0");
  const bool quiet = args.has("--quiet");
  const CancelToken& cancel = interrupt_token();  // installs the Ctrl+C handler before anything starts
  auto rec = make_recorder(args.value("--sensor").value_or("auto"), args.value("--sysfs-root").value_or("/"),
                           args.number("--interval-ms", 100), err, quiet);
  int status = 0;
  std::string what;
  if (timed) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!cancel.cancelled() && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    what = "recorded " + std::to_string(seconds) + " s";
  } else {
    std::vector<char*> argv;
    for (const auto& a : command) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    const double t0 = rec->now_s();
    if (const int e = posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ); e != 0) {
      rec->finish("");
      err << "benchscope-cli: error: cannot run '" << command[0] << "': " << std::strerror(e) << '\n';
      return 127;
    }
    // Ctrl+C reaches the command too (same process group); we wait for it and keep what was recorded.
    int ws = 0;
    while (waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
    }
    status = WIFEXITED(ws) ? WEXITSTATUS(ws) : WIFSIGNALED(ws) ? 128 + WTERMSIG(ws) : 1;
    rec->add_phase(command[0], t0, rec->now_s());
    what = "'" + command[0] + "' exited with status " + std::to_string(status);
  }
  std::string label = "record-power";
  for (const auto& a : command) label += " " + a;
  PowerTrace trace = rec->finish(label);
  sensors::save_recording_csv(*path, trace);
  if (cancel.cancelled())
    err << "benchscope-cli: interrupted; keeping the " << trace.time_s.size() << " samples recorded\n";
  if (!quiet) {
    const auto all = window_energy(trace, trace.time_s.empty() ? 0 : trace.time_s.front(),
                                   trace.time_s.empty() ? 0 : trace.time_s.back(), "whole recording");
    err << "benchscope-cli: " << what << "; wrote " << trace.time_s.size() << " samples to " << *path << '\n';
    if (all) {
      char line[160];
      std::snprintf(line, sizeof line, "%.3f J over %.3f s, mean %.3f W (%s, %s)\n", all->energy_j,
                    all->end_s - all->start_s, all->mean_power_w,
                    std::string(to_string(trace.provenance.measurement)).c_str(), trace.provenance.sensor.c_str());
      out << line;
    }
  }
  return timed ? (cancel.cancelled() ? 130 : 0) : status;
}

const CommandRegistrar registrar({
    "record-power",
    "record this computer's power sensors to a CSV, for S seconds or while a command runs",
    "usage: benchscope-cli record-power --out FILE.csv [--sensor ID[,ID...]|auto] [--interval-ms 100]\n"
    "         [--sysfs-root DIR] [--quiet] (--seconds S | -- COMMAND ARGS...)\n"
    "  auto (default): the board's or package's total (Jetson input rail VDD_IN/POM_5V_IN with the other rails\n"
    "  beside it; RAPL psys or package(s) with their sub-zones; else an NVML GPU or a hwmon power file).\n"
    "  The CSV starts with comments naming sensor, kind, host and the absolute start time; `benchscope-cli import`\n"
    "  reads it back as an on-board-sensor power trace. With a COMMAND, its exit status is passed on; Ctrl+C\n"
    "  stops and keeps what was recorded. Energy counters (RAPL, hwmon energy) become power as dE/dt, with the\n"
    "  counter's wraparound (max_energy_range_uj) added back.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        return record_power(args, out, err);
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << "\n(see benchscope-cli help record-power)\n";
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
