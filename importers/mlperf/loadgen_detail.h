// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The few facts BenchScope takes from LoadGen's mlperf_log_detail.txt (":::MLLOG {json}" lines, v0.7 and later):
// the LoadGen version, the test date, the number of queries in the result and, for power runs, the power window
// (power_begin / power_end, in PTDaemon's "MM-DD-YYYY hh:mm:ss.fff" time). Only lines with one of these keys are
// parsed as JSON, so the multi-megabyte sample lists (loaded_qsl_set) cost a substring search each. v0.5's older
// text layout has none of the keys and yields an empty result.
#include <cstddef>
#include <optional>
#include <string>

#include "common/importer.h"

namespace bs {

struct LoadgenDetail {
  std::string loadgen_version;  // "3.0 @ f536725011"
  std::string test_datetime;    // "2023-02-24T06:21:48Z"
  std::optional<double> result_query_count;
  std::optional<double> qps_with_loadgen_overhead;  // result_qps_with_loadgen_overhead (v1.x power metric)
  std::string power_begin, power_end;               // as written: "02-24-2023 06:22:00.638"
  std::size_t power_begin_line = 0, power_end_line = 0, query_count_line = 0, qps_with_line = 0;
};

// Throws ImportError (Syntax naming the line) for an :::MLLOG line with one of the keys whose JSON is malformed.
LoadgenDetail parse_loadgen_detail(std::string_view text, const std::string& file, const ImportLimits& limits);

// "02-24-2023 06:22:00.638" (MM-DD-YYYY, PTDaemon's and LoadGen's power time) to seconds since 1970 (UTC as
// written); nullopt when malformed.
std::optional<double> ptd_time_to_epoch(std::string_view text);

}  // namespace bs
