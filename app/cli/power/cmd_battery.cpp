// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli battery: battery life under a constant load or a mission profile, with the paper's
// constant-power model (t = V x capacity / P_mean) or a LiPo discharge curve with internal resistance.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "analysis/platform/platform_battery.h"
#include "analysis/power/battery.h"
#include "analysis/power/power_stats.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "power/power_import.h"
#include "store/battery_preset_store.h"
#include "store/workspace.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

// The preset (built-in, or saved in --workspace, which may replace a built-in of the same name), or without
// --preset the setup the workspace's Battery tab shows (as it was last edited there: the same numbers as the GUI),
// then the command line's overrides.
BatterySetup setup_from_args(const ParsedArgs& args, const Workspace* ws) {
  const std::string preset_name = args.value("--preset").value_or("paper-4s-3850");
  std::optional<BatterySetup> found;
  if (ws && !args.value("--preset")) found = battery_tab_setup(*ws);
  if (!found) found = find_battery_setup(ws, preset_name);
  if (!found) {
    std::string names;
    for (const BatterySetup& p : all_battery_setups(ws)) names += (names.empty() ? "" : ", ") + p.pack.name;
    throw UsageError("unknown --preset '" + preset_name + "' (known: " + names + ")");
  }
  BatterySetup setup = *found;
  BatteryPack& pack = setup.pack;
  if (args.value("--volts")) {
    const double volts = args.number("--volts", 0);
    if (!(volts > 0)) throw UsageError("--volts must be > 0");
    // A LiPo pack's nominal voltage is 3.7 V per series cell; the cell count follows from it.
    pack.cells_series = std::max(1, static_cast<int>(std::lround(volts / 3.7)));
    pack.nominal_cell_v = volts / pack.cells_series;
    pack.name = "custom";
  }
  if (args.value("--capacity-mah")) {
    pack.capacity_ah = args.number("--capacity-mah", 0) / 1000;
    if (!(pack.capacity_ah > 0)) throw UsageError("--capacity-mah must be > 0");
    pack.name = "custom";
  }
  if (args.value("--internal-mohm")) {
    pack.internal_resistance_ohm = args.number("--internal-mohm", 0) / 1000;
    if (!(pack.internal_resistance_ohm >= 0)) throw UsageError("--internal-mohm must be >= 0");
  }
  if (args.value("--cutoff-cell-volts")) {
    pack.cutoff_cell_v = args.number("--cutoff-cell-volts", 0);
    if (!(pack.cutoff_cell_v >= 0 && pack.cutoff_cell_v < 4.2))
      throw UsageError("--cutoff-cell-volts must be in [0, 4.2)");
  }
  if (const auto model = args.value("--model")) {
    if (*model == "lipo")
      setup.model = BatteryModel::Lipo;
    else if (*model == "constant-power")
      setup.model = BatteryModel::ConstantPower;
    else
      throw UsageError("--model must be constant-power or lipo");
  }
  setup.depth_of_discharge = args.number("--dod", setup.depth_of_discharge);
  if (!(setup.depth_of_discharge > 0 && setup.depth_of_discharge <= 1)) throw UsageError("--dod must be in (0, 1]");
  setup.extra_load_w = args.number("--extra-load", setup.extra_load_w);
  if (!(setup.extra_load_w >= 0)) throw UsageError("--extra-load must be >= 0 W");
  if (const auto mission = args.value("--mission")) setup.mission = *mission;
  return setup;
}

// --workspace WS without a load: every platform's computer at the mean power of its log, with the extra load and
// the mission's phases on top (analysis/platform_battery.h, what the GUI's Battery tab shows).
int per_platform(const LoadedData& data, const BatterySetup& setup, const DischargeOptions& options, bool json,
                 std::ostream& out) {
  std::vector<PlatformBattery> rows;
  try {
    rows = platform_battery(data.power_traces, setup.pack, options, setup.extra_load_w, setup.mission);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (rows.empty()) throw std::runtime_error("the workspace has no power log with a known power");
  const BatteryPack& pack = setup.pack;
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const PlatformBattery& b : rows)
      list.push_back({{"platform", b.platform},
                      {"computer_mean_w", b.computer_mean_w},
                      {"mean_load_w", b.mission.mean_load_w()},
                      {"runtime_min", b.result.runtime_s / 60},
                      {"runtime_h", b.result.runtime_s / 3600},
                      {"stop_reason", b.result.stop_reason},
                      {"lipo_runtime_min", b.lipo.runtime_s / 60}});
    out << nlohmann::json{{"format", "benchscope-battery-platforms"},
                          {"version", 1},
                          {"preset", pack.name},
                          {"model", std::string(to_string(options.model))},
                          {"model_label", rows[0].result.model_label},
                          {"nominal_v", pack.nominal_v()},
                          {"capacity_mah", pack.capacity_ah * 1000},
                          {"usable_fraction", options.depth_of_discharge},
                          {"extra_load_w", setup.extra_load_w},
                          {"mission", setup.mission},
                          {"platforms", list}}
               .dump(2)
        << '\n';
    return 0;
  }
  char line[512];
  std::snprintf(line, sizeof line,
                "battery %s: %.1f V (%dS) x %.0f mAh = %.2f Wh, usable %.0f %%, extra load %g W%s%s\n",
                pack.name.c_str(), pack.nominal_v(), pack.cells_series, pack.capacity_ah * 1000, pack.nominal_wh(),
                options.depth_of_discharge * 100, setup.extra_load_w, setup.mission.empty() ? "" : ", mission ",
                setup.mission.c_str());
  out << line << "model: " << rows[0].result.model_label << '\n';
  std::snprintf(line, sizeof line, "%-20s %14s %14s %14s  %s\n", "platform", "computer (W)", "total (W)",
                "runtime (min)", "ends by");
  out << line;
  for (const PlatformBattery& b : rows) {
    std::snprintf(line, sizeof line, "%-20s %14.2f %14.2f %14.2f  %s\n", b.platform.c_str(), b.computer_mean_w,
                  b.mission.mean_load_w(), b.result.runtime_s / 60, b.result.stop_reason.c_str());
    out << line;
  }
  return 0;
}

int run_battery(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const ParsedArgs args = parse_args(raw, {"--json"},
                                     {"--preset", "--volts", "--capacity-mah", "--internal-mohm", "--cutoff-cell-volts",
                                      "--watts", "--power-log", "--supply-volts", "--mission", "--model", "--dod",
                                      "--extra-load", "--step", "--series", "--workspace", "--save-preset"});
  std::unique_ptr<Workspace> ws;
  if (const auto path = args.value("--workspace")) {
    // Only an existing workspace: opening a missing path would create an empty one.
    if (!looks_like_workspace(*path)) throw UsageError("--workspace: " + *path + " is not a BenchScope workspace");
    ws = std::make_unique<Workspace>(
        *path, args.value("--save-preset") ? Workspace::OpenMode::ReadWrite : Workspace::OpenMode::ReadOnly);
    warn_damage(*ws);
  }
  const BatterySetup setup = setup_from_args(args, ws.get());
  const BatteryPack& pack = setup.pack;
  DischargeOptions options;
  options.model = setup.model;
  options.depth_of_discharge = setup.depth_of_discharge;
  options.step_s = args.number("--step", 1.0);
  if (!(options.step_s >= 1e-3 && options.step_s <= 3600)) throw UsageError("--step must be in [0.001, 3600] s");
  const double extra = setup.extra_load_w;
  if (const auto name = args.value("--save-preset")) {
    if (!ws) throw UsageError("--save-preset needs --workspace");
    BatterySetup saved = setup;
    saved.pack.name = *name;
    try {
      save_battery_setup(*ws, saved);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--save-preset: ") + e.what());
    }
    err << "saved battery preset '" << *name << "' in " << ws->path() << '\n';
  }
  const bool no_load = !args.value("--watts") && !args.value("--power-log");
  if (ws && no_load)
    return per_platform(load_inputs({ws->path()}, interrupt_token()), setup, options, args.has("--json"), out);
  int given = (args.value("--watts") ? 1 : 0) + (args.value("--power-log") ? 1 : 0) + (args.value("--mission") ? 1 : 0);
  if (given == 0 && !setup.mission.empty()) given = 1;  // the preset's own mission
  if (given != 1)
    throw UsageError(
        "give exactly one of --watts P, --power-log FILE or --mission SPEC (or --workspace WS alone: per platform)");

  Mission mission;
  std::string source;
  if (args.value("--watts")) {
    const double watts = args.number("--watts", 0);
    if (!(watts > 0)) throw UsageError("the load must be > 0 W");
    mission = constant_load(watts, extra);
    source = "given";
  } else if (const auto log = args.value("--power-log")) {
    ParseOptions import_options;
    if (args.value("--supply-volts")) {
      import_options.supply_voltage_v = args.number("--supply-volts", 0);
      if (!(*import_options.supply_voltage_v > 0)) throw UsageError("--supply-volts must be > 0");
    }
    const ImportBatch batch = import_power_log(*log, import_options, interrupt_token());
    for (const std::string& w : batch.warnings) err << "warning: " << w << '\n';
    const PowerStats s = power_stats(batch.power_traces.at(0));
    if (!s.power_w) throw std::runtime_error(*log + ": current-only log; give --supply-volts");
    mission = constant_load(s.power_w->summary.mean, extra);
    source = "mean of " + *log + " (" + std::string(to_string(s.power_source)) + ")";
  } else {
    try {
      mission = parse_mission(setup.mission);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--mission: ") + e.what());
    }
    mission.extra_load_w = extra;
    source = "mission of " + std::to_string(mission.phases.size()) + " phases, repeated";
  }
  if (!(mission.mean_load_w() > 0)) throw UsageError("the load must be > 0 W");
  const DischargeResult r = simulate_discharge(pack, mission, options);
  // The paper's figure for the same pack and mean load, shown beside the LiPo model's for comparison.
  DischargeOptions paper_options = options;
  paper_options.model = BatteryModel::ConstantPower;
  const DischargeResult paper = simulate_discharge(pack, mission, paper_options);

  if (const auto series_path = args.value("--series")) {
    std::ofstream f(*series_path);
    if (!f) throw std::runtime_error("cannot write " + *series_path);
    f << "# state of charge over time, " << r.model_label << "\ntime_s,soc,terminal_V,current_A,load_W,phase\n";
    for (const DischargePoint& p : r.series)
      f << p.t_s << ',' << p.soc << ',' << p.terminal_v << ',' << p.current_a << ',' << p.load_w << ','
        << mission.phases[p.phase].name << '\n';
  }
  if (args.has("--json")) {
    nlohmann::json phases = nlohmann::json::array();
    for (const MissionPhase& p : mission.phases)
      phases.push_back({{"name", p.name}, {"seconds", p.duration_s}, {"load_w", p.load_w}});
    out << nlohmann::json{{"format", "benchscope-battery"},
                          {"version", 2},
                          {"model", std::string(to_string(options.model))},
                          {"model_label", r.model_label},
                          {"preset", pack.name},
                          {"nominal_v", pack.nominal_v()},
                          {"cells_series", pack.cells_series},
                          {"capacity_mah", pack.capacity_ah * 1000},
                          {"internal_resistance_ohm", pack.internal_resistance_ohm},
                          {"usable_fraction", options.depth_of_discharge},
                          {"load_source", source},
                          {"mean_load_w", mission.mean_load_w()},
                          {"extra_load_w", mission.extra_load_w},
                          {"mission", phases},
                          {"runtime_h", r.runtime_s / 3600},
                          {"runtime_min", r.runtime_s / 60},
                          {"stop_reason", r.stop_reason},
                          {"energy_wh", r.energy_wh},
                          {"peak_current_a", r.peak_current_a},
                          {"min_terminal_v", r.min_terminal_v},
                          {"constant_power_runtime_min", paper.runtime_s / 60}}
               .dump(2)
        << '\n';
    return 0;
  }
  char line[512];
  std::snprintf(line, sizeof line, "battery %.1f V (%dS) x %.0f mAh = %.2f Wh, usable %.0f %%\n", pack.nominal_v(),
                pack.cells_series, pack.capacity_ah * 1000, pack.nominal_wh(), options.depth_of_discharge * 100);
  out << line;
  out << "load " << format_number("%.2f", mission.mean_load_w()) << " W mean (" << source << ")";
  if (mission.extra_load_w > 0) out << ", incl. " << format_number("%g", mission.extra_load_w) << " W extra load";
  out << '\n';
  std::snprintf(line, sizeof line, "runtime %.2f min (%.2f h): %s\n  model: %s\n", r.runtime_s / 60, r.runtime_s / 3600,
                r.stop_reason.c_str(), r.model_label.c_str());
  out << line;
  if (options.model == BatteryModel::ConstantPower) {
    out << "  t = V x capacity x DoD / P (current rises as the voltage falls, power stays constant)\n";
  } else {
    std::snprintf(line, sizeof line,
                  "  energy delivered %.2f Wh, peak current %.2f A, lowest terminal voltage %.2f V\n"
                  "  the paper's constant-power model for the same load: %.2f min\n",
                  r.energy_wh, r.peak_current_a, r.min_terminal_v, paper.runtime_s / 60);
    out << line;
  }
  return 0;
}

const CommandRegistrar registrar({
    "battery",
    "battery life under a load or mission (the paper's constant-power model, or a LiPo curve)",
    "usage: benchscope-cli battery [--workspace WS] [--preset NAME] [--volts V] [--capacity-mah C]\n"
    "         (--watts P | --power-log FILE [--supply-volts V] | --mission name:s:W,...)\n"
    "       benchscope-cli battery --workspace WS [--preset NAME] [--mission SPEC] [options]   (per platform)\n"
    "         [--model constant-power|lipo] [--dod F] [--extra-load W] [--internal-mohm R] [--cutoff-cell-volts V]\n"
    "         [--step S] [--series FILE.csv] [--json]\n"
    "  Default pack: the paper's 14.8 V 4S LiPo of 3850 mAh (--preset paper-4s-3850; also 4s-5000, 3s-2200,\n"
    "  6s-10000). constant-power: t = V x capacity x DoD / P_mean (the paper). lipo: open-circuit voltage vs state\n"
    "  of charge, internal resistance and a cut-off voltage per cell, constant-power load in --step time steps.\n"
    "  --dod: usable depth of discharge. --extra-load: a parallel load such as servos (the paper's robot: up to\n"
    "  225 W). --mission: phases repeated until empty, e.g. idle:60:15,walk:30:120. --series: state of charge\n"
    "  over time as CSV.\n"
    "  --workspace WS: also the presets saved in the workspace (GUI Battery tab, or --save-preset NAME, which saves\n"
    "  the pack and options given here); their depth of discharge, extra load, model and mission are the defaults.\n"
    "  Without --watts/--power-log: runtime per platform, each computer at the mean power of its log, with the\n"
    "  extra load and the mission's phases on top.",
    run_battery,
});

}  // namespace
}  // namespace bs::cli
