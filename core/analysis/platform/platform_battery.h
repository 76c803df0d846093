// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Battery life per platform: each platform's computer draws the mean power of its log, in parallel with an extra
// load (servos) and, optionally, a mission profile's phases. One function for the GUI's Battery tab and
// `benchscope-cli battery --workspace`, so both show the same minutes.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/power/battery.h"
#include "model/power_trace.h"

namespace bs {

// The load a platform puts on the pack: with an empty `mission_spec`, the computer's mean power plus `extra_load_w`
// as a constant load; otherwise the mission's phases (parse_mission(); e.g. servo loads per phase) with the
// computer's mean power plus `extra_load_w` in parallel to every phase. Throws std::invalid_argument.
Mission platform_mission(double computer_mean_w, double extra_load_w, std::string_view mission_spec);

struct PlatformBattery {
  std::string platform;
  std::string trace_label;
  double computer_mean_w = 0;  // mean power of the platform's log
  Mission mission;
  DischargeResult result;  // with the options' model
  DischargeResult lipo;    // with the LiPo model, for the pack-voltage curve (equal to `result` when LiPo)
};

// One row per platform that has a log with a known power (the first such log of each platform), in log order.
// Throws std::invalid_argument for a bad pack, options or mission.
std::vector<PlatformBattery> platform_battery(std::span<const PowerTrace> traces, const BatteryPack& pack,
                                              const DischargeOptions& options, double extra_load_w,
                                              std::string_view mission_spec);

}  // namespace bs
