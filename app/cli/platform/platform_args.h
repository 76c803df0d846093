// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The battery and constraint options shared by `platforms` and `report`.
#include <set>
#include <string>

#include "analysis/platform/platform_comparison.h"
#include "analysis/power/battery.h"
#include "common/args.h"
#include "headroom/loop_requirement.h"

namespace bs::cli {

// --budget W, --min-fps FPS, --min-runtime MIN, --battery PRESET, --extra-load W, --supply-volts V,
// --mission SPEC (name:seconds:watts,... in parallel with each computer, as `battery --mission`),
// --require-loop SPEC (a control-loop requirement, headroom/loop_requirement.h)
const std::set<std::string>& platform_value_options();

struct PlatformArgs {
  const BatteryPack* pack = nullptr;
  ComparisonOptions options;
  Constraints constraints;
  std::optional<headroom::LoopRequirement> loop;
  bool constrained() const {
    return constraints.power_budget_w || constraints.min_fps || constraints.min_runtime_h || loop;
  }
};

// Throws UsageError for an unknown battery preset, naming the known ones, or a malformed mission.
PlatformArgs parse_platform_args(const ParsedArgs& args);

}  // namespace bs::cli
