// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a sustained run (#53) concludes, as pure functions of the record (docs/sustain.md gives each definition and
// its source):
//  - stability: the worst interval's rate / the best interval's rate, in % (3DMark's stress tests: frame-rate
//    stability, worst loop / best loop; a "stable" pass needs >= 97 %, the default threshold here);
//  - throttling: any clock below a fraction of its stated maximum (NVIDIA nvbench's --throttle-threshold, 0.8 by
//    default) or any thermal zone at or above its trip point, with the first interval it happened in (the onset),
//    what throttled and the clock and temperature then. Without a clock that states its maximum and a zone that
//    states a trip point the verdict is unknown, with the reason, never "no throttling";
//  - sustained rate: the mean of the last third of the intervals, against the peak (the best interval);
//  - time to steady state: the start of the first interval after which every interval's rate stays within ±3 %
//    (settable) of the sustained rate;
//  - the first slow interval: the first whose rate is below the stable threshold of the best, after the load first
//    reached that threshold (the intervals of its warm-up are not a slowdown).
#include <optional>
#include <string>
#include <vector>

#include "analysis/stats/stats.h"
#include "model/sustain_run.h"

namespace bs::sustain {

struct AnalysisOptions {
  double stable_percent = 97;       // 3DMark's stable pass: worst / best >= 97 %
  double throttle_threshold = 0.8;  // nvbench: a clock below 0.8 x its maximum is throttled
  double steady_percent = 3;        // steady state: every later interval within ±3 % of the sustained rate
};

// One reading at the onset of throttling: a clock against its maximum, or a temperature against its trip point.
struct OnsetReading {
  std::string name;
  double value = 0;             // Hz or °C
  std::optional<double> limit;  // the clock's maximum (Hz) or the zone's trip point (°C)
  bool throttled = false;       // below the threshold of its maximum, or at or above its trip point
};

struct Throttle {
  bool known = false;          // false: nothing to judge by; `unknown_reason` says why
  std::string unknown_reason;  // "unknown: no cpufreq under ...: no CPU clock; no thermal zone ... not exposed"
  bool detected = false;
  std::optional<std::size_t> onset_index;
  std::optional<double> onset_s;  // the onset interval's start, seconds from the run's start
  std::vector<std::string>
      what;  // "cpu0 at 1.8 GHz, 60 % of its 3 GHz maximum", "thermal_zone0 x at 97 °C >= trip 95 °C"
  std::optional<OnsetReading> clock_at_onset;        // the lowest clock relative to its maximum at the onset
  std::optional<OnsetReading> temperature_at_onset;  // the hottest sensor relative to its trip (or the hottest) then
  std::vector<std::pair<double, double>> spans;      // throttled spans [start, end] in seconds, for drawing bands
  double throttled_s = 0;                            // their total length
  std::vector<std::string> notes;                    // what could not be judged ("clocks only: no trip point stated")
};

struct SlowInterval {
  std::size_t index = 0;
  double start_s = 0, end_s = 0;
  double rate = 0;
};

struct SustainAnalysis {
  bool has_rate = false;                    // false for a record without a rate (an imported log)
  Summary rate;                             // every interval with a rate: mean ± SD, n, worst (min) and best (max)
  std::optional<double> stability_percent;  // worst / best x 100
  bool stable = false;                      // stability_percent >= options.stable_percent
  std::optional<double> peak_rate;          // the best interval
  Summary sustained;                        // the last third of the intervals (at least one)
  std::optional<double> sustained_percent_of_peak;
  std::optional<double> steady_s;  // empty: the rate never settled within ±steady_percent of the sustained rate
  std::optional<SlowInterval> first_slow;
  Throttle throttle;
  AnalysisOptions options;
};

// Start of interval i: the previous interval's end (0 for the first).
double interval_start(const SustainRun& run, std::size_t i);
Throttle find_throttle(const SustainRun& run, double throttle_threshold);
SustainAnalysis analyse(const SustainRun& run, const AnalysisOptions& options = {});

}  // namespace bs::sustain
