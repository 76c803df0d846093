// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/decision_inputs.h"

namespace bs {

DecisionInputs decision_inputs(const Workspace* ws) {
  DecisionInputs in;
  std::optional<BatterySetup> tab;
  if (ws) {
    in.stored = stored_decision(*ws);
    tab = battery_tab_setup(*ws);
    for (const auto& [platform, id] : chosen_logs(*ws)) in.chosen_log_platforms.push_back(platform);
  }
  const StoredDecision d = in.stored.value_or(StoredDecision{});
  in.battery_choice = d.battery;
  std::optional<BatterySetup> named;
  if (!d.battery.empty()) named = find_battery_setup(ws, d.battery);
  in.battery_missing = !d.battery.empty() && !named;
  if (named) {
    in.battery = *named;
  } else if (tab) {
    in.battery = *tab;
    in.battery_from_tab = true;
  } else {
    in.battery = builtin_battery_setups().front();
  }
  in.options.battery_nominal_v = in.battery.pack.nominal_v();
  in.options.battery_capacity_ah = in.battery.pack.capacity_ah;
  in.options.usable_fraction = in.battery.depth_of_discharge;
  // The parallel load and the mission are the decision's own fields; a workspace without a decision shows the
  // Battery tab's, as the Platforms tab does on a first start.
  in.options.extra_load_w = in.stored ? d.extra_load_w : tab ? tab->extra_load_w : 0;
  in.options.mission = in.stored ? d.mission : tab ? tab->mission : std::string();
  in.constraints = d.constraints();
  // stored_decision() refuses a requirement that does not parse: what it returned parses.
  if (!d.loop.empty()) in.loop = headroom::parse_loop_requirement(d.loop);
  if (!d.sustained.empty()) in.sustained = sustain::parse_sustain_requirement(d.sustained);
  in.candidates = d.candidates;
  return in;
}

}  // namespace bs
