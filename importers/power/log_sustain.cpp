// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/log_sustain.h"

#include <algorithm>
#include <cmath>

namespace bs::meter {
namespace {

bool has_reading(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return !std::isnan(x); });
}

// The log's typical sampling interval: the median of its time steps (a log has no asked interval; one paused or
// late line must not set it).
double median_step(const std::vector<double>& t) {
  if (t.size() < 2) return 0;
  std::vector<double> steps(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) steps[i - 1] = t[i] - t[i - 1];
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  return steps[steps.size() / 2];
}

}  // namespace

std::optional<SustainRun> log_sustain_run(const PowerTrace& trace, LogSensors sensors) {
  SustainRun run;
  std::string silent;  // series left out for want of any reading
  auto left_out = [&](const std::string& name) { silent += (silent.empty() ? "" : ", ") + name; };
  for (std::size_t k = 0; k < sensors.clocks_mhz.size(); ++k) {
    SampleSeries::Series& s = sensors.clocks_mhz[k];
    if (!has_reading(s.values)) {
      left_out(s.name);
      continue;
    }
    ClockSeries c;
    c.name = std::move(s.name);
    if (k < sensors.max_mhz.size() && sensors.max_mhz[k]) c.max_hz = *sensors.max_mhz[k] * 1e6;
    c.hz.reserve(s.values.size());
    for (double mhz : s.values) c.hz.push_back(mhz * 1e6);
    run.clocks.push_back(std::move(c));
  }
  for (SampleSeries::Series& s : sensors.celsius) {
    if (!has_reading(s.values)) {
      left_out(s.name);
      continue;
    }
    run.temperatures.push_back({std::move(s.name), std::nullopt, std::move(s.values)});
  }
  if (run.clocks.empty() && run.temperatures.empty()) return std::nullopt;

  run.platform = trace.platform;
  run.label = trace.label;
  run.t_s = trace.time_s;
  run.interval_s = median_step(trace.time_s);
  for (const PowerChannel& c : trace.channels)
    if (c.name == trace.total_channel && c.quantity == PowerQuantity::Power) {
      run.power_w = c.values;
      run.power_sensor = trace.provenance.tool + " " + c.name;
    }
  run.not_exposed = std::move(sensors.not_exposed);
  if (run.clocks.empty()) run.not_exposed.push_back("no clock in the log: clock throttling cannot be seen");
  if (run.temperatures.empty()) run.not_exposed.push_back("no temperature in the log");
  run.provenance = trace.provenance;
  std::string note = "clocks and temperatures read from the log beside its power";
  for (const std::string& n : sensors.notes) note += "; " + n;
  if (!silent.empty()) note += "; no reading in the whole log, left out: " + silent;
  run.provenance.note = run.provenance.note.empty() ? note : run.provenance.note + "; " + note;
  return run;
}

}  // namespace bs::meter
