// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_text.h"

#include <cmath>

#include "analysis/stats/units.h"
#include "util/text.h"

namespace bs::sustain {
namespace {

std::string celsius(double c) {
  return fixed(c, 1) +
         " \xC2\xB0"
         "C";
}

std::string rate_text(double v, const std::string& unit) {
  return std::isfinite(v) ? fixed(v, v >= 100 ? 1 : 2) + " " + unit : "no work counted";
}

std::string mean_sd(const Summary& s, const std::string& unit) {
  return fixed(s.mean, 2) + " \xC2\xB1 " + fixed(s.sd, 2) + " " + unit + " (n = " + std::to_string(s.n) + ")";
}

// The clock furthest below its maximum in interval i (a clock without a maximum counts as at it).
const ClockSeries* lowest_clock(const SustainRun& r, std::size_t i, double& ratio) {
  const ClockSeries* low = nullptr;
  for (const ClockSeries& c : r.clocks) {
    if (i >= c.hz.size() || !std::isfinite(c.hz[i])) continue;
    const double q = c.max_hz && *c.max_hz > 0 ? c.hz[i] / *c.max_hz : 1e9;
    if (!low || q < ratio) {
      low = &c;
      ratio = q;
    }
  }
  return low;
}

// The sensor nearest its trip point in interval i, else the hottest.
const TemperatureSeries* hottest(const SustainRun& r, std::size_t i) {
  const TemperatureSeries* hot = nullptr;
  double hot_margin = 0;
  for (const TemperatureSeries& t : r.temperatures) {
    if (i >= t.celsius.size() || !std::isfinite(t.celsius[i])) continue;
    const double margin = t.trip_c ? t.celsius[i] - *t.trip_c : t.celsius[i] - 1e6;
    if (!hot || margin > hot_margin) {
      hot = &t;
      hot_margin = margin;
    }
  }
  return hot;
}

void add_rate_rows(std::vector<SummaryRow>& rows, const SustainRun& r, const SustainAnalysis& a) {
  if (!a.has_rate) {
    rows.push_back({"rate", "none: clocks and temperatures only", false});
    return;
  }
  if (a.peak_rate) rows.push_back({"peak rate", rate_text(*a.peak_rate, r.rate_unit) + " (best interval)", false});
  rows.push_back({"sustained rate",
                  mean_sd(a.sustained, r.rate_unit) + ", last third; " +
                      fixed(a.sustained_percent_of_peak.value_or(0), 1) + " % of peak",
                  false});
  rows.push_back({"all intervals", mean_sd(a.rate, r.rate_unit), false});
  if (a.stability_percent)
    rows.push_back({"stability",
                    fixed(*a.stability_percent, 1) +
                        " % (worst / best interval): " + (a.stable ? "stable" : "NOT stable") + " (threshold " +
                        fixed(a.options.stable_percent, 1) + " %)",
                    !a.stable});
  if (a.first_slow)
    rows.push_back({"first slow",
                    "interval " + std::to_string(a.first_slow->index + 1) + ", " + fixed(a.first_slow->start_s, 1) +
                        " .. " + fixed(a.first_slow->end_s, 1) + " s at " + rate_text(a.first_slow->rate, r.rate_unit),
                    false});
  rows.push_back({"steady state",
                  (a.steady_s ? "from " + fixed(*a.steady_s, 1) + " s" : std::string("not reached")) +
                      " (every later interval within \xC2\xB1" + fixed(a.options.steady_percent, 0) +
                      " % of the sustained rate)",
                  false});
}

void add_throttle_rows(std::vector<SummaryRow>& rows, const SustainAnalysis& a) {
  const Throttle& t = a.throttle;
  if (!t.known) {
    rows.push_back({"throttling", t.unknown_reason, false});
  } else if (!t.detected) {
    rows.push_back({"throttling",
                    "none (no clock below " + fixed(100 * a.options.throttle_threshold, 0) +
                        " % of its maximum, no zone at its trip point)",
                    false});
  } else {
    rows.push_back({"throttling",
                    "DETECTED from " + fixed(t.onset_s.value_or(0), 1) + " s (interval " +
                        std::to_string(t.onset_index.value_or(0) + 1) + "), throttled for " + fixed(t.throttled_s, 1) +
                        " s",
                    true});
    for (const std::string& w : t.what) rows.push_back({"throttled", w, true});
    if (t.clock_at_onset)
      rows.push_back(
          {"clock at onset", t.clock_at_onset->name + " " + format_si(t.clock_at_onset->value, "Hz"), false});
    if (t.temperature_at_onset)
      rows.push_back(
          {"temperature at onset", t.temperature_at_onset->name + " " + celsius(t.temperature_at_onset->value), false});
  }
  for (const std::string& n : t.notes) rows.push_back({"note", n, false});
}

}  // namespace

std::string interval_line(const SustainRun& r, std::size_t i) {
  std::string line = fixed(r.t_s[i], 1) + " s: ";
  line += i < r.rate.size() ? rate_text(r.rate[i], r.rate_unit) : std::string("no rate");
  double ratio = 0;
  if (const ClockSeries* low = lowest_clock(r, i, ratio)) {
    line += ", " + low->name + " " + format_si(low->hz[i], "Hz");
    if (low->max_hz) line += " (" + fixed(100 * ratio, 0) + " % of max)";
  }
  if (const TemperatureSeries* hot = hottest(r, i)) {
    line += ", " + hot->name + " " + celsius(hot->celsius[i]);
    if (hot->trip_c) line += " (trip " + celsius(*hot->trip_c) + ")";
  }
  if (i < r.power_w.size() && std::isfinite(r.power_w[i])) line += ", " + fixed(r.power_w[i], 2) + " W";
  return line;
}

std::vector<SummaryRow> summary_rows(const SustainRun& r, const SustainAnalysis& a) {
  std::vector<SummaryRow> rows;
  add_rate_rows(rows, r, a);
  add_throttle_rows(rows, a);
  for (const std::string& n : r.not_exposed) rows.push_back({"not exposed", n, false});
  if (!r.power_w.empty()) rows.push_back({"power", "per interval from " + r.power_sensor, false});
  return rows;
}

}  // namespace bs::sustain
