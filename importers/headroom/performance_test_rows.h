// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The statistics rows Apex.AI performance_test writes about once a second (CSV and JSON logs alike), and how they
// become one message-latency result.
//
// Each row has counts (samples received and sent) and latency statistics (min, max, mean, variance). The versions
// seen in the wild (2018-2024) reset their statistics every interval, so a row describes its interval alone; a
// log that keeps running totals instead has counts that grow row by row and a last row that describes the whole
// run. Which one a file is, is read from the counts against the publishing rate (sent per row ~ rate x T_loop for
// per-interval rows, ~ rate x the time so far for running totals), or, without a rate, from whether they grow
// steadily. A file whose rows change from one kind to the other is refused at the first row of the other kind:
// adding running totals to interval counts would count samples twice.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/import_error.h"
#include "headroom/headroom_measurement.h"

namespace bs::headroom_import {

struct PerfTestRow {
  ErrorLocation at;  // where the row is, for errors
  double t_experiment_s = 0;
  double t_loop_s = 0;
  double received = 0;
  double sent = 0;
  std::optional<double> latency_n;  // the statistics' own count (JSON); else `received` counts the latencies
  double min_s = 0, max_s = 0, mean_s = 0;
  double variance_s2 = 0;  // population variance (M2 / n), in s^2
};

struct CombinedLatency {
  std::uint64_t n = 0;
  double min_s = 0, max_s = 0, mean_s = 0, sd_s = 0;
  bool running_totals = false;
  std::size_t rows = 0;        // rows the result comes from
  std::string worst_interval;  // "max 0.33 ms in the interval ending at T = 16.0 s" (per-interval rows)
};

// Combines the rows: per-interval rows are pooled (n-weighted mean, pooled variance, min of minima, max of maxima);
// with running totals the last row is the run. `rate_hz` is the publishing rate when the file gives one. Throws
// ImportError (InvalidValue) naming the first row of the other kind when the rows are mixed, MissingField when no
// row has a latency.
CombinedLatency combine_rows(const std::vector<PerfTestRow>& rows, std::optional<double> rate_hz);

// The measurement of a performance_test log: kind message latency, one "thread" (the subscribers' latencies
// together), summary only (performance_test keeps no histogram), the configuration in the provenance settings.
headroom::HeadroomMeasurement perf_test_measurement(const CombinedLatency& c,
                                                    std::vector<std::pair<std::string, std::string>> settings,
                                                    const std::string& file);

}  // namespace bs::headroom_import
