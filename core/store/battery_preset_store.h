// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Battery presets edited by the user, saved in the workspace (settings "battery-preset/<name>", JSON), so a lab's
// own packs and mission profiles travel with its data. The GUI's Battery tab and `benchscope-cli battery
// --workspace WS --preset NAME` read the same list: built-in presets first, then the workspace's; a workspace
// preset with a built-in's name replaces it.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/power/battery.h"
#include "store/workspace.h"

namespace bs {

// A pack and how it is used: everything the Battery tab edits.
struct BatterySetup {
  BatteryPack pack;
  double depth_of_discharge = 1.0;  // usable fraction, (0, 1]
  double extra_load_w = 0;          // parallel load on top of the computer (servos)
  BatteryModel model = BatteryModel::ConstantPower;
  std::string mission;          // parse_mission() text; empty: the computer's mean power as a constant load
  bool from_workspace = false;  // set when read back from a workspace
};

// The built-in packs as setups with the paper's defaults (full depth of discharge, no extra load, constant power).
std::vector<BatterySetup> builtin_battery_setups();

std::string battery_setup_to_json(const BatterySetup& setup);
// Throws std::invalid_argument naming the field for malformed JSON or out-of-range values.
BatterySetup battery_setup_from_json(std::string_view json);

// Throws std::invalid_argument for an empty name or invalid values (the same checks as reading back).
void save_battery_setup(Workspace& ws, const BatterySetup& setup);
void remove_battery_setup(Workspace& ws, std::string_view name);
// The workspace's own presets, by name. A stored entry that no longer parses is skipped and named in `errors`.
std::vector<BatterySetup> workspace_battery_setups(const Workspace& ws, std::vector<std::string>* errors = nullptr);
// Built-ins then the workspace's (which replace built-ins of the same name); `ws` may be null.
std::vector<BatterySetup> all_battery_setups(const Workspace* ws, std::vector<std::string>* errors = nullptr);
std::optional<BatterySetup> find_battery_setup(const Workspace* ws, std::string_view name);
// The setup the Battery tab shows (saved as it is edited, setting "battery-tab/current"); nullopt when none was saved
// or it no longer parses.
std::optional<BatterySetup> battery_tab_setup(const Workspace& ws);

}  // namespace bs
