// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/stats/units.h"
#include "util/text.h"

namespace bs::sustain {
namespace {

bool finite(double v) { return std::isfinite(v); }

std::string celsius(double c) {
  char b[32];
  std::snprintf(b, sizeof b,
                "%.1f \xC2\xB0"
                "C",
                c);
  return b;
}

std::string percent(double p) { return format_number("%.0f %%", p); }

// The clock and temperature readings of interval i, with whether each is past its limit.
struct IntervalState {
  std::vector<OnsetReading> clocks, temperatures;
  bool throttled = false;
};

IntervalState state_at(const SustainRun& run, std::size_t i, double threshold) {
  IntervalState s;
  for (const ClockSeries& c : run.clocks) {
    if (i >= c.hz.size() || !finite(c.hz[i])) continue;
    OnsetReading r{c.name, c.hz[i], c.max_hz, false};
    if (c.max_hz && *c.max_hz > 0) r.throttled = c.hz[i] < threshold * *c.max_hz;
    s.throttled = s.throttled || r.throttled;
    s.clocks.push_back(r);
  }
  for (const TemperatureSeries& t : run.temperatures) {
    if (i >= t.celsius.size() || !finite(t.celsius[i])) continue;
    OnsetReading r{t.name, t.celsius[i], t.trip_c, false};
    if (t.trip_c) r.throttled = t.celsius[i] >= *t.trip_c;
    s.throttled = s.throttled || r.throttled;
    s.temperatures.push_back(r);
  }
  return s;
}

std::string describe_reading(const OnsetReading& r, bool clock) {
  if (clock) {
    std::string s = r.name + " at " + format_si(r.value, "Hz");
    if (r.limit && *r.limit > 0)
      s += ", " + percent(100 * r.value / *r.limit) + " of its " + format_si(*r.limit, "Hz") + " maximum";
    return s;
  }
  std::string s = r.name + " at " + celsius(r.value);
  if (r.limit) s += (r.throttled ? " >= trip " : ", trip ") + celsius(*r.limit);
  return s;
}

}  // namespace

double interval_start(const SustainRun& run, std::size_t i) { return i == 0 ? 0.0 : run.t_s[i - 1]; }

Throttle find_throttle(const SustainRun& run, double threshold) {
  Throttle t;
  // What can be judged: a clock with a stated maximum and a reading, a zone with a trip point and a reading.
  const auto read_once = [](const std::vector<double>& v) { return std::any_of(v.begin(), v.end(), finite); };
  std::size_t clocks = 0, zones = 0;
  for (const ClockSeries& c : run.clocks) clocks += c.max_hz && *c.max_hz > 0 && read_once(c.hz);
  for (const TemperatureSeries& z : run.temperatures) zones += z.trip_c && read_once(z.celsius);
  if (clocks + zones == 0) {
    std::string why = join(run.not_exposed, "; ");
    if (!run.clocks.empty() || !run.temperatures.empty())
      why += std::string(why.empty() ? "" : "; ") + "no clock with a stated maximum and no zone with a trip point read";
    t.unknown_reason = "unknown: " + (why.empty() ? std::string("no clock and no thermal zone") : why) +
                       " (not exposed: nothing to judge throttling by)";
    return t;
  }
  t.known = true;
  if (clocks == 0) t.notes.push_back("judged by temperatures only: no clock with a stated maximum was read");
  if (zones == 0) t.notes.push_back("judged by clocks only: no thermal zone with a trip point was read");
  bool in_span = false;
  double span_start = 0;
  for (std::size_t i = 0; i < run.t_s.size(); ++i) {
    const IntervalState s = state_at(run, i, threshold);
    if (s.throttled && !in_span) {
      in_span = true;
      span_start = interval_start(run, i);
    }
    if (!s.throttled && in_span) {
      t.spans.emplace_back(span_start, interval_start(run, i));
      in_span = false;
    }
    if (!s.throttled || t.detected) continue;
    t.detected = true;
    t.onset_index = i;
    t.onset_s = interval_start(run, i);
    for (const OnsetReading& r : s.clocks)
      if (r.throttled) t.what.push_back(describe_reading(r, true));
    for (const OnsetReading& r : s.temperatures)
      if (r.throttled) t.what.push_back(describe_reading(r, false));
    // The clock furthest below its maximum, the temperature nearest (or furthest past) its trip point.
    const auto ratio = [](const OnsetReading& r) { return r.limit && *r.limit > 0 ? r.value / *r.limit : 1e9; };
    if (!s.clocks.empty())
      t.clock_at_onset = *std::min_element(s.clocks.begin(), s.clocks.end(),
                                           [&](const auto& a, const auto& b) { return ratio(a) < ratio(b); });
    const auto margin = [](const OnsetReading& r) { return r.limit ? r.value - *r.limit : r.value - 1e9; };
    if (!s.temperatures.empty())
      t.temperature_at_onset = *std::max_element(s.temperatures.begin(), s.temperatures.end(),
                                                 [&](const auto& a, const auto& b) { return margin(a) < margin(b); });
  }
  if (in_span && !run.t_s.empty()) t.spans.emplace_back(span_start, run.t_s.back());
  for (const auto& [a, b] : t.spans) t.throttled_s += b - a;
  return t;
}

SustainAnalysis analyse(const SustainRun& run, const AnalysisOptions& options) {
  SustainAnalysis a;
  a.options = options;
  a.throttle = find_throttle(run, options.throttle_threshold);
  const std::size_t n = std::min(run.rate.size(), run.t_s.size());
  std::vector<double> rates;
  for (std::size_t i = 0; i < n; ++i)
    if (finite(run.rate[i]) && run.rate[i] >= 0) rates.push_back(run.rate[i]);
  if (rates.empty()) return a;
  a.has_rate = true;
  a.rate = summarize(rates);
  a.peak_rate = a.rate.max;
  if (a.rate.max > 0) {
    a.stability_percent = 100 * a.rate.min / a.rate.max;
    a.stable = *a.stability_percent >= options.stable_percent;
  }
  // The last third of the intervals (by count, at least one), their rates where present.
  const std::size_t last = std::max<std::size_t>(1, n / 3);
  std::vector<double> tail;
  for (std::size_t i = n - last; i < n; ++i)
    if (finite(run.rate[i]) && run.rate[i] >= 0) tail.push_back(run.rate[i]);
  if (!tail.empty()) {
    a.sustained = summarize(tail);
    if (a.rate.max > 0) a.sustained_percent_of_peak = 100 * a.sustained.mean / a.rate.max;
    // Steady state: walk back from the end while each interval stays within the band around the sustained rate.
    const double band = options.steady_percent / 100 * a.sustained.mean;
    std::optional<std::size_t> from;
    for (std::size_t k = n; k-- > 0;) {
      const double r = run.rate[k];
      if (!finite(r)) continue;  // an interval without work says nothing either way
      if (std::abs(r - a.sustained.mean) > band) break;
      from = k;
    }
    if (from) a.steady_s = interval_start(run, *from);
  }
  // The first slow interval comes after the load first reached the stable band: the intervals of its warm-up (a
  // pool of threads starting, a network being built, caches filling) are slow without anything slowing it down.
  const double slow_below = options.stable_percent / 100 * a.rate.max;
  bool reached = false;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = run.rate[i];
    if (!reached) {
      reached = finite(r) && r >= slow_below;
      continue;
    }
    if (finite(r) && r < slow_below) {
      a.first_slow = SlowInterval{i, interval_start(run, i), run.t_s[i], r};
      break;
    }
  }
  return a;
}

}  // namespace bs::sustain
