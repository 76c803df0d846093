// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/platform_args.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>

#include "store/battery_preset_store.h"
#include "store/decision_inputs.h"
#include "store/decision_store.h"
#include "util/text.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

// The decision inputs the workspace holds (store/decision_inputs.h: the same rule as the GUI's Platforms tab), when
// the command reads exactly one workspace and is not told to ignore them; the defaults otherwise. The workspace
// stays open for the --battery lookup (its own presets) and is closed on return.
struct FromWorkspace {
  std::unique_ptr<const Workspace> ws;
  DecisionInputs in;
};

FromWorkspace read_inputs(const ParsedArgs& args) {
  FromWorkspace f;
  if (args.has("--no-stored") || args.positional.size() != 1 || !looks_like_workspace(args.positional[0])) {
    f.in = decision_inputs(nullptr);
    return f;
  }
  f.ws = std::make_unique<const Workspace>(args.positional[0], Workspace::OpenMode::ReadOnly);
  try {
    f.in = decision_inputs(f.ws.get());
  } catch (const WorkspaceError& e) {
    if (e.kind() != WorkspaceError::Kind::Corrupt) throw;
    throw WorkspaceError(e.kind(), std::string(e.what()) + " (--no-stored ignores it)");
  }
  return f;
}

}  // namespace

const std::set<std::string>& platform_value_options() {
  static const std::set<std::string> names{"--budget",  "--min-fps",      "--min-runtime",
                                           "--battery", "--extra-load",   "--supply-volts",
                                           "--mission", "--require-loop", "--require-sustained"};
  return names;
}

PlatformArgs parse_platform_args(const ParsedArgs& args) {
  PlatformArgs p;
  const FromWorkspace from = read_inputs(args);
  const DecisionInputs& in = from.in;
  std::vector<std::string> taken;  // what came from the workspace, in words
  BatterySetup battery = in.battery;
  if (const auto name = args.value("--battery")) {
    // A built-in pack or one the workspace saved (the Battery tab's presets), with its depth of discharge.
    const auto found = find_battery_setup(from.ws.get(), *name);
    if (!found) {
      std::string names;
      for (const BatterySetup& b : all_battery_setups(from.ws.get()))
        names += (names.empty() ? "" : ", ") + b.pack.name;
      throw UsageError("unknown --battery '" + *name + "' (known: " + names + ")");
    }
    battery = *found;
  } else if (in.battery_from_tab || !in.battery_choice.empty()) {
    taken.push_back("battery " + battery.pack.name +
                    (!in.battery_from_tab ? std::string()
                     : in.battery_missing ? " (the Battery tab's pack; preset " + in.battery_choice + " is gone)"
                                          : std::string(" (the Battery tab's pack)")));
  }
  p.pack = battery.pack;
  p.options.battery_nominal_v = p.pack.nominal_v();
  p.options.battery_capacity_ah = p.pack.capacity_ah;
  p.options.usable_fraction = battery.depth_of_discharge;
  p.options.extra_load_w = args.number("--extra-load", in.options.extra_load_w);
  if (!(p.options.extra_load_w >= 0)) throw UsageError("--extra-load must be >= 0 W");
  if (!args.value("--extra-load") && in.options.extra_load_w > 0) taken.push_back("parallel load");
  std::optional<std::string> mission = args.value("--mission");
  if (!mission && !in.options.mission.empty()) {
    mission = in.options.mission;
    taken.push_back("mission " + in.options.mission);
  }
  if (mission) {
    try {
      parse_mission(*mission);  // name the option in the error, before any data is loaded
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string(args.value("--mission") ? "--mission: " : "the workspace's stored mission: ") +
                       e.what());
    }
    p.options.mission = *mission;
  }
  if (args.value("--supply-volts")) p.options.supply_v = args.number("--supply-volts", 0);
  // Constraints: the command line's replace the stored ones as a whole (one set of constraints, never a mix).
  const bool given = args.value("--budget") || args.value("--min-fps") || args.value("--min-runtime") ||
                     args.value("--require-loop") || args.value("--require-sustained");
  if (args.value("--budget")) p.constraints.power_budget_w = args.number("--budget", 0);
  if (args.value("--min-fps")) p.constraints.min_fps = args.number("--min-fps", 0);
  if (args.value("--min-runtime")) p.constraints.min_runtime_h = args.number("--min-runtime", 0) / 60.0;  // minutes
  if (const auto loop = args.value("--require-loop")) {
    try {
      p.loop = headroom::parse_loop_requirement(*loop);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--require-loop: ") + e.what());
    }
  }
  if (const auto sustained = args.value("--require-sustained")) {
    try {
      p.sustained = sustain::parse_sustain_requirement(*sustained);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--require-sustained: ") + e.what());
    }
  }
  if (!given && in.stored && in.stored->constrained()) {
    p.constraints = in.constraints;
    p.loop = in.loop;
    p.sustained = in.sustained;
    taken.insert(taken.begin(), describe_constraints(*in.stored));
  }
  p.library = in.candidates;
  p.chosen_log_platforms = in.chosen_log_platforms;
  p.battery_choice = args.value("--battery").value_or(in.battery_choice);
  p.stored = join(taken, "; ");
  return p;
}

StoredDecision decision_to_store(const PlatformArgs& p) {
  StoredDecision d;
  d.power_budget_w = p.constraints.power_budget_w;
  d.min_fps = p.constraints.min_fps;
  if (p.constraints.min_runtime_h) d.min_runtime_min = *p.constraints.min_runtime_h * 60;
  d.battery = p.battery_choice;
  d.extra_load_w = p.options.extra_load_w;
  d.mission = p.options.mission;
  d.candidates = p.library;
  if (p.loop) d.loop = p.loop->text;
  if (p.sustained) d.sustained = p.sustained->text;
  return d;
}

std::size_t use_log(std::vector<PowerTrace>& traces, const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
    throw UsageError("--use-log expects PLATFORM=LOG (a power log's name, as `power` lists it), got '" + spec + "'");
  const std::string platform = spec.substr(0, eq), label = spec.substr(eq + 1);
  std::size_t first = traces.size(), chosen = traces.size();
  std::string names;
  for (std::size_t i = 0; i < traces.size(); ++i) {
    if (traces[i].platform != platform) continue;
    if (first == traces.size()) first = i;
    if (traces[i].label == label && chosen == traces.size()) chosen = i;
    names += (names.empty() ? "" : ", ") + traces[i].label;
  }
  if (chosen == traces.size())
    throw UsageError("--use-log: " + platform + " has no power log '" + label + "'" +
                     (names.empty() ? " (it has no power log)" : " (its logs: " + names + ")"));
  std::rotate(traces.begin() + static_cast<long>(first), traces.begin() + static_cast<long>(chosen),
              traces.begin() + static_cast<long>(chosen) + 1);
  return first;
}

RequirementVerdicts judge_requirements(const PlatformArgs& p, const std::vector<PlatformRow>& rows,
                                       const LoadedData& data) {
  std::vector<std::string> names;
  for (const PlatformRow& r : rows) names.push_back(r.platform);
  RequirementVerdicts v;
  if (p.loop) v.loop = headroom::evaluate_loop(*p.loop, data.headroom, names);
  if (p.sustained) v.sustained = sustain::evaluate_sustain(*p.sustained, data.sustain_runs, names);
  return v;
}

}  // namespace bs::cli
