// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/battery.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace bs {
namespace {

[[noreturn]] void invalid(const std::string& why) { throw std::invalid_argument("battery: " + why); }

// Where a mission is at time t: phase, its load and the time left in it (infinite after a non-repeating end).
class MissionClock {
 public:
  explicit MissionClock(const Mission& m) : m_(m) {
    for (const MissionPhase& p : m.phases) pass_s_ += p.duration_s;
  }
  double pass_s() const { return pass_s_; }
  bool ended(double t) const { return !m_.repeat && t >= pass_s_; }
  struct At {
    std::size_t phase = 0;
    double load_w = 0;
    double left_s = 0;
  };
  At at(double t) const {
    double in_pass = m_.repeat ? std::fmod(t, pass_s_) : std::min(t, pass_s_);
    for (std::size_t k = 0; k < m_.phases.size(); ++k) {
      const MissionPhase& p = m_.phases[k];
      if (in_pass < p.duration_s || k + 1 == m_.phases.size())
        return {k, p.load_w + m_.extra_load_w, std::max(p.duration_s - in_pass, 0.0)};
      in_pass -= p.duration_s;
    }
    return {};
  }

 private:
  const Mission& m_;
  double pass_s_ = 0;
};

void check(const BatteryPack& pack, const Mission& mission, const DischargeOptions& o) {
  if (pack.cells_series < 1 || !(pack.capacity_ah > 0) || !(pack.nominal_cell_v > 0) ||
      !(pack.internal_resistance_ohm >= 0) || !(pack.cutoff_cell_v >= 0))
    invalid("the pack needs >= 1 cell, capacity > 0, nominal voltage > 0, resistance >= 0");
  if (mission.phases.empty()) invalid("the mission has no phases");
  double pass = 0;
  for (const MissionPhase& p : mission.phases) {
    if (!(p.duration_s > 0) || !(p.load_w >= 0) || !std::isfinite(p.duration_s) || !std::isfinite(p.load_w))
      invalid("phase '" + p.name + "': duration must be > 0 s and load >= 0 W");
    pass += p.duration_s;
  }
  if (!(mission.extra_load_w >= 0)) invalid("the extra load must be >= 0 W");
  if (!(pass > 0)) invalid("the mission lasts 0 s");
  if (!(o.depth_of_discharge > 0 && o.depth_of_discharge <= 1)) invalid("the depth of discharge must be in (0, 1]");
  if (!(o.step_s >= 1e-3 && o.step_s <= 3600)) invalid("the time step must be in [1 ms, 1 h]");
  if (!(o.max_hours > 0 && o.max_hours <= 1e5)) invalid("the time limit must be in (0, 100000] h");
}

// Records about `points` evenly spaced samples, plus whatever the caller forces (first and last).
class SeriesRecorder {
 public:
  SeriesRecorder(double expected_s, std::size_t points)
      : every_s_(points > 0 ? std::max(expected_s, 1.0) / static_cast<double>(points) : 0) {}
  void offer(const DischargePoint& p, std::vector<DischargePoint>& out, bool force = false) {
    if (force || out.empty() || p.t_s >= next_s_) {
      out.push_back(p);
      next_s_ = p.t_s + every_s_;
    }
  }

 private:
  double every_s_;
  double next_s_ = 0;
};

DischargeResult constant_power(const BatteryPack& pack, const Mission& mission, const DischargeOptions& o) {
  DischargeResult r;
  char label[160];
  std::snprintf(label, sizeof label, "constant power at %.1f V nominal (the paper's model), %.0f %% depth of discharge",
                pack.nominal_v(), o.depth_of_discharge * 100);
  r.model_label = label;
  const MissionClock clock(mission);
  const double full_j = pack.nominal_wh() * 3600;
  const double budget_j = full_j * o.depth_of_discharge;
  double pass_j = 0;
  for (const MissionPhase& p : mission.phases) pass_j += (p.load_w + mission.extra_load_w) * p.duration_s;
  const double limit_s = o.max_hours * 3600;
  // Energy used by time t (whole passes at once, then the phases of the last pass).
  const auto used_j = [&](double t) {
    double e = 0;
    if (mission.repeat) {
      const double passes = std::floor(t / clock.pass_s());
      e = passes * pass_j;
      t -= passes * clock.pass_s();
    } else {
      t = std::min(t, clock.pass_s());
    }
    for (const MissionPhase& p : mission.phases) {
      const double d = std::min(t, p.duration_s);
      e += d * (p.load_w + mission.extra_load_w);
      t -= d;
      if (t <= 0) break;
    }
    return e;
  };
  // Runtime: whole passes, then phase by phase through the last one.
  double t = 0, left = budget_j;
  if (mission.repeat && pass_j > 0) {
    const double passes = std::floor(left / pass_j);
    t = passes * clock.pass_s();
    left -= passes * pass_j;
  }
  r.stop_reason = "depth of discharge reached";
  bool done = false;
  for (std::size_t pass = 0; !done && pass < 2; ++pass) {
    for (const MissionPhase& p : mission.phases) {
      const double w = p.load_w + mission.extra_load_w;
      if (left <= 0) {
        done = true;
        break;
      }
      if (w * p.duration_s < left) {
        left -= w * p.duration_s;
        t += p.duration_s;
        continue;
      }
      t += left / w;
      left = 0;
      done = true;
      break;
    }
    if (!mission.repeat) break;
  }
  if (!done) r.stop_reason = mission.repeat ? "time limit reached (no load)" : "mission ended";
  if (pass_j <= 0 && mission.repeat) t = limit_s;
  if (t > limit_s) {
    t = limit_s;
    r.stop_reason = "time limit reached";
  }
  r.runtime_s = t;
  r.energy_wh = used_j(t) / 3600;
  r.mean_load_w = t > 0 ? used_j(t) / t : mission.mean_load_w();
  r.min_terminal_v = pack.nominal_v();
  SeriesRecorder rec(t, o.series_points);
  const std::size_t points = std::max<std::size_t>(o.series_points, 2);
  for (std::size_t k = 0; k < points; ++k) {
    const double at = t * static_cast<double>(k) / static_cast<double>(points - 1);
    const auto a = clock.at(at);
    const double i = a.load_w / pack.nominal_v();
    r.peak_current_a = std::max(r.peak_current_a, i);
    rec.offer({at, 1 - used_j(at) / full_j, pack.nominal_v(), i, a.load_w, a.phase}, r.series, true);
  }
  for (const MissionPhase& p : mission.phases)
    r.peak_current_a = std::max(r.peak_current_a, (p.load_w + mission.extra_load_w) / pack.nominal_v());
  return r;
}

DischargeResult lipo(const BatteryPack& pack, const Mission& mission, const DischargeOptions& o) {
  DischargeResult r;
  const std::vector<OcvPoint>& curve = pack.ocv.empty() ? typical_lipo_ocv() : pack.ocv;
  char label[200];
  std::snprintf(
      label, sizeof label,
      "LiPo discharge curve, %dS, %.0f mOhm internal resistance, cut-off %.2f V/cell, %.0f %% depth of discharge",
      pack.cells_series, pack.internal_resistance_ohm * 1000, pack.cutoff_cell_v, o.depth_of_discharge * 100);
  r.model_label = label;
  const MissionClock clock(mission);
  const double full_c = pack.capacity_ah * 3600;
  const double floor_soc = 1 - o.depth_of_discharge;
  const double n = pack.cells_series, res = pack.internal_resistance_ohm, cutoff_v = pack.cutoff_cell_v * n;
  const double limit_s = o.max_hours * 3600;
  // The current that delivers `watts` at this state of charge, or empty when the pack cannot.
  const auto current = [&](double soc, double watts) -> std::optional<double> {
    const double voc = n * ocv_per_cell(curve, soc);
    if (watts <= 0) return 0.0;
    if (res == 0) return watts / voc;
    const double disc = voc * voc - 4 * res * watts;
    if (disc < 0) return std::nullopt;
    return (voc - std::sqrt(disc)) / (2 * res);
  };
  const double expected_s = pack.nominal_wh() * 3600 * o.depth_of_discharge / std::max(mission.mean_load_w(), 1e-9);
  SeriesRecorder rec(std::min(expected_s, limit_s), o.series_points);
  double t = 0, soc = 1, energy_j = 0;
  r.min_terminal_v = n * ocv_per_cell(curve, 1);
  r.stop_reason = "time limit reached";
  for (;;) {
    if (clock.ended(t)) {
      r.stop_reason = "mission ended";
      break;
    }
    if (t >= limit_s) break;
    const auto a = clock.at(t);
    const auto i0 = current(soc, a.load_w);
    if (!i0) {
      r.stop_reason = "voltage collapse: the pack cannot deliver the load through its internal resistance";
      break;
    }
    const double v_term = n * ocv_per_cell(curve, soc) - *i0 * res;
    if (v_term < cutoff_v) {
      r.stop_reason = "cut-off voltage reached";
      break;
    }
    r.min_terminal_v = std::min(r.min_terminal_v, v_term);
    r.peak_current_a = std::max(r.peak_current_a, *i0);
    rec.offer({t, soc, v_term, *i0, a.load_w, a.phase}, r.series);
    double dt = std::min({o.step_s, a.left_s > 0 ? a.left_s : o.step_s, limit_s - t});
    // Midpoint rule: the current at half a step is the step's average to second order.
    const auto im = current(std::max(soc - *i0 * dt / 2 / full_c, 0.0), a.load_w);
    const double i = im ? *im : *i0;
    if (i > 0 && soc - i * dt / full_c <= floor_soc) {
      dt = (soc - floor_soc) * full_c / i;
      t += dt;
      energy_j += a.load_w * dt;
      soc = floor_soc;
      r.stop_reason = "depth of discharge reached";
      break;
    }
    soc -= i * dt / full_c;
    t += dt;
    energy_j += a.load_w * dt;
  }
  const auto a = clock.at(t);
  const auto i_end = current(soc, a.load_w);
  const double v_end = n * ocv_per_cell(curve, soc) - i_end.value_or(0) * res;
  rec.offer({t, soc, v_end, i_end.value_or(0), a.load_w, a.phase}, r.series, true);
  r.runtime_s = t;
  r.energy_wh = energy_j / 3600;
  r.mean_load_w = t > 0 ? energy_j / t : mission.mean_load_w();
  return r;
}

}  // namespace

const std::vector<OcvPoint>& typical_lipo_ocv() {
  static const std::vector<OcvPoint> curve = {
      {0.00, 3.27}, {0.05, 3.61}, {0.10, 3.69}, {0.15, 3.71}, {0.20, 3.73}, {0.25, 3.75}, {0.30, 3.77},
      {0.35, 3.79}, {0.40, 3.80}, {0.45, 3.82}, {0.50, 3.84}, {0.55, 3.85}, {0.60, 3.87}, {0.65, 3.91},
      {0.70, 3.95}, {0.75, 3.98}, {0.80, 4.02}, {0.85, 4.08}, {0.90, 4.11}, {0.95, 4.15}, {1.00, 4.20}};
  return curve;
}

double ocv_per_cell(const std::vector<OcvPoint>& curve, double soc) {
  if (curve.empty()) return 0;
  soc = std::clamp(soc, 0.0, 1.0);
  const auto hi =
      std::lower_bound(curve.begin(), curve.end(), soc, [](const OcvPoint& p, double s) { return p.soc < s; });
  if (hi == curve.begin()) return hi->volts_per_cell;
  if (hi == curve.end()) return curve.back().volts_per_cell;
  const auto lo = hi - 1;
  const double span = hi->soc - lo->soc;
  return span > 0 ? lo->volts_per_cell + (hi->volts_per_cell - lo->volts_per_cell) * (soc - lo->soc) / span
                  : hi->volts_per_cell;
}

double mean_ocv_per_cell(const std::vector<OcvPoint>& curve, double lo, double hi) {
  if (!(hi > lo)) return ocv_per_cell(curve, lo);
  // Trapezoids between the curve's own points (exact for a piecewise-linear curve).
  std::vector<double> cuts{lo, hi};
  for (const OcvPoint& p : curve)
    if (p.soc > lo && p.soc < hi) cuts.push_back(p.soc);
  std::sort(cuts.begin(), cuts.end());
  double area = 0;
  for (std::size_t k = 1; k < cuts.size(); ++k)
    area += (cuts[k] - cuts[k - 1]) * (ocv_per_cell(curve, cuts[k]) + ocv_per_cell(curve, cuts[k - 1])) / 2;
  return area / (hi - lo);
}

const std::vector<BatteryPack>& battery_presets() {
  static const std::vector<BatteryPack> presets = {
      {"paper-4s-3850", "14.8 V 4S LiPo, 3850 mAh (the paper's robot battery)", 4, 3.85, 3.7, 0.040, 3.3, {}},
      {"4s-5000", "14.8 V 4S LiPo, 5000 mAh", 4, 5.0, 3.7, 0.030, 3.3, {}},
      {"3s-2200", "11.1 V 3S LiPo, 2200 mAh", 3, 2.2, 3.7, 0.045, 3.3, {}},
      {"6s-10000", "22.2 V 6S LiPo, 10000 mAh", 6, 10.0, 3.7, 0.030, 3.3, {}},
  };
  return presets;
}

const BatteryPack* find_battery_preset(std::string_view name) {
  for (const BatteryPack& p : battery_presets())
    if (p.name == name) return &p;
  return nullptr;
}

double Mission::mean_load_w() const {
  double e = 0, d = 0;
  for (const MissionPhase& p : phases) {
    e += p.load_w * p.duration_s;
    d += p.duration_s;
  }
  return (d > 0 ? e / d : 0) + extra_load_w;
}

Mission constant_load(double watts, double extra_load_w) {
  Mission m;
  m.phases.push_back({"load", 3600, watts});
  m.extra_load_w = extra_load_w;
  return m;
}

Mission parse_mission(std::string_view spec) {
  Mission m;
  std::size_t start = 0;
  while (start <= spec.size()) {
    const auto end = std::min(spec.find(',', start), spec.size());
    const std::string_view item = spec.substr(start, end - start);
    const auto c1 = item.find(':');
    const auto c2 = c1 == std::string_view::npos ? c1 : item.find(':', c1 + 1);
    if (c2 == std::string_view::npos) invalid("mission phase '" + std::string(item) + "' is not name:seconds:watts");
    MissionPhase p;
    p.name = std::string(item.substr(0, c1));
    const auto number = [&](std::string_view s, double& v) {
      const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
      if (r.ec != std::errc() || r.ptr != s.data() + s.size())
        invalid("mission phase '" + std::string(item) + "': '" + std::string(s) + "' is not a number");
    };
    number(item.substr(c1 + 1, c2 - c1 - 1), p.duration_s);
    number(item.substr(c2 + 1), p.load_w);
    if (p.name.empty()) invalid("mission phase '" + std::string(item) + "' has no name");
    if (!(p.duration_s > 0) || !(p.load_w >= 0)) invalid("mission phase '" + p.name + "': seconds > 0 and watts >= 0");
    m.phases.push_back(std::move(p));
    start = end + 1;
  }
  return m;
}

std::string_view to_string(BatteryModel model) { return model == BatteryModel::Lipo ? "lipo" : "constant-power"; }

DischargeResult simulate_discharge(const BatteryPack& pack, const Mission& mission, const DischargeOptions& options) {
  check(pack, mission, options);
  return options.model == BatteryModel::Lipo ? lipo(pack, mission, options) : constant_power(pack, mission, options);
}

}  // namespace bs
