// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/platform_battery.h"

#include <set>
#include <stdexcept>

#include "analysis/power/power_stats.h"

namespace bs {

Mission platform_mission(double computer_mean_w, double extra_load_w, std::string_view mission_spec) {
  if (!(computer_mean_w >= 0) || !(extra_load_w >= 0)) throw std::invalid_argument("loads must be >= 0 W");
  if (mission_spec.empty()) return constant_load(computer_mean_w, extra_load_w);
  Mission m = parse_mission(mission_spec);
  m.extra_load_w = computer_mean_w + extra_load_w;
  return m;
}

std::vector<PlatformBattery> platform_battery(std::span<const PowerTrace> traces, const BatteryPack& pack,
                                              const DischargeOptions& options, double extra_load_w,
                                              std::string_view mission_spec) {
  std::vector<PlatformBattery> out;
  std::set<std::string> done;
  for (const PowerTrace& trace : traces) {
    const std::string platform = trace.platform.empty() ? trace.label : trace.platform;
    if (done.count(platform)) continue;
    const PowerStats s = power_stats(trace);
    if (!s.power_w || !(s.power_w->summary.mean > 0)) continue;
    PlatformBattery b;
    b.platform = platform;
    b.trace_label = trace.label;
    b.computer_mean_w = s.power_w->summary.mean;
    b.mission = platform_mission(b.computer_mean_w, extra_load_w, mission_spec);
    b.result = simulate_discharge(pack, b.mission, options);
    if (options.model == BatteryModel::Lipo) {
      b.lipo = b.result;
    } else {
      DischargeOptions lipo = options;
      lipo.model = BatteryModel::Lipo;
      b.lipo = simulate_discharge(pack, b.mission, lipo);
    }
    done.insert(platform);
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace bs
