// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli headroom: will the robot's control loop keep its deadlines while it sees? Runs BenchScope's probe
// (a periodic thread, the balance loop's stand-in) idle and beside each chosen load, prints the latency
// distribution and the deadline misses per phase, records power where a sensor exists and stores the measurement.
#include <iostream>

#include <nlohmann/json.hpp>

#include "commands/headroom_grammar.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "headroom/command_load.h"
#include "headroom/headroom_args.h"
#include "headroom/headroom_import.h"
#include "headroom/headroom_json.h"
#include "headroom/headroom_print.h"
#include "headroom/headroom_run.h"
#include "headroom/loads/load_spec.h"
#include "power/power_args.h"
#include "store/workspace.h"
#include "vision/frames/frame_file.h"

namespace bs::cli {
namespace {

using namespace bs::headroom;

std::vector<std::unique_ptr<Load>> loads_from(const commands::HeadroomSettings& settings) {
  LoadOptions options;
  options.pipeline_detector = settings.detector;
  for (const std::string& path : settings.frames) {
    const vision::FrameFile f = vision::read_frame_file(path);
    options.frames.push_back(vision::to_8bit(f.mosaic, f.bit_depth));
    options.frames_note += (options.frames_note.empty() ? "" : ", ") + path;
  }
  std::vector<std::unique_ptr<Load>> loads;
  try {
    loads = make_loads(settings.loads, options);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--load: ") + e.what());
  }
  if (!settings.load_command.empty()) {
    try {
      loads.push_back(std::make_unique<CommandLoad>(split_command(settings.load_command)));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--load-command: ") + e.what());
    }
  }
  return loads;
}

std::string command_line(const std::vector<std::string>& raw) {
  std::string s = "benchscope-cli headroom";
  for (const std::string& a : raw) s += " " + a;
  return s;
}

int run_headroom_cmd(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const commands::HeadroomSettings settings = commands::headroom_from_words(raw);
  RunConfig config = settings.config;
  if (const std::string e = validate(config.probe); !e.empty()) throw UsageError(e);
  config.command = command_line(raw);
  std::vector<std::unique_ptr<Load>> owned = loads_from(settings);
  std::vector<Load*> loads;
  for (auto& l : owned) loads.push_back(l.get());

  const bool json = settings.json;
  std::ostream& info = json ? err : out;  // --json keeps stdout to the document alone
  if (config.probe.realtime) {
    const RealtimeRights rights = probe_realtime_rights();
    if (!rights.fifo) info << "benchscope-cli: " << rights.explanation << "\n";
  } else {
    info << "benchscope-cli: --no-rt: the probe runs as a normal thread; its numbers are not comparable with "
            "real-time ones\n";
  }
  std::unique_ptr<sensors::PowerRecorder> power;
  if (settings.power.sensor != "none")
    power = make_recorder(settings.power.sensor, settings.power.sysfs_root.value_or("/"),
                          settings.power.interval_ms.value_or(100), err, json);

  // Ctrl+C stops the running phase; progress names each phase as it starts.
  CancelToken token;
  std::string last_step;
  token.set_progress([&](double, std::string_view step) {
    if (interrupt_token().cancelled()) token.cancel();
    if (step != last_step) {
      last_step = std::string(step);
      err << "benchscope-cli: headroom phase '" << last_step << "'\n";
    }
  });
  RunOutput result;
  try {
    result = run_headroom(config, loads, power.get(), &token);
  } catch (const Cancelled&) {
    err << "benchscope-cli: headroom cancelled; nothing stored\n";
    return 1;
  }
  const HeadroomMeasurement& m = result.measurement;
  const nlohmann::json doc = to_json(m, true);
  if (json)
    out << doc.dump(2) << "\n";
  else
    print_headroom(out, m, "this run");
  if (const auto& ws_path = settings.workspace) {
    const std::int64_t id = bring_home(*ws_path, headroom_import(m, result.power, "benchscope-cli headroom"));
    info << "stored the measurement in " << *ws_path << " (import " << id << ")\n";
  }
  return 0;
}

const CommandRegistrar registrar({
    "headroom",
    "control-loop headroom: a periodic probe's wake-up latency and deadline misses, idle and beside loads",
    "usage: benchscope-cli headroom [--rate HZ] [--seconds S] [--threads N] [--computation-us C] [--deadline-us D]\n"
    "         [--cpu LIST] [--priority P] [--no-rt] [--limit-us L] [--load SPECS] [--load-command \"CMD ...\"]\n"
    "         [--detector hog|none|mobilenet-ssd|yolo-n] [--settle S] [--no-idle] [FRAME...]\n"
    "         [--platform NAME] [--workspace WS] [--json] [--power SENSOR|auto|none] [--power-interval-ms M]\n"
    "         [--sysfs-root DIR]\n"
    "  Measures whether a control loop keeps its deadlines while the robot's other work runs: the probe is measured\n"
    "  for --seconds S (default 20) idle, then beside each load in turn (each started --settle S seconds, default 1,\n"
    "  before its phase). --no-idle skips the idle phase.\n" +
        std::string(kProbeUsage) +
        "  Loads (--load, comma-separated; the same text names the phase):\n"
        "    pipeline[@FPS]       BenchScope's vision pipeline paced at FPS (default 30) on the sample frame or the\n"
        "                         FRAME files (1280x1024 mosaics), detection stage --detector (default hog)\n"
        "    dnn[:NET][@RATE]     the detector alone: mobilenet-ssd (default), yolo-n (random weights: their cost),\n"
        "                         or hog, back to back or paced at RATE inferences/s\n"
        "    flops[:W]            the FLOPS kernel (rotation, CPU SIMD) with W workers (default threads x 32)\n"
        "  --load-command runs an external command as the last load (no shell; e.g. stress-ng with 2 CPU workers and\n"
        "  its brief metrics), stopped with SIGINT; the bogo ops/s stress-ng then prints is its achieved rate.\n"
        "  Prints per phase and thread: rate, p50 / p99 / p99.9 / p99.99 / max latency (nearest rank over 1 us bins),\n"
        "  misses (% and count), the longest run of consecutive misses, n cycles, the load's achieved rate, mean\n"
        "  power, the policy obtained, and the kernel's real-time facts (release, PREEMPT_RT, isolcpus, nohz_full,\n"
        "  governor). --json prints the measurement (benchscope-headroom JSON with each thread's summary).\n"
        "  --workspace WS stores it (with the power trace) for the Headroom and Platforms views.\n" +
        kPowerUsage,
    run_headroom_cmd,
});

}  // namespace
}  // namespace bs::cli
