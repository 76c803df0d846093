// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Apex.AI performance_test's CSV log (--logfile, 2018 to the 2.x releases): the experiment's configuration as
// "Key: value" lines ("Performance Test Version: 80ff298", "Publishing rate: 1000", "Msg name: Array1k", ...), then
// "---EXPERIMENT-START---", a header row and one row about every second, separated by a comma and tabs:
//
//   T_experiment,	T_loop,	received,	sent,	lost,	relative_loss,	data_received,	latency_min (ms),
//   latency_max (ms),	latency_mean (ms),	latency_variance (ms),	pub_loop_res_min (ms), ...
//
// Latencies are in the unit the header names (milliseconds in every version seen: performance_test multiplies its
// seconds by 1000). Its "latency_variance (ms)" is the variance in s^2 times 1000 (the same x1000 applied to a
// squared quantity), read as such. The JSON log of the same tool keeps seconds (performance_test_json.h).
//
// Publisher-to-subscriber message latency (kind "message latency"), summary only; per-interval rows and running
// totals are told apart and mixed rows refused (performance_test_rows.h). Errors name the line; a last row cut
// without its line end is left out with a warning.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kPerformanceTestCsvFileFormat;  // id "performance-test-csv"

}  // namespace bs
