// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The table a roboticist reads for a headroom measurement, one row per phase and thread: rate, p50 / p99 / p99.9 /
// p99.99 / max wake-up latency, deadline misses (count and %), the longest run of consecutive misses, n cycles,
// the load's achieved rate, mean power and the flags. `benchscope-cli headroom` prints it, the Headroom tab shows
// it and exports it (LaTeX / CSV), the report includes it: one definition of every cell.
#include <string>
#include <vector>

#include "headroom/headroom_measurement.h"
#include "util/table_export.h"

namespace bs::headroom {

// "37 us", "12.3 us" (below 100 us, one decimal when not whole), ">= 10000 us" for a percentile known only to lie
// beyond the histogram.
std::string latency_text(const HistogramPercentile& p);
std::string latency_text(std::int64_t ns);
// "0.40 % (8)", "0 % (0)", "≥ 0.05 % (≥ 10)" when counted from a histogram whose deadline cuts a bin.
std::string misses_text(const LatencySummary& s);

// Rows for every phase and thread of `m`; `source` (a run or file name) is written in the caption so every view says
// where its numbers come from.
ExportTable headroom_table(const HeadroomMeasurement& m, const std::string& source);

}  // namespace bs::headroom
