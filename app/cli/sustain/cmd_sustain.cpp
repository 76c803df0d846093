// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli sustain (#53): will it hold its speed for a whole match? Runs one load without a break, takes its
// achieved rate, every clock and temperature (and power) per interval, reports each interval as it completes, and
// concludes: stability, throttling with its onset, sustained rate against the peak, time to steady state.
#include <iostream>
#include <set>

#include <nlohmann/json.hpp>

#include "commands/sustain_grammar.h"
#include "common/args.h"
#include "common/command.h"
#include "common/events_option.h"
#include "common/signals.h"
#include "headroom/loads/load_spec.h"
#include "power/power_args.h"
#include "store/workspace.h"
#include "sustain/sustain_import.h"
#include "sustain/sustain_json.h"
#include "sustain/sustain_runner.h"
#include "sustain/sustain_text.h"
#include "util/text.h"

namespace bs::cli {
namespace {

std::string command_line(const std::vector<std::string>& raw) {
  std::string s = "benchscope-cli sustain";
  for (const std::string& a : raw) s += " " + a;
  return s;
}

// A JSON line on stdout, flushed at once: the reader (a test, the robot's job agent relaying it to the desk as an
// event of stream v1) sees each interval as it completes.
void json_line(std::ostream& out, const char* type, double t, nlohmann::json fields) {
  nlohmann::json line = {{"v", 1}, {"type", type}, {"t", t}};
  line.update(fields);
  out << line.dump() << std::endl;
}

// `events` (--events jsonl, a robot's job): the intervals and the result go out as events of stream v1 on stdout,
// between the stream's start and end, and the text goes to `out`, which is then stderr.
int run_sustain_with(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err,
                     remote::EventWriter* events) {
  const commands::SustainSettings s = commands::sustain_from_words(raw);
  headroom::LoadOptions options;
  options.pipeline_detector = s.detector;
  std::vector<std::unique_ptr<headroom::Load>> loads;
  try {
    loads = headroom::make_loads(s.load, options);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--load: ") + e.what());
  }
  if (loads.size() != 1) throw UsageError("--load takes one load");
  headroom::Load& load = *loads.front();

  const std::string root = s.sysfs_root.value_or("/");
  const sustain::SysfsSampler sampler(root);
  std::unique_ptr<sensors::PowerRecorder> power;
  if (s.power.sensor != "none")
    power = make_recorder(s.power.sensor, root, s.power.interval_ms.value_or(100), err, s.json);

  sustain::RunConfig config;
  config.seconds = s.seconds;
  config.interval_s = s.interval_s;
  config.platform = s.platform;
  config.command = command_line(raw);
  for (const std::string& n : sampler.not_exposed()) err << "benchscope-cli: not exposed: " << n << "\n";
  err << "benchscope-cli: sustain " << load.name() << " for " << commands::number_word(s.seconds) << " s, every "
      << commands::number_word(s.interval_s) << " s: " << sampler.clocks().size() << " clock(s), "
      << sampler.temperatures().size() << " temperature(s)\n";

  CancelToken token;
  token.set_progress([&](double, std::string_view) {
    if (interrupt_token().cancelled()) token.cancel();
  });
  std::set<std::string> warned;
  const auto on_interval = [&](const SustainRun& so_far, std::size_t i, const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings)
      if (warned.insert(w).second) err << "benchscope-cli: warning: " << w << "\n";
    err << "benchscope-cli: sustain " << sustain::interval_line(so_far, i) << std::endl;
    if (events)
      events->write("interval", sustain::interval_json(so_far, i));
    else if (s.json)
      json_line(out, "interval", so_far.t_s[i], sustain::interval_json(so_far, i));
  };
  sustain::RunOutput result;
  try {
    result = sustain::run_sustain(config, load, sampler, power.get(), &token, on_interval);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  SustainRun& run = result.run;
  for (const std::string& w : result.warnings) err << "benchscope-cli: warning: " << w << "\n";
  if (result.cancelled) err << "benchscope-cli: sustain cancelled after " << run.t_s.size() << " interval(s)\n";
  if (run.t_s.empty()) {
    err << "benchscope-cli: no interval completed; nothing stored\n";
    return 1;
  }
  sustain::AnalysisOptions ao;
  ao.stable_percent = s.stable_percent;
  ao.throttle_threshold = s.throttle_threshold;
  const sustain::SustainAnalysis analysis = sustain::analyse(run, ao);
  if (s.json || events) {
    nlohmann::json doc = sustain::result_json(run, analysis);
    doc["load_notes"] = result.load_notes;
    doc["warnings"] = result.warnings;
    doc["cancelled"] = result.cancelled;
    if (events)
      events->write("result", std::move(doc));
    else
      json_line(out, "result", run.t_s.back(), std::move(doc));
  } else {
    out << "Sustained run: " << run.label << " on " << run.platform << " (" << run.t_s.size() << " intervals of "
        << fixed(run.interval_s, 2) << " s)\n";
    for (const sustain::SummaryRow& row : sustain::summary_rows(run, analysis)) {
      std::string label = row.label + ":";
      label.resize(std::max<std::size_t>(label.size() + 1, 17), ' ');
      out << "  " << label << row.value << "\n";
    }
    for (const std::string& n : result.load_notes) out << "  load: " << n << "\n";
  }
  if (const auto& ws_path = s.workspace) {
    const std::int64_t id = bring_home(*ws_path, sustain::sustain_import(run, result.power, "benchscope-cli sustain"));
    (s.json ? err : out) << "stored the sustained run in " << *ws_path << " (import " << id << ")\n";
  }
  return result.cancelled ? 1 : 0;
}

int run_sustain_cmd(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  return run_with_events("sustain", raw, out, [&](remote::EventWriter* events) {
    return run_sustain_with(raw, events ? err : out, err, events);
  });
}

const CommandRegistrar registrar({
    "sustain",
    "sustained performance: a load's rate, clocks, temperatures and power per interval; stability and throttling",
    "usage: benchscope-cli sustain [--load flops[:W]|pipeline[@FPS]|dnn[:NET][@RATE]] [--seconds S] [--interval I]\n"
    "         [--detector hog|none|mobilenet-ssd|yolo-n] [--stable-percent P] [--throttle-threshold F]\n"
    "         [--platform NAME] [--workspace WS] [--json] [--power SENSOR|auto|none] [--power-interval-ms M]\n"
    "         [--sysfs-root DIR] [--events jsonl]\n"
    "  Runs one load without a break for --seconds S (default 600: a RoboCup half) and records, every --interval I\n"
    "  seconds (default 1), its achieved rate (GFLOPS, fps or inferences/s), every CPU clock (cpufreq) and devfreq\n"
    "  clock against its maximum, every thermal zone (with its lowest passive/hot/critical trip point) and hwmon\n"
    "  temperature, read under --sysfs-root DIR (default /), and the mean power of each interval with --power.\n"
    "  Each interval is printed on stderr as it completes. Then: stability = worst / best interval rate (stable at\n"
    "  >= --stable-percent, default 97, as 3DMark's stress tests), throttling = a clock below --throttle-threshold\n"
    "  (default 0.8, as nvbench) of its maximum or a zone at its trip point, with its onset and what throttled\n"
    "  (unknown when nothing is exposed), the sustained rate (mean of the last third) against the peak, the time to\n"
    "  steady state (every later interval within 3 % of the sustained rate) and the first slow interval.\n"
    "  --json: one JSON line per interval on stdout ({\"v\":1,\"type\":\"interval\",...}) as it completes, then the\n"
    "  result as one line ({\"v\":1,\"type\":\"result\",...}: intervals, stability_percent, throttle, ...).\n"
    "  --workspace WS stores the run (with the power trace).\n" +
        std::string(kPowerUsage) + "\n" + kEventsUsage,
    run_sustain_cmd,
});

}  // namespace
}  // namespace bs::cli
