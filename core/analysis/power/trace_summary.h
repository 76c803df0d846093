// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a workspace keeps about a power trace besides its samples, computed once at import (or by the schema 6
// migration) and stored with it: sample count and duration, and per channel the statistics of the whole log and a
// min/max overview for drawing. A view can show a 100-million-sample log, its numbers and its shape from this alone
// while the samples load in the background (store/workspace.h: power_trace_summaries()).
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/power/decimate.h"
#include "analysis/power/power_stats.h"
#include "model/power_trace.h"

namespace bs {

struct ChannelSummary {
  std::string name;
  PowerQuantity quantity = PowerQuantity::Current;
  SignalStats stats;         // n (present samples), mean, sample SD, min, max, p5/p50/p95/p99 of the whole log
  double integral = 0;       // trapezoidal over time, missing samples bridged (analysis/power.h): J, C or V s
  DecimatedSeries overview;  // min/max per column over the whole log (analysis/decimate.h)
};

struct TraceSummary {
  std::size_t samples = 0;               // timestamps, present or not
  double duration_s = 0;                 // last timestamp minus the first
  std::vector<ChannelSummary> channels;  // in the trace's channel order
};

// Columns of the stored overview: enough for a full-screen plot of the whole log (two points per column).
inline constexpr std::size_t kOverviewColumns = 2048;

// Every number comes from the same functions the views use on the full samples (signal_stats,
// integrate_trapezoid, decimate_min_max), so a cached summary equals one computed from the loaded trace.
TraceSummary summarize_trace(const PowerTrace& trace, std::size_t overview_columns = kOverviewColumns);

}  // namespace bs
