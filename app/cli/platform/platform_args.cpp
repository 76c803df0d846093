// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/platform_args.h"

#include <stdexcept>

namespace bs::cli {

const std::set<std::string>& platform_value_options() {
  static const std::set<std::string> names{"--budget",     "--min-fps",      "--min-runtime", "--battery",
                                           "--extra-load", "--supply-volts", "--mission",     "--require-loop"};
  return names;
}

PlatformArgs parse_platform_args(const ParsedArgs& args) {
  PlatformArgs p;
  const std::string preset_name = args.value("--battery").value_or("paper-4s-3850");
  p.pack = find_battery_preset(preset_name);
  if (!p.pack) {
    std::string names;
    for (const BatteryPack& b : battery_presets()) names += (names.empty() ? "" : ", ") + b.name;
    throw UsageError("unknown --battery '" + preset_name + "' (known: " + names + ")");
  }
  p.options.battery_nominal_v = p.pack->nominal_v();
  p.options.battery_capacity_ah = p.pack->capacity_ah;
  p.options.extra_load_w = args.number("--extra-load", 0);
  if (!(p.options.extra_load_w >= 0)) throw UsageError("--extra-load must be >= 0 W");
  if (const auto mission = args.value("--mission")) {
    try {
      parse_mission(*mission);  // name the option in the error, before any data is loaded
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--mission: ") + e.what());
    }
    p.options.mission = *mission;
  }
  if (args.value("--supply-volts")) p.options.supply_v = args.number("--supply-volts", 0);
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
  return p;
}

}  // namespace bs::cli
