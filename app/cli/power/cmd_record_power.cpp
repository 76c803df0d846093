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
#include "commands/record_power_grammar.h"
#include "common/args.h"
#include "common/command.h"
#include "common/events_option.h"
#include "common/signals.h"
#include "power/power_args.h"
#include "power/recording_home.h"
#include "sensors/recording_csv.h"
#include "store/home_batch.h"
#include "store/workspace.h"

extern char** environ;

namespace bs::cli {
namespace {

int record_power(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err,
                 remote::EventWriter* events) {
  const commands::RecordPowerSettings s = commands::record_power_from_words(raw);
  const std::vector<std::string>& command = s.command;
  const auto& path = s.out;
  const auto& ws_path = s.workspace;
  std::ostream& text = events ? err : out;
  const bool timed = s.seconds.has_value();
  const double seconds = s.seconds.value_or(0);
  const bool quiet = s.quiet;
  const CancelToken& cancel = interrupt_token();  // installs the Ctrl+C handler before anything starts
  auto rec = make_recorder(s.sensor, s.sysfs_root.value_or("/"), s.interval_ms, err, quiet, events);
  int status = 0;
  std::string what;
  if (timed) {
    const auto start = std::chrono::steady_clock::now();
    const auto end = start + std::chrono::duration<double>(seconds);
    int reported = -1;
    while (!cancel.cancelled() && std::chrono::steady_clock::now() < end) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      const double f = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / seconds;
      if (events && static_cast<int>(f * 100) != reported) {  // at most a hundred progress events
        reported = static_cast<int>(f * 100);
        events->progress(std::min(f, 1.0), "recording");
      }
    }
    what = "recorded " + std::to_string(seconds) + " s";
  } else {
    std::vector<char*> argv;
    for (const auto& a : command) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    const double t0 = rec->now_s();
    // With --events, stdout carries events only: the command's own output goes to stderr.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (events) posix_spawn_file_actions_adddup2(&actions, 2, 1);
    const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (const int e = spawned; e != 0) {
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
  if (path) sensors::save_recording_csv(*path, trace);
  if (ws_path) {
    bring_home(*ws_path, recording_home(trace, "benchscope-cli record-power"));
  }
  if (cancel.cancelled())
    err << "benchscope-cli: interrupted; keeping the " << trace.time_s.size() << " samples recorded\n";
  if (!quiet) {
    const auto all = window_energy(trace, trace.time_s.empty() ? 0 : trace.time_s.front(),
                                   trace.time_s.empty() ? 0 : trace.time_s.back(), "whole recording");
    err << "benchscope-cli: " << what << "; wrote " << trace.time_s.size() << " samples to "
        << (path ? *path : *ws_path) << '\n';
    if (all) {
      char line[160];
      std::snprintf(line, sizeof line, "%.3f J over %.3f s, mean %.3f W (%s, %s)\n", all->energy_j,
                    all->end_s - all->start_s, all->mean_power_w,
                    std::string(to_string(trace.provenance.measurement)).c_str(), trace.provenance.sensor.c_str());
      text << line;
    }
  }
  if (events) {
    const auto all = window_energy(trace, trace.time_s.empty() ? 0 : trace.time_s.front(),
                                   trace.time_s.empty() ? 0 : trace.time_s.back(), "whole recording");
    events->write("result", {{"samples", trace.time_s.size()},
                             {"sensor", trace.provenance.sensor},
                             {"energy_j", all ? nlohmann::json(all->energy_j) : nlohmann::json(nullptr)},
                             {"mean_power_w", all ? nlohmann::json(all->mean_power_w) : nlohmann::json(nullptr)},
                             {"seconds", all ? nlohmann::json(all->end_s - all->start_s) : nlohmann::json(nullptr)},
                             {"out", path ? nlohmann::json(*path) : nlohmann::json(nullptr)},
                             {"workspace", ws_path ? nlohmann::json(*ws_path) : nlohmann::json(nullptr)}});
  }
  return timed ? (cancel.cancelled() ? 130 : 0) : status;
}

const CommandRegistrar registrar({
    "record-power",
    "record this computer's power sensors to a CSV, for S seconds or while a command runs",
    "usage: benchscope-cli record-power (--out FILE.csv | --workspace W.bsw) [--sensor ID[,ID...]|auto]\n"
    "         [--interval-ms 100] [--sysfs-root DIR] [--quiet] [--events jsonl] (--seconds S | -- COMMAND ARGS...)\n"
    "  auto (default): the board's or package's total (Jetson input rail VDD_IN/POM_5V_IN with the other rails\n"
    "  beside it; RAPL psys or package(s) with their sub-zones; else an NVML GPU or a hwmon power file).\n"
    "  The CSV starts with comments naming sensor, kind, host and the absolute start time; `benchscope-cli import`\n"
    "  reads it back as an on-board-sensor power trace. With a COMMAND, its exit status is passed on; Ctrl+C\n"
    "  stops and keeps what was recorded. Energy counters (RAPL, hwmon energy) become power as dE/dt, with the\n"
    "  counter's wraparound (max_energy_range_uj) added back. --workspace stores the trace there (as well).\n"
    "  --events jsonl: the event stream on stdout (progress, every reading, the result; docs/remote-events-v1.md)\n"
    "  and the text, with the command's own output, on stderr.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        return run_with_events("record-power", args, out,
                               [&](remote::EventWriter* events) { return record_power(args, out, err, events); });
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << "\n(see benchscope-cli help record-power)\n";
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
