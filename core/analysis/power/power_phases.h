// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Load phases of a power/current trace found from level changes, and lining a benchmark run up with a trace.
// Method: a centred moving average (smooth_s) takes out sample noise, then binary segmentation splits the
// smoothed signal where the split explains the most variance, as long as both sides last min_phase_s and their
// levels differ by at least min_step; neighbouring segments closer than min_step are merged. The noise level
// behind the default min_step is estimated from the raw signal (median absolute first difference), so one
// spike does not make a phase and a flat noisy log stays one phase.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/power_trace.h"

namespace bs {

struct PhaseOptions {
  double smooth_s = 0.5;           // moving-average window (centred)
  double min_phase_s = 2.0;        // shortest phase reported
  std::optional<double> min_step;  // smallest level change that starts a phase; default 6 x noise SD, at least
                                   // 2 % of the signal's range
};

struct DetectedPhase {
  std::string name;  // "idle" for the lowest level (within min_step), "load" for the others
  double start_s = 0, end_s = 0;
  std::size_t first = 0, last = 0;  // sample indices [first, last]
  double mean = 0;                  // level of the raw values in the phase
};

// Phases tile the trace: each ends where the next starts. Throws std::invalid_argument on bad options or
// mismatched lengths. Fewer than two samples: no phases.
std::vector<DetectedPhase> detect_phases(std::span<const double> time_s, std::span<const double> values,
                                         const PhaseOptions& options = {});

// Noise SD estimate used for the default step: median |x[k+1] - x[k]| / (0.6745 * sqrt 2).
double noise_sd(std::span<const double> values);

// The phases as the model stores them (name and times).
std::vector<TracePhase> to_trace_phases(const std::vector<DetectedPhase>& phases);

struct TimeWindow {
  double from_s = 0, to_s = 0;  // seconds from the trace's first sample
};

// A benchmark run given by absolute ISO 8601 start and end times, in the trace's own seconds. Empty when the
// trace has no absolute start time, a time does not parse, or the run does not overlap the trace.
std::optional<TimeWindow> align_run(const PowerTrace& trace, std::string_view run_start_iso,
                                    std::string_view run_end_iso);

// When the clocks were not shared: the load phase whose duration is closest to the run's, if within
// `tolerance` (relative, 0.25 = 25 %).
std::optional<DetectedPhase> match_load_phase(const std::vector<DetectedPhase>& phases, double run_duration_s,
                                              double tolerance = 0.25);

}  // namespace bs
