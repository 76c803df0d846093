// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Everything a workspace holds that changes the decision and the battery numbers, assembled by one rule for the
// GUI's Platforms tab, `benchscope-cli platforms`, `report` and `battery --workspace` (issue #50: the Battery tab's
// 5000 mAh edit gave 109.56 min in the GUI and 84.36 min in the CLI, which read the pack only beside a stored
// decision). The rule, the GUI's own:
//  - the pack: the decision's named preset (built-in or the workspace's) when it names one that exists; otherwise
//    the Battery tab's setup as saved ("battery-tab/current"), with its depth of discharge; otherwise the first
//    built-in pack (the paper's 4S 3850 mAh);
//  - parallel load and mission: the stored decision's when there is one; otherwise the Battery tab's setup's;
//  - constraints, control-loop and sustained requirements, library candidates: the stored decision's;
//  - the power log each platform's numbers come from: the chosen ones (store/decision_store.h).
// The command line's options then override single inputs (app/cli/platform/platform_args.cpp); the GUI shows them.
#include <optional>
#include <string>
#include <vector>

#include "analysis/platform/platform_comparison.h"
#include "headroom/loop_requirement.h"
#include "store/battery_preset_store.h"
#include "store/decision_store.h"
#include "sustain/sustain_requirement.h"

namespace bs {

struct DecisionInputs {
  std::optional<StoredDecision> stored;  // the Platforms tab's decision row; nullopt when never set
  BatterySetup battery;                  // the pack in effect, with its depth of discharge and model
  // "" follows the Battery tab; else the preset the decision names (also when it no longer exists: then `battery` is
  // the Battery tab's and `battery_missing` says so).
  std::string battery_choice;
  bool battery_from_tab = false;  // `battery` is the Battery tab's saved setup
  bool battery_missing = false;   // the named preset is gone; the Battery tab's pack stands in
  ComparisonOptions options;      // battery voltage, capacity, usable fraction, parallel load, mission
  Constraints constraints;
  std::optional<headroom::LoopRequirement> loop;
  std::optional<sustain::SustainRequirement> sustained;
  std::string candidates;
  std::vector<std::string> chosen_log_platforms;
};

// `ws` may be null (the defaults). Throws WorkspaceError(Corrupt) for a stored decision the schema refuses, as
// stored_decision() does.
DecisionInputs decision_inputs(const Workspace* ws);

}  // namespace bs
