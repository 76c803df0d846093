// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_live.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "sustain/sustain_json.h"

namespace bs::sustain {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A number, or NaN for null (an interval without that reading).
double reading(const nlohmann::json& j, const std::string& field) {
  if (j.is_null()) return kNaN;
  if (!j.is_number() || !std::isfinite(j.get<double>()))
    throw SustainJsonError("interval " + field + ": not a number or null");
  return j.get<double>();
}

// Adds this interval's value of every named series; a new name starts with NaN for the intervals before it.
template <class Series>
void add_readings(std::vector<Series>& all, std::vector<double> Series::*values, const nlohmann::json& named,
                  std::size_t before, const char* field) {
  if (!named.is_object()) throw SustainJsonError(std::string("interval ") + field + ": not an object");
  for (Series& s : all) (s.*values).push_back(kNaN);
  for (auto it = named.begin(); it != named.end(); ++it) {
    auto found = std::find_if(all.begin(), all.end(), [&](const Series& s) { return s.name == it.key(); });
    if (found == all.end()) {
      if (all.size() >= kMaxSeries) throw SustainJsonError(std::string("interval ") + field + ": too many series");
      Series s;
      s.name = it.key();
      (s.*values).assign(before + 1, kNaN);
      all.push_back(std::move(s));
      found = all.end() - 1;
    }
    ((*found).*values).back() = reading(it.value(), std::string(field) + "." + it.key());
  }
}

}  // namespace

void append_interval(SustainRun& so_far, const nlohmann::json& j) {
  if (!j.is_object()) throw SustainJsonError("interval: not an object");
  if (so_far.t_s.size() >= kMaxIntervals) throw SustainJsonError("interval: more intervals than a run may have");
  const double t = reading(j.value("t_s", nlohmann::json()), "t_s");
  if (!std::isfinite(t) || t < 0 || (!so_far.t_s.empty() && !(t > so_far.t_s.back())))
    throw SustainJsonError("interval t_s: missing, negative or not after the previous interval");
  SustainRun next = so_far;  // all or nothing
  const std::size_t before = next.t_s.size();
  next.t_s.push_back(t);
  if (const auto unit = j.find("rate_unit"); unit != j.end() && unit->is_string()) next.rate_unit = *unit;
  const double rate = reading(j.value("rate", nlohmann::json()), "rate");
  if (!next.rate_unit.empty() || std::isfinite(rate)) {
    next.rate.resize(before, kNaN);
    next.rate.push_back(rate);
  }
  const double watts = reading(j.value("power_w", nlohmann::json()), "power_w");
  if (!next.power_w.empty() || std::isfinite(watts)) {
    next.power_w.resize(before, kNaN);
    next.power_w.push_back(watts);
  }
  add_readings(next.clocks, &ClockSeries::hz, j.value("clocks_hz", nlohmann::json::object()), before, "clocks_hz");
  add_readings(next.temperatures, &TemperatureSeries::celsius, j.value("temperatures_c", nlohmann::json::object()),
               before, "temperatures_c");
  so_far = std::move(next);
}

}  // namespace bs::sustain
