// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_print.h"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "analysis/stats/units.h"

namespace bs::cli {
namespace {

std::string fixed(double v, int decimals) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

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

}  // namespace

std::string interval_line(const SustainRun& r, std::size_t i) {
  std::string line = fixed(r.t_s[i], 1) + " s: ";
  line += i < r.rate.size() ? rate_text(r.rate[i], r.rate_unit) : std::string("no rate");
  // The clock furthest below its maximum, the sensor nearest its trip point (or the hottest).
  const ClockSeries* low = nullptr;
  double low_ratio = 0;
  for (const ClockSeries& c : r.clocks) {
    if (i >= c.hz.size() || !std::isfinite(c.hz[i])) continue;
    const double ratio = c.max_hz && *c.max_hz > 0 ? c.hz[i] / *c.max_hz : 1e9;
    if (!low || ratio < low_ratio) {
      low = &c;
      low_ratio = ratio;
    }
  }
  if (low) {
    line += ", " + low->name + " " + format_si(low->hz[i], "Hz");
    if (low->max_hz) line += " (" + fixed(100 * low_ratio, 0) + " % of max)";
  }
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
  if (hot) {
    line += ", " + hot->name + " " + celsius(hot->celsius[i]);
    if (hot->trip_c) line += " (trip " + celsius(*hot->trip_c) + ")";
  }
  if (i < r.power_w.size() && std::isfinite(r.power_w[i])) line += ", " + fixed(r.power_w[i], 2) + " W";
  return line;
}

void print_sustain(std::ostream& out, const SustainRun& r, const sustain::SustainAnalysis& a) {
  out << "Sustained run: " << r.label << " on " << r.platform << " (" << r.t_s.size() << " intervals of "
      << fixed(r.interval_s, 2) << " s)\n";
  if (a.has_rate) {
    out << "  peak rate:       " << rate_text(*a.peak_rate, r.rate_unit) << " (best interval)\n";
    out << "  sustained rate:  " << mean_sd(a.sustained, r.rate_unit) << ", last third; "
        << fixed(a.sustained_percent_of_peak.value_or(0), 1) << " % of peak\n";
    out << "  all intervals:   " << mean_sd(a.rate, r.rate_unit) << "\n";
    if (a.stability_percent)
      out << "  stability:       " << fixed(*a.stability_percent, 1)
          << " % (worst / best interval): " << (a.stable ? "stable" : "NOT stable") << " (threshold "
          << fixed(a.options.stable_percent, 1) << " %)\n";
    if (a.first_slow)
      out << "  first slow:      interval " << a.first_slow->index + 1 << ", " << fixed(a.first_slow->start_s, 1)
          << " .. " << fixed(a.first_slow->end_s, 1) << " s at " << rate_text(a.first_slow->rate, r.rate_unit) << "\n";
    out << "  steady state:    " << (a.steady_s ? "from " + fixed(*a.steady_s, 1) + " s" : std::string("not reached"))
        << " (every later interval within \xC2\xB1" << fixed(a.options.steady_percent, 0)
        << " % of the sustained rate)\n";
  } else {
    out << "  no rate: clocks and temperatures only\n";
  }
  const sustain::Throttle& t = a.throttle;
  if (!t.known) {
    out << "  throttling:      " << t.unknown_reason << "\n";
  } else if (!t.detected) {
    out << "  throttling:      none (no clock below " << fixed(100 * a.options.throttle_threshold, 0)
        << " % of its maximum, no zone at its trip point)\n";
  } else {
    out << "  throttling:      DETECTED from " << fixed(*t.onset_s, 1) << " s (interval " << *t.onset_index + 1
        << "), throttled for " << fixed(t.throttled_s, 1) << " s\n";
    for (const std::string& w : t.what) out << "    " << w << "\n";
    if (t.clock_at_onset)
      out << "    clock at onset: " << t.clock_at_onset->name << " " << format_si(t.clock_at_onset->value, "Hz")
          << "\n";
    if (t.temperature_at_onset)
      out << "    temperature at onset: " << t.temperature_at_onset->name << " "
          << celsius(t.temperature_at_onset->value) << "\n";
  }
  for (const std::string& n : t.notes) out << "  note: " << n << "\n";
  for (const std::string& n : r.not_exposed) out << "  not exposed: " << n << "\n";
  if (!r.power_w.empty()) out << "  power:           per interval from " << r.power_sensor << "\n";
}

}  // namespace bs::cli
