// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// MLPerf Inference LoadGen's mlperf_log_summary.txt, every round from v0.5 (2019) to v4.x: "Key : Value" lines
// under the "MLPerf Results Summary", "Additional Stats" and "Test Parameters Used" banners. What is kept: the
// scenario (v0.5's "Single Stream" spelled as later rounds do, "SingleStream"), the mode, the validity line and its
// checks, the scenario's result line (SingleStream: 90th percentile latency; MultiStream: 99th percentile latency
// from v2.0, samples per query before; Offline: samples per second; Server: scheduled/completed samples per
// second), the latency statistics and percentiles (per sample; v0.5's per-query block is kept apart), queries per
// second and samples_per_query. Every value keeps its line number, so a test and a library entry can cite it.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "common/importer.h"

namespace bs {

struct LoadgenValue {
  std::string key;  // as in the file, trimmed: "90th percentile latency (ns)", "QPS w/o loadgen overhead"
  double value = 0;
  std::size_t line = 0;
  bool per_query = false;  // v0.5 MultiStream's "Per-query latency:" block (before "Per-sample latency:")
};

struct LoadgenSummary {
  std::string sut_name;
  std::string scenario;  // "SingleStream", "MultiStream", "Offline", "Server"
  std::string mode;      // "PerformanceOnly" ("Performance" in v0.5), "AccuracyOnly", ...
  bool valid = false;    // "Result is : VALID"
  std::string validity;  // "VALID", "INVALID"
  std::size_t validity_line = 0;
  std::vector<std::pair<std::string, bool>> checks;  // "Min duration satisfied" -> true, ...
  std::optional<LoadgenValue> result;                // the scenario's headline metric (the percentile line)
  // LoadGen's early-stopping estimates (v2.0 on: " * Early stopping 90th percentile estimate: 1637696"), keyed
  // "Early stopping 90th percentile estimate": from v2.0 the official SingleStream / MultiStream result.
  std::vector<LoadgenValue> early_stopping;
  std::vector<LoadgenValue> values;  // every numeric line, in file order
  std::optional<double> samples_per_query;

  // The first numeric line whose key is `key` (per-sample latencies come after v0.5's per-query block, so the
  // per-query percentiles are looked up with per_query = true).
  const LoadgenValue* find(std::string_view key, bool per_query = false) const;
};

// The round's official result, as MLPerf's submission checker takes it: the early-stopping estimate of the scenario's
// percentile where LoadGen printed one (SingleStream p90, MultiStream p99 per query: v2.0 on), else `result`.
const LoadgenValue* official_result(const LoadgenSummary& s);

// Throws ImportError: Syntax when the banner is missing or the text ends before "Result is" (a truncated log),
// MissingField for a missing scenario/mode/result line, InvalidValue for a malformed or negative number (naming the
// line), Unsupported for a scenario LoadGen does not have.
LoadgenSummary parse_loadgen_summary(std::string_view text, const std::string& file);

// Scenario spellings of all rounds to the canonical ones; empty when unknown.
std::string canonical_scenario(std::string_view text);

}  // namespace bs
