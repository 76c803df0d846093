// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Battery life of a robot's computer (and its servos) on a LiPo pack.
//  - Constant-power model (the paper): t = V_nominal x capacity x depth-of-discharge / P_mean. The load draws
//    constant power, so its current rises as the voltage falls; the energy is taken at the nominal voltage.
//  - LiPo model: open-circuit voltage per cell as a function of state of charge (a typical LiPo curve, or the
//    pack's own), a series internal resistance, the same constant-power load: each time step solves
//    P = I (V_oc - I R) for the current, drains I dt from the charge, and stops at the depth of discharge,
//    at the cut-off terminal voltage, or when the pack cannot deliver the power at all (V_oc^2 < 4 R P).
// Loads come as a mission profile: phases with durations and loads (idle / walk / kick), repeated, plus a
// parallel load on top of every phase (servos: the paper's robot draws up to 225 W).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bs {

struct OcvPoint {
  double soc = 0;             // state of charge, 0..1, ascending in a curve
  double volts_per_cell = 0;  // open-circuit (rested) voltage
};
// A typical LiPo cell at rest, 3.27 V empty .. 4.20 V full (hobby-pack tables; real cells differ by ~0.05 V).
const std::vector<OcvPoint>& typical_lipo_ocv();
// Linear interpolation in `curve` (soc clamped to [0, 1]).
double ocv_per_cell(const std::vector<OcvPoint>& curve, double soc);
// Mean open-circuit voltage per cell over soc [lo, hi] (exact for the piecewise-linear curve).
double mean_ocv_per_cell(const std::vector<OcvPoint>& curve, double lo = 0, double hi = 1);

struct BatteryPack {
  std::string name;  // preset id, e.g. "paper-4s-3850"
  std::string description;
  int cells_series = 4;
  double capacity_ah = 3.85;
  double nominal_cell_v = 3.7;
  double internal_resistance_ohm = 0.04;  // whole pack, DC
  double cutoff_cell_v = 3.3;             // terminal voltage per cell under load at which the pack is empty
  std::vector<OcvPoint> ocv;              // empty: typical_lipo_ocv()
  double nominal_v() const { return cells_series * nominal_cell_v; }
  double nominal_wh() const { return nominal_v() * capacity_ah; }
};
// "paper-4s-3850" (the paper's 14.8 V 4S 3850 mAh) first. Internal resistances are typical values for such
// packs, not figures from the paper.
const std::vector<BatteryPack>& battery_presets();
const BatteryPack* find_battery_preset(std::string_view name);

struct MissionPhase {
  std::string name;
  double duration_s = 0;
  double load_w = 0;
};
struct Mission {
  std::vector<MissionPhase> phases;
  bool repeat = true;          // run the phases again and again until the battery is empty
  double extra_load_w = 0;     // in parallel with every phase (servos, sensors)
  double mean_load_w() const;  // over one pass, extra load included
};
Mission constant_load(double watts, double extra_load_w = 0);
// "idle:60:12,walk:30:140,kick:5:225" (name:seconds:watts, comma separated). Throws std::invalid_argument.
Mission parse_mission(std::string_view spec);

enum class BatteryModel { ConstantPower, Lipo };
std::string_view to_string(BatteryModel model);  // "constant-power", "lipo"

struct DischargeOptions {
  BatteryModel model = BatteryModel::ConstantPower;
  double depth_of_discharge = 1.0;  // usable fraction of the capacity, (0, 1]
  double step_s = 1.0;              // LiPo model time step (shortened at phase ends)
  double max_hours = 1000;          // stop there (a mission of zero load)
  std::size_t series_points = 500;  // about how many points of the state-of-charge series to keep
};

struct DischargePoint {
  double t_s = 0;
  double soc = 1;         // 0..1
  double terminal_v = 0;  // pack voltage under load (nominal in the constant-power model)
  double current_a = 0;
  double load_w = 0;
  std::size_t phase = 0;  // index into the mission's phases
};

struct DischargeResult {
  std::string model_label;  // e.g. "constant power at 14.8 V nominal (the paper's model)"
  double runtime_s = 0;
  std::string stop_reason;  // "depth of discharge reached", "cut-off voltage reached", ...
  double energy_wh = 0;     // delivered to the load
  double mean_load_w = 0;
  double peak_current_a = 0;
  double min_terminal_v = 0;
  std::vector<DischargePoint> series;  // state of charge over time, first and last point included
};

// Throws std::invalid_argument for an empty mission, negative loads or durations, or a bad pack/options.
DischargeResult simulate_discharge(const BatteryPack& pack, const Mission& mission,
                                   const DischargeOptions& options = {});

}  // namespace bs
