// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Apex.AI performance_test's JSON log (--logfile x.json, 2021 on): the configuration as keys ("perf_test_version",
// "com_mean_str", "rmw_implementation", "rate", "msg_name", "number_of_publishers", ...) and "analysis_results", an
// array of the per-second statistics rows:
//
//   { "experiment_start": 6230330930, "loop_start": 1000018073, "num_samples_received": 99, "num_samples_sent": 99,
//     "num_samples_lost": 0, "latency_min": 0.000034222, "latency_max": 0.000039518, "latency_n": 100.0,
//     "latency_mean": 0.00003521156, "latency_M2": 6.278e-11, "latency_variance": 6.278e-13, ... }
//
// Unlike the CSV log, latencies are in seconds (variance in s^2) and times in ns ("loop_start" is the interval's
// length, not a start). The row's own "latency_n" counts its latencies. Message latency, summary only; per-interval
// rows and running totals are told apart and mixed rows refused (performance_test_rows.h), naming the row's line.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kPerformanceTestJsonFileFormat;  // id "performance-test-json"

}  // namespace bs
