// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/platform_args.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "store/battery_preset_store.h"
#include "store/decision_store.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

// The workspace's stored decision, when the command reads exactly one workspace and is not told to ignore it.
struct Stored {
  StoredDecision decision;
  std::optional<BatterySetup> battery;  // the pack the Platforms tab used (a preset, or the Battery tab's)
  std::vector<std::string> chosen_log_platforms;
};

std::optional<Stored> read_stored(const ParsedArgs& args) {
  if (args.has("--no-stored") || args.positional.size() != 1 || !looks_like_workspace(args.positional[0]))
    return std::nullopt;
  const Workspace ws(args.positional[0], Workspace::OpenMode::ReadOnly);
  Stored s;
  for (const auto& [platform, id] : chosen_logs(ws)) s.chosen_log_platforms.push_back(platform);
  std::optional<StoredDecision> d;
  try {
    d = stored_decision(ws);
  } catch (const WorkspaceError& e) {
    if (e.kind() != WorkspaceError::Kind::Corrupt) throw;
    throw WorkspaceError(e.kind(), std::string(e.what()) + " (--no-stored ignores it)");
  }
  if (!d) return s.chosen_log_platforms.empty() ? std::nullopt : std::optional<Stored>(std::move(s));
  s.decision = *d;
  s.battery = d->battery.empty() ? battery_tab_setup(ws) : find_battery_setup(&ws, d->battery);
  return s;
}

}  // namespace

const std::set<std::string>& platform_value_options() {
  static const std::set<std::string> names{"--budget",     "--min-fps",      "--min-runtime", "--battery",
                                           "--extra-load", "--supply-volts", "--mission",     "--require-loop"};
  return names;
}

PlatformArgs parse_platform_args(const ParsedArgs& args) {
  PlatformArgs p;
  const std::optional<Stored> stored = read_stored(args);
  const StoredDecision* d = stored ? &stored->decision : nullptr;
  std::vector<std::string> taken;  // what came from the workspace, in words
  const std::string preset_name = args.value("--battery").value_or("paper-4s-3850");
  const BatteryPack* preset = find_battery_preset(preset_name);
  if (!preset) {
    std::string names;
    for (const BatteryPack& b : battery_presets()) names += (names.empty() ? "" : ", ") + b.name;
    throw UsageError("unknown --battery '" + preset_name + "' (known: " + names + ")");
  }
  p.pack = *preset;
  if (!args.value("--battery") && stored && stored->battery) {
    p.pack = stored->battery->pack;
    p.options.usable_fraction = stored->battery->depth_of_discharge;
    taken.push_back("battery " + p.pack.name + (d->battery.empty() ? " (the Battery tab's pack)" : ""));
  }
  p.options.battery_nominal_v = p.pack.nominal_v();
  p.options.battery_capacity_ah = p.pack.capacity_ah;
  p.options.extra_load_w = args.number("--extra-load", d ? d->extra_load_w : 0);
  if (!(p.options.extra_load_w >= 0)) throw UsageError("--extra-load must be >= 0 W");
  if (d && !args.value("--extra-load") && d->extra_load_w > 0) taken.push_back("parallel load");
  std::optional<std::string> mission = args.value("--mission");
  if (!mission && d && !d->mission.empty()) {
    mission = d->mission;
    taken.push_back("mission " + d->mission);
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
  const bool given =
      args.value("--budget") || args.value("--min-fps") || args.value("--min-runtime") || args.value("--require-loop");
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
  if (!given && d && d->constrained()) {
    p.constraints = d->constraints();
    if (!d->loop.empty()) {
      try {
        p.loop = headroom::parse_loop_requirement(d->loop);
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("the workspace's stored control-loop requirement: ") + e.what() +
                         " (--no-stored ignores it)");
      }
    }
    taken.insert(taken.begin(), describe_constraints(*d));
  }
  if (d && !d->candidates.empty()) p.library = d->candidates;
  if (stored) p.chosen_log_platforms = stored->chosen_log_platforms;
  p.battery_choice = args.value("--battery").value_or(d ? d->battery : std::string());
  for (const std::string& t : taken) p.stored += (p.stored.empty() ? "" : "; ") + t;
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

}  // namespace bs::cli
