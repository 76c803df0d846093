// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Statistics of supply current/power logs, the paper's efficiency figure and its battery model.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/stats/stats.h"
#include "model/power_trace.h"

namespace bs {

// The channel that stands for the whole trace in quantity `q`: PowerTrace::total_channel when it has that quantity,
// else the first channel of it; nullptr when there is none (or its length differs from the time axis).
const PowerChannel* main_channel(const PowerTrace& trace, PowerQuantity q);

// Power in W per sample: the main power channel if the log has one, else current x voltage channel, else current
// x `supply_v` (or the trace's own supply voltage). Empty when none of these is available. Missing samples (NaN)
// stay NaN.
std::vector<double> power_series(const PowerTrace& trace, std::optional<double> supply_v = std::nullopt);
std::vector<double> current_series(const PowerTrace& trace);  // empty without a current channel

// Missing samples: NaN in a channel marks a sample the log does not have. Every statistic below skips them (never
// reads them as zero): n counts the present samples only.

// n, mean, sample SD, min, max of the present (non-NaN) values.
Summary summarize_samples(std::span<const double> values) noexcept;

// percentile() and median() are in analysis/stats.h.

// Trapezoidal integral of `values` over irregular timestamps `time_s` (J for W) over the whole trace: a thin call
// to TraceIndex::integral (analysis/trace_index.h). A missing sample is bridged: the trapezoid joins the present
// samples on either side of the gap (a straight line across it, as the plot draws it); before the first and after
// the last present sample nothing is counted.
double integrate_trapezoid(const std::vector<double>& time_s, const std::vector<double>& values);

struct TraceStats {
  std::size_t n = 0;
  double duration_s = 0;
  std::optional<Summary> current_a;
  std::optional<Summary> power_w;
  double power_p5 = 0, power_p50 = 0, power_p95 = 0, power_p99 = 0;
  double energy_j = 0;
};
// Over [from_s, to_s] (seconds from the start of the trace; unset = whole trace): a thin call to power_stats()
// (analysis/power_stats.h), kept for callers that want the short form. Duration and energy follow its definition
// (interpolated range ends).
TraceStats trace_stats(const PowerTrace& trace, std::optional<double> supply_v = std::nullopt,
                       std::optional<double> from_s = std::nullopt, std::optional<double> to_s = std::nullopt);

// The paper's GFLOPS/W: peak FLOPS / (supply V x maximum current), in FLOPS per W.
double paper_flops_per_watt(double peak_flops, double supply_v, double max_current_a);

// The paper's battery model: t = V_nominal x capacity / P_mean (constant power), in hours. `usable_fraction` is
// the depth of discharge a LiPo is allowed (1 in the paper).
double constant_power_runtime_h(double nominal_v, double capacity_ah, double mean_power_w,
                                double usable_fraction = 1.0);

}  // namespace bs
